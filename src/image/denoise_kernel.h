// The denoiser of image/denoise.h, N lanes wide (denoise_lanes.h) over a DenoiseLayout: built once for the
// x86-64 baseline (denoise.cpp, N = 4) and once for AVX2 (denoise_avx2.cpp, N = 8), which give the same bits;
// denoise.cpp checks the input and picks one at run time. Every stage works on whole rows, handed out to the
// threads a few at a time, and a row's result depends on nothing but the rows it reads: the same for any
// thread count. Internal linkage apart from the two entry points; not for other files.
#pragma once

#include "image/denoise.h"
#include "image/denoise_lanes.h"
#include "image/denoise_layout.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace shadelab::denoise_detail {

constexpr float kLumR = 0.2126f, kLumG = 0.7152f, kLumB = 0.0722f;  // ITU-R BT.709, as trace/luminance.h
constexpr float kB3[3] = {0.25f, 0.5f, 0.25f};                      // the 3-tap B-spline kernel

// The whole filter, for input denoise() has checked (sizes agree, settings in range, at least one pixel) and
// threads >= 1. The AVX2 build exists on x86-64 only, and may run only where the CPU has AVX2 and FMA.
ImageF denoiseBaseline(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                       const DenoiseSettings& s, int threads);
#if defined(SHADELAB_DENOISE_AVX2)
ImageF denoiseAvx2(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                   const DenoiseSettings& s, int threads);
#endif

namespace {

// Rows per task: enough tasks to balance two to sixteen threads, and the threads' rows close together, so that
// the rows a tap reads above and below are still in the shared cache for the other thread.
constexpr int kRowsPerTask = 4;

// Row y of every plane: the colour c / (1 + L) (see denoise()), the guides, and the padding of both colour
// sets, which the passes never write.
inline void prepareRow(DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                       const SurfacePasses& g, const DenoiseSettings& s, int y) {
    const int w = layout.width(), h = layout.height(), pad = layout.pad(), end = layout.stride() - pad;
    float* p[kPlaneCount];
    for (int k = 0; k < kPlaneCount; ++k) p[k] = layout.row(k, y);
    const auto fillOutside = [&](int x) {
        for (int k = kColourA; k < kNx; ++k) p[k][x] = 0.0f;
        p[kNx][x] = p[kNy][x] = p[kNz][x] = p[kDepth][x] = p[kSlope][x] = 0.0f;
        p[kAlbedoR][x] = p[kAlbedoG][x] = p[kAlbedoB][x] = INFINITY;
    };
    for (int x = -pad; x < 0; ++x) fillOutside(x);
    for (int x = w; x < end; ++x) fillOutside(x);

    const size_t row = size_t(y) * size_t(w);
    const float invA = 1.0f / s.sigmaAlbedo;
    const float* z = &g.depth[row];
    // The depth change per pixel step along one axis: the smaller of the two one-sided differences, so that a
    // silhouette (a jump on one side only) does not count as slope; 0 where the image has no neighbour.
    const auto along = [](float centre, const float* before, const float* after) {
        float best = INFINITY;
        if (before) best = std::min(best, std::abs(*before - centre));
        if (after) best = std::min(best, std::abs(*after - centre));
        return std::isfinite(best) ? best : 0.0f;
    };
    for (int x = 0; x < w; ++x) {
        const size_t i = row + size_t(x);
        const float* c = &color.rgba[4 * i];
        const bool finite = std::isfinite(c[0] + c[1] + c[2]) && std::isfinite(variance[i]);
        const float l = std::max(0.0f, kLumR * c[0] + kLumG * c[1] + kLumB * c[2]), k = 1.0f / (1.0f + l);
        p[kColourA][x] = finite ? c[0] * k : 0.0f;
        p[kColourA + 1][x] = finite ? c[1] * k : 0.0f;
        p[kColourA + 2][x] = finite ? c[2] * k : 0.0f;
        // Variances below 1e-20 (a standard error of 1e-10) are none: nothing denormal enters the sums.
        const float v = variance[i] * (k * k) * (k * k);
        p[kColourA + 3][x] = finite && v > 1e-20f ? v : 0.0f;
        p[kNx][x] = g.normal[3 * i];
        p[kNy][x] = g.normal[3 * i + 1];
        p[kNz][x] = g.normal[3 * i + 2];
        p[kDepth][x] = z[x];
        // A pixel whose colour is not finite lends nothing: its albedo guide is that of the padding.
        p[kAlbedoR][x] = finite ? g.albedo[3 * i] * invA : INFINITY;
        p[kAlbedoG][x] = finite ? g.albedo[3 * i + 1] * invA : INFINITY;
        p[kAlbedoB][x] = finite ? g.albedo[3 * i + 2] * invA : INFINITY;
        const float slopeX = along(z[x], x > 0 ? &z[x - 1] : nullptr, x + 1 < w ? &z[x + 1] : nullptr);
        const float slopeY = along(z[x], y > 0 ? &z[x] - w : nullptr, y + 1 < h ? &z[x] + w : nullptr);
        p[kSlope][x] = s.sigmaDepth * std::max(slopeX, slopeY);
    }
}

// One à-trous pass at `step` pixels over row y, from the colour set at plane `src` into the one at `dst`.
template <int N>
void filterRow(DenoiseLayout& layout, int src, int dst, const DenoiseSettings& s, int step, int y) {
    using V = Lanes<N>;
    using F = typename V::F;
    const int w = layout.width(), h = layout.height(), stride = layout.stride();
    const float* in[4];
    float* out[4];
    for (int c = 0; c < 4; ++c) {
        in[c] = layout.row(src + c, y);
        out[c] = layout.row(dst + c, y);
    }
    const float *nx = layout.row(kNx, y), *ny = layout.row(kNy, y), *nz = layout.row(kNz, y);
    const float *z = layout.row(kDepth, y), *ar = layout.row(kAlbedoR, y), *ag = layout.row(kAlbedoG, y),
                *ab = layout.row(kAlbedoB, y);
    const float* slope = layout.row(kSlope, y);

    // The rows of the variance's blur (SVGF: a steadier estimate of the noise to stop at), the 3x3 B-spline at
    // step 1 normalised over the pixels inside the image.
    const float* blurRow[3];
    float blurWeight[3], blurRowSum = 0.0f;
    int blurRows = 0;
    for (int j = -1; j <= 1; ++j)
        if (y + j >= 0 && y + j < h) {
            blurRow[blurRows] = layout.row(src + 3, y + j);
            blurWeight[blurRows++] = kB3[j + 1];
            blurRowSum += kB3[j + 1];
        }
    // The taps other than the centre, as offsets from it: rows outside the image have none, columns outside
    // it are the padding, which weighs 0.
    ptrdiff_t tapOffset[8];
    float tapWeight[8], tapInvDist[8];
    int taps = 0;
    for (int j = -1; j <= 1; ++j) {
        const int qy = y + j * step;
        if (qy < 0 || qy >= h) continue;
        for (int i = -1; i <= 1; ++i) {
            if (i == 0 && j == 0) continue;
            tapOffset[taps] = ptrdiff_t(qy - y) * stride + ptrdiff_t(i * step);
            tapWeight[taps] = kB3[i + 1] * kB3[j + 1];
            tapInvDist[taps++] = 1.0f / std::sqrt(float(i * i + j * j));
        }
    }

    F lane;
    for (int l = 0; l < N; ++l) lane[l] = float(l);
    const float sn = s.sigmaNormal;
    for (int x = 0; x < w; x += N) {
        // The noise to stop at: the blurred variance, but never more than the pixel's own, so that a converged
        // pixel beside a noisy one keeps its value. A pixel without noise stops at any difference: 1e-6 of
        // luminance is far below one 8-bit step.
        F blur = F{};
        for (int r = 0; r < blurRows; ++r) {
            const float* v = blurRow[r] + x;
            blur += blurWeight[r] * (0.25f * V::load(v - 1) + 0.5f * V::load(v) + 0.25f * V::load(v + 1));
        }
        const F column = V::splat(float(x)) + lane;
        const F columnSum =
            1.0f - (column == 0.0f ? V::splat(0.25f) : F{}) - (column == float(w - 1) ? V::splat(0.25f) : F{});
        const F vp = V::load(in[3] + x);
        const F noise = V::sqrt(V::max(V::min(blur / (blurRowSum * columnSum), vp), F{}));
        const F invL = 1.0f / (s.sigmaLuminance * noise + 1e-6f);
        const F zp = V::load(z + x);
        const F invZ = 1.0f / (V::load(slope + x) * float(step) + 1e-3f * V::abs(zp) + 1e-6f);

        const F rp = V::load(in[0] + x), gp = V::load(in[1] + x), bp = V::load(in[2] + x);
        const F lp = kLumR * rp + kLumG * gp + kLumB * bp;
        const F nxp = V::load(nx + x), nyp = V::load(ny + x), nzp = V::load(nz + x);
        const F arp = V::load(ar + x), agp = V::load(ag + x), abp = V::load(ab + x);
        // The centre tap: its kernel weight (1/2 · 1/2) times e^0.
        constexpr float k0 = kB3[1] * kB3[1];
        F sw = V::splat(k0), sr = k0 * rp, sg = k0 * gp, sb = k0 * bp, sv = (k0 * k0) * vp;
        for (int t = 0; t < taps; ++t) {
            const ptrdiff_t q = ptrdiff_t(x) + tapOffset[t];
            const F rq = V::load(in[0] + q), gq = V::load(in[1] + q), bq = V::load(in[2] + q);
            const F lq = kLumR * rq + kLumG * gq + kLumB * bq;
            const F dn = 1.0f - (nxp * V::load(nx + q) + nyp * V::load(ny + q) + nzp * V::load(nz + q));
            const F e = V::abs(lp - lq) * invL + sn * V::max(dn, F{}) +
                        V::abs(zp - V::load(z + q)) * (invZ * tapInvDist[t]) +
                        (V::abs(arp - V::load(ar + q)) + V::abs(agp - V::load(ag + q)) + V::abs(abp - V::load(ab + q)));
            const F wq = tapWeight[t] * V::expNeg(e);
            sw += wq;
            sr += wq * rq;
            sg += wq * gq;
            sb += wq * bq;
            sv += wq * wq * V::load(in[3] + q);
        }
        // A pixel that takes no part keeps its value (the padding its zeros): its albedo guide is not finite.
        const F inv = 1.0f / sw;
        const auto keep = arp < INFINITY;
        V::store(out[0] + x, keep ? sr * inv : rp);
        V::store(out[1] + x, keep ? sg * inv : gp);
        V::store(out[2] + x, keep ? sb * inv : bp);
        V::store(out[3] + x, keep ? sv * inv * inv : vp);
    }
}

// Row y of the result from the colour set at plane `src`: c' / (1 − L') (denoise()), alpha kept; a pixel
// whose colour or variance is not finite is its input.
inline void finishRow(const DenoiseLayout& layout, int src, const ImageF& color, const std::vector<float>& variance,
                      ImageF& out, int y) {
    const float *r = layout.row(src, y), *g = layout.row(src + 1, y), *b = layout.row(src + 2, y);
    const size_t row = size_t(y) * size_t(layout.width());
    for (int x = 0; x < layout.width(); ++x) {
        const float* c = &color.rgba[4 * (row + size_t(x))];
        float* o = &out.rgba[4 * (row + size_t(x))];
        if (!(std::isfinite(c[0] + c[1] + c[2]) && std::isfinite(variance[row + size_t(x)]))) {
            for (int k = 0; k < 4; ++k) o[k] = c[k];
            continue;
        }
        const float k = 1.0f / std::max(1.0f - (kLumR * r[x] + kLumG * g[x] + kLumB * b[x]), 1e-6f);
        o[0] = r[x] * k;
        o[1] = g[x] * k;
        o[2] = b[x] * k;
        o[3] = c[3];
    }
}

template <int N>
ImageF denoiseLanes(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                    const DenoiseSettings& s, int threads) {
    const int h = color.height;
    DenoiseLayout layout(color.width, h, 1 << (s.iterations - 1));
    const auto eachRow = [&](auto&& body) {
        parallelFor((h + kRowsPerTask - 1) / kRowsPerTask, threads, [&](int task) {
            for (int y = task * kRowsPerTask; y < std::min(h, (task + 1) * kRowsPerTask); ++y) body(y);
        });
    };
    eachRow([&](int y) { prepareRow(layout, color, variance, guides, s, y); });
    int src = kColourA, dst = kColourB;
    for (int k = 0; k < s.iterations; ++k) {
        eachRow([&](int y) { filterRow<N>(layout, src, dst, s, 1 << k, y); });
        std::swap(src, dst);
    }
    ImageF out(color.width, h);
    eachRow([&](int y) { finishRow(layout, src, color, variance, out, y); });
    return out;
}

}  // namespace
}  // namespace shadelab::denoise_detail
