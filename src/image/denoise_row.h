// The denoiser's inner pass (image/denoise.h), included by denoise.cpp (x86-64 baseline) and denoise_avx2.cpp
// (built for AVX2 and FMA: eight lanes instead of four), which denoise.cpp picks between at run time. Its
// functions have internal linkage, so that each file keeps its own build of them. Not for other files.
#pragma once

#include "image/denoise.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace shadelab::denoise_detail {

constexpr float kLumR = 0.2126f, kLumG = 0.7152f, kLumB = 0.0722f;  // ITU-R BT.709, as trace/luminance.h
constexpr float kB3[3] = {0.25f, 0.5f, 0.25f};                      // the 3-tap B-spline kernel

struct Planes {
    int w = 0, h = 0;
    std::vector<float> r, g, b, v;  // colour and variance of luminance
    explicit Planes(int width = 0, int height = 0)
        : w(width),
          h(height),
          r(size_t(width) * height),
          g(size_t(width) * height),
          b(size_t(width) * height),
          v(size_t(width) * height) {}
};

// What every pass reads of the guides: per pixel, its normal, depth, albedo and local depth slope, and
// whether its colour takes part (1) or not (0: not finite).
struct Guides {
    std::vector<float> nx, ny, nz, z, slope, ar, ag, ab, valid;
};

// filterRowIn built for AVX2 and FMA (denoise_avx2.cpp); only called where the CPU has both.
void filterRowAvx2(const Planes& in, const Guides& g, const std::vector<float>& lum, const std::vector<float>& varBlur,
                   const DenoiseSettings& s, int step, int y, Planes& out);

// The functions below have internal linkage: each including file keeps its own build of them.
namespace {

[[gnu::always_inline]] inline float absf(float v) { return std::max(v, -v); }

// e^-x for x >= 0, within 2e-4 relative: 2^t with t = −x·log2 e split as i + f, i = trunc(t), f in (−1, 0],
// 2^f by its Taylor series in f·ln 2 to the fifth power, scaled by 2^i through the exponent bits. Beyond
// x = 20 (a weight of 2e-9) it is 0: smaller weights would only make denormal products (w², w·var), which
// cost a hundred cycles each on x86.
[[gnu::always_inline]] inline float expNeg(float x) {
    const float c = x < 20.0f ? x : 20.0f;
    const float t = -c * 1.44269504f;
    const int i = int(t);
    const float y = (t - float(i)) * 0.693147181f;
    const float p = 1.0f + y * (1.0f + y * (0.5f + y * (1.0f / 6 + y * (1.0f / 24 + y * (1.0f / 120)))));
    // A multiply by 0 or 1 rather than a select: GCC 12 vectorises this loop for AVX2 only without the select.
    return p * __builtin_bit_cast(float, int32_t((i + 127) << 23)) * float(x < 20.0f);
}

// Pixels of a row filtered together: their sums live in local arrays, which the compiler knows no plane
// aliases, so that each tap's loop over them vectorises without run-time overlap checks.
constexpr int kChunk = 256;

// One à-trous pass at `step` pixels over row y.
inline void filterRowIn(const Planes& in, const Guides& g, const std::vector<float>& lum,
                        const std::vector<float>& varBlur, const DenoiseSettings& s, int step, int y, Planes& out) {
    const int w = in.w;
    const size_t row = size_t(y) * size_t(w);
    const float invA = 1.0f / s.sigmaAlbedo, sn = s.sigmaNormal;
    for (int c0 = 0; c0 < w; c0 += kChunk) {
        const int c1 = std::min(w, c0 + kChunk);
        float invL[kChunk], invZ[kChunk], sw[kChunk], sr[kChunk], sg[kChunk], sb[kChunk], sv[kChunk];
        for (int x = c0; x < c1; ++x) {
            const size_t p = row + size_t(x);
            const int t = x - c0;
            // The noise to stop at: the blurred variance (a steadier estimate, SVGF), but never more than the
            // pixel's own, so that a converged pixel beside a noisy one keeps its value. A pixel without noise
            // stops at any difference: 1e-6 of luminance is far below one 8-bit step.
            invL[t] = 1.0f / (s.sigmaLuminance * std::sqrt(std::max(std::min(varBlur[p], in.v[p]), 0.0f)) + 1e-6f);
            invZ[t] = 1.0f / (s.sigmaDepth * g.slope[p] * float(step) + 1e-3f * std::abs(g.z[p]) + 1e-6f);
            // The centre tap: its kernel weight (1/2 · 1/2) times e^0.
            const float k = kB3[1] * kB3[1] * g.valid[p];
            sw[t] = k;
            sr[t] = k * in.r[p];
            sg[t] = k * in.g[p];
            sb[t] = k * in.b[p];
            sv[t] = k * k * in.v[p];
        }
        for (int j = -1; j <= 1; ++j) {
            const int qy = y + j * step;
            if (qy < 0 || qy >= in.h) continue;
            const size_t qrow = size_t(qy) * size_t(w);
            for (int i = -1; i <= 1; ++i) {
                if (i == 0 && j == 0) continue;
                const int dx = i * step;
                const int x0 = std::max(c0, -dx), x1 = std::min(c1, w - dx);
                const float k = kB3[i + 1] * kB3[j + 1];
                const float invDist = 1.0f / std::sqrt(float(i * i + j * j));
                for (int x = x0; x < x1; ++x) {
                    const size_t p = row + size_t(x), q = qrow + size_t(x + dx);
                    const int t = x - c0;
                    const float dn = 1.0f - (g.nx[p] * g.nx[q] + g.ny[p] * g.ny[q] + g.nz[p] * g.nz[q]);
                    const float e =
                        absf(lum[p] - lum[q]) * invL[t] + sn * (dn > 0.0f ? dn : 0.0f) +
                        absf(g.z[p] - g.z[q]) * invZ[t] * invDist +
                        (absf(g.ar[p] - g.ar[q]) + absf(g.ag[p] - g.ag[q]) + absf(g.ab[p] - g.ab[q])) * invA;
                    const float wq = k * g.valid[q] * expNeg(e);
                    sw[t] += wq;
                    sr[t] += wq * in.r[q];
                    sg[t] += wq * in.g[q];
                    sb[t] += wq * in.b[q];
                    sv[t] += wq * wq * in.v[q];
                }
            }
        }
        for (int x = c0; x < c1; ++x) {
            const size_t p = row + size_t(x);
            const int t = x - c0;
            if (!(g.valid[p] > 0.0f)) {
                out.r[p] = in.r[p], out.g[p] = in.g[p], out.b[p] = in.b[p], out.v[p] = in.v[p];
                continue;
            }
            const float inv = 1.0f / sw[t];
            out.r[p] = sr[t] * inv;
            out.g[p] = sg[t] * inv;
            out.b[p] = sb[t] * inv;
            out.v[p] = sv[t] * inv * inv;
        }
    }
}

}  // namespace
}  // namespace shadelab::denoise_detail
