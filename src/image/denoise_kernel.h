// The denoiser of image/denoise.h over a DenoiseLayout, its passes N lanes wide (denoise_lanes.h): the row
// functions of every build (denoise_builds.h). Internal linkage, and nothing else from outside but what
// inlines (no thread, no allocation): a build's file then holds no function that the linker could take for
// another build's, which the CPU may not run. Not for other files.
#pragma once

#include "image/denoise.h"
#include "image/denoise_lanes.h"
#include "image/denoise_layout.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadelab::denoise_detail {

constexpr float kLumR = 0.2126f, kLumG = 0.7152f, kLumB = 0.0722f;  // ITU-R BT.709, as trace/luminance.h
constexpr float kB3[3] = {0.25f, 0.5f, 0.25f};                      // the 3-tap B-spline kernel

namespace {

// One à-trous pass at `step` pixels over row y. `in[j + 1]` is the red plane of the pass's input at row
// y + j·step (null outside the image), `blur[j + 1]` the variance plane at row y + j (null outside); the
// planes of a row lie `stride` apart, in the input as in `out`.
template <int N>
void filterRow(const DenoiseLayout& layout, const float* const in[3], const float* const blur[3], float* out,
               const DenoiseSettings& s, int step, int y) {
    using V = Lanes<N>;
    using F = typename V::F;
    const int w = layout.width(), stride = layout.stride();
    const float *r = in[1], *g = r + stride, *b = g + stride, *v = b + stride;
    const float *nx = layout.image(kNx, y), *ny = nx + stride, *nz = ny + stride, *z = nz + stride, *ar = z + stride,
                *ag = ar + stride, *ab = ag + stride, *lumGuide = ab + stride, *gradX = lumGuide + stride,
                *gradY = gradX + stride, *slope = gradY + stride;
    // The first pass compares the luminance's 3x3 means (DenoiseLayout's kLuminance), whose noise is that of a
    // mean of nine pixels: Σ w² = (3/8)² of one pixel's variance.
    const bool prefiltered = step == 1;
    const float noiseScale = prefiltered ? 0.375f : 1.0f;

    // The rows of the variance's blur (SVGF: a steadier estimate of the noise to stop at), the 3x3 B-spline at
    // step 1 normalised over the pixels inside the image.
    const float* blurRow[3];
    float blurWeight[3], blurRowSum = 0.0f;
    int blurRows = 0;
    for (int j = 0; j < 3; ++j)
        if (blur[j]) {
            blurRow[blurRows] = blur[j];
            blurWeight[blurRows++] = kB3[j];
            blurRowSum += kB3[j];
        }
    // The taps other than the centre, as offsets from it in the colour and in the guides: rows outside the
    // image have none, columns outside it are the padding, which weighs 0.
    ptrdiff_t colourOffset[8], guideOffset[8];
    float tapWeight[8], tapInvDist[8], tapDx[8], tapDy[8];
    int taps = 0;
    for (int j = -1; j <= 1; ++j) {
        if (!in[j + 1]) continue;
        for (int i = -1; i <= 1; ++i) {
            if (i == 0 && j == 0) continue;
            colourOffset[taps] = (in[j + 1] - r) + ptrdiff_t(i * step);
            guideOffset[taps] = ptrdiff_t(j * step) * kImagePlanes * stride + ptrdiff_t(i * step);
            tapWeight[taps] = kB3[i + 1] * kB3[j + 1];
            tapDx[taps] = float(i * step);
            tapDy[taps] = float(j * step);
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
        F blurred = F{};
        for (int k = 0; k < blurRows; ++k) {
            const float* q = blurRow[k] + x;
            blurred += blurWeight[k] * (0.25f * V::load(q - 1) + 0.5f * V::load(q) + 0.25f * V::load(q + 1));
        }
        const F column = V::splat(float(x)) + lane;
        const F columnSum =
            1.0f - (column == 0.0f ? V::splat(0.25f) : F{}) - (column == float(w - 1) ? V::splat(0.25f) : F{});
        const F vp = V::load(v + x);
        const F noise = V::sqrt(V::max(V::min(blurred / (blurRowSum * columnSum), vp), F{}));
        const F invL = 1.0f / (s.sigmaLuminance * noiseScale * noise + 1e-6f);
        const F zp = V::load(z + x), gxp = V::load(gradX + x), gyp = V::load(gradY + x);
        const F invZ = 1.0f / (V::load(slope + x) * float(step) + 1e-3f * V::abs(zp) + 1e-6f);

        const F rp = V::load(r + x), gp = V::load(g + x), bp = V::load(b + x);
        const F lp = prefiltered ? V::load(lumGuide + x) : kLumR * rp + kLumG * gp + kLumB * bp;
        const F nxp = V::load(nx + x), nyp = V::load(ny + x), nzp = V::load(nz + x);
        const F arp = V::load(ar + x), agp = V::load(ag + x), abp = V::load(ab + x);
        // The centre tap: its kernel weight (1/2 · 1/2) times e^0.
        constexpr float k0 = kB3[1] * kB3[1];
        F sw = V::splat(k0), sr = k0 * rp, sg = k0 * gp, sb = k0 * bp, sv = (k0 * k0) * vp;
        for (int t = 0; t < taps; ++t) {
            const ptrdiff_t c = ptrdiff_t(x) + colourOffset[t], q = ptrdiff_t(x) + guideOffset[t];
            const F rq = V::load(r + c), gq = V::load(g + c), bq = V::load(b + c);
            const F lq = prefiltered ? V::load(lumGuide + q) : kLumR * rq + kLumG * gq + kLumB * bq;
            const F dn = 1.0f - (nxp * V::load(nx + q) + nyp * V::load(ny + q) + nzp * V::load(nz + q));
            // Summed as a tree: the sum is on the path from the loads to the weight, which bounds the loop.
            const F e = (V::abs(lp - lq) * invL + sn * V::max(dn, F{})) +
                        ((V::abs(zp + gxp * tapDx[t] + gyp * tapDy[t] - V::load(z + q)) * (invZ * tapInvDist[t]) +
                          V::abs(arp - V::load(ar + q))) +
                         (V::abs(agp - V::load(ag + q)) + V::abs(abp - V::load(ab + q))));
            const F wq = tapWeight[t] * V::expNeg(e);
            sw += wq;
            sr += wq * rq;
            sg += wq * gq;
            sb += wq * bq;
            sv += wq * wq * V::load(v + c);
        }
        // A pixel that takes no part keeps its value (the padding its zeros): its albedo guide is not finite.
        const F inv = 1.0f / sw;
        const auto keep = arp < INFINITY;
        V::store(out + x, keep ? sr * inv : rp);
        V::store(out + stride + x, keep ? sg * inv : gp);
        V::store(out + 2 * stride + x, keep ? sb * inv : bp);
        // The carried variance has the input's floor (1e-20): below it, products with the weights go denormal.
        const F carried = sv * inv * inv;
        V::store(out + 3 * stride + x, keep ? (carried > 1e-20f ? carried : F{}) : vp);
    }
}

// Row y of the result from the last pass's output row `c` (red plane; the others `stride` apart), alpha
// kept; a pixel whose colour or variance is not finite is its input.
inline void finishRow(const DenoiseLayout& layout, const float* c, const ImageF& color,
                      const std::vector<float>& variance, ImageF& out, int y) {
    const int stride = layout.stride();
    const size_t row = size_t(y) * size_t(layout.width());
    for (int x = 0; x < layout.width(); ++x) {
        const float* in = &color.rgba[4 * (row + size_t(x))];
        float* o = &out.rgba[4 * (row + size_t(x))];
        if (!(std::isfinite(in[0] + in[1] + in[2]) && std::isfinite(variance[row + size_t(x)]))) {
            for (int k = 0; k < 4; ++k) o[k] = in[k];
            continue;
        }
        o[0] = c[x];
        o[1] = c[stride + x];
        o[2] = c[2 * stride + x];
        o[3] = in[3];
    }
}

// Every pass over rows y0 .. y1 − 1 of the result, in strip `strip`'s rings: the passes run together down
// the strip, each a few rows behind the one before it (its taps' reach), so that a pass reads rows the one
// before wrote a moment ago. Pass k filters its rows within H_k = 2^(k+1) + ... + 2^(iterations−1) of
// the strip too (what the later passes read), as the neighbouring strip does: a row's values are the same in
// every strip that filters it, so the result does not depend on where the strips end.
template <int N>
void filterStrip(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                 const DenoiseSettings& s, int strip, int y0, int y1, ImageF& out) {
    const int h = layout.height(), passes = layout.iterations(), stride = layout.stride();
    const int pad = layout.pad(), tail = (layout.width() + N - 1) / N * N, end = stride - pad;
    int next[8], hi[8];
    for (int k = 0; k < passes; ++k) {
        const int halo = (1 << passes) - (2 << k);  // 2^(k+1) + ... + 2^(passes−1)
        next[k] = std::max(0, y0 - halo);
        hi[k] = std::min(h, y1 + halo);
    }
    // The rings' padding, which no pass writes: zero, as the image's.
    for (int k = 0; k < passes; ++k) {
        const int rows = k + 1 < passes ? DenoiseLayout::ringRows(k) : 1;
        for (int row = 0; row < rows; ++row) {
            float* red = layout.output(strip, k, row);
            for (int c = 0; c < kColourPlanes; ++c) {
                std::fill(red + c * stride - pad, red + c * stride, 0.0f);
                std::fill(red + c * stride + tail, red + c * stride + end, 0.0f);
            }
        }
    }
    // The red plane of pass k's input at row y: the prepared image for the first pass, else the ring of the
    // pass before; null outside the image.
    const auto input = [&](int k, int y) -> const float* {
        if (y < 0 || y >= h) return nullptr;
        return k == 0 ? layout.image(kColour, y) : layout.output(strip, k - 1, y);
    };
    const auto run = [&](int k) {
        const int y = next[k]++, step = 1 << k;
        const float* in[3] = {input(k, y - step), input(k, y), input(k, y + step)};
        const float* blur[3];
        for (int j = 0; j < 3; ++j) {
            const float* row = input(k, y + j - 1);
            blur[j] = row ? row + 3 * stride : nullptr;
        }
        float* dst = layout.output(strip, k, y);
        filterRow<N>(layout, in, blur, dst, s, step, y);
        if (k + 1 == passes) finishRow(layout, dst, color, variance, out, y);
    };
    // Pass k may filter its next row y once the pass before has filtered every row it reads, up to y + 2^k.
    // The latest pass that may goes first: then a pass runs at most 2^(k+1) + 1 rows ahead of the one that
    // reads it, which its ring holds (DenoiseLayout::ringRows).
    const auto ready = [&](int k) {
        return next[k] < hi[k] && (k == 0 || next[k - 1] >= std::min(h, next[k] + (1 << k) + 1));
    };
    for (;;) {
        int k = passes - 1;
        while (k >= 0 && !ready(k)) --k;
        if (k < 0) break;
        run(k);
    }
}

}  // namespace
}  // namespace shadelab::denoise_detail
