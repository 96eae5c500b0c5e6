// denoise: the passes run over planes of floats (one per channel), each row's 3x3 taps one tap at a time
// across the row (image/denoise_row.h), so that the inner loops are straight-line arithmetic the compiler
// vectorises; on x86-64 CPUs with AVX2 and FMA the row pass built for them runs (denoise_avx2.cpp).
#include "image/denoise.h"

#include "image/denoise_row.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>

namespace shadelab {
namespace {

using namespace denoise_detail;

// The row pass for this CPU.
void filterRow(const Planes& in, const Guides& g, const std::vector<float>& lum, const std::vector<float>& varBlur,
               const DenoiseSettings& s, int step, int y, Planes& out) {
#if defined(SHADELAB_DENOISE_AVX2)
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) return filterRowAvx2(in, g, lum, varBlur, s, step, y, out);
#endif
    filterRowIn(in, g, lum, varBlur, s, step, y, out);
}

Guides guidesOf(const SurfacePasses& s, const std::vector<uint8_t>& finite) {
    const size_t n = size_t(s.width) * size_t(s.height);
    Guides g;
    for (auto* p : {&g.nx, &g.ny, &g.nz, &g.z, &g.slope, &g.ar, &g.ag, &g.ab, &g.valid}) p->resize(n);
    for (size_t i = 0; i < n; ++i) {
        g.nx[i] = s.normal[3 * i];
        g.ny[i] = s.normal[3 * i + 1];
        g.nz[i] = s.normal[3 * i + 2];
        g.z[i] = s.depth[i];
        g.ar[i] = s.albedo[3 * i];
        g.ag[i] = s.albedo[3 * i + 1];
        g.ab[i] = s.albedo[3 * i + 2];
        g.valid[i] = finite[i] ? 1.0f : 0.0f;
    }
    // The depth change per pixel step here: the larger of the one-sided differences' smaller halves, so that
    // a silhouette (a jump on one side only) does not count as slope.
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const size_t i = size_t(y) * size_t(s.width) + size_t(x);
            auto along = [&](int dx, int dy) {
                float best = INFINITY;
                for (int sgn : {-1, 1}) {
                    const int qx = x + sgn * dx, qy = y + sgn * dy;
                    if (qx < 0 || qy < 0 || qx >= s.width || qy >= s.height) continue;
                    best = std::min(best, std::abs(g.z[size_t(qy) * size_t(s.width) + size_t(qx)] - g.z[i]));
                }
                return std::isfinite(best) ? best : 0.0f;
            };
            g.slope[i] = std::max(along(1, 0), along(0, 1));
        }
    return g;
}

// The variance blurred by the 3x3 B-spline at step 1 (SVGF: a steadier estimate of the noise to stop at).
std::vector<float> blurredVariance(const Planes& p) {
    std::vector<float> out(p.v.size());
    for (int y = 0; y < p.h; ++y)
        for (int x = 0; x < p.w; ++x) {
            float sum = 0.0f, wsum = 0.0f;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    const int qx = x + i, qy = y + j;
                    if (qx < 0 || qy < 0 || qx >= p.w || qy >= p.h) continue;
                    const float k = kB3[i + 1] * kB3[j + 1];
                    sum += k * p.v[size_t(qy) * size_t(p.w) + size_t(qx)];
                    wsum += k;
                }
            out[size_t(y) * size_t(p.w) + size_t(x)] = sum / wsum;
        }
    return out;
}

}  // namespace

ImageF denoise(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
               const DenoiseSettings& s) {
    const size_t n = size_t(color.width) * size_t(color.height);
    if (color.rgba.size() != 4 * n || variance.size() != n || guides.width != color.width ||
        guides.height != color.height || guides.albedo.size() != 3 * n || guides.normal.size() != 3 * n ||
        guides.depth.size() != n)
        throw std::invalid_argument("denoise: the colour, variance and passes differ in size");
    if (s.iterations < 1 || s.iterations > 8)
        throw std::invalid_argument("denoise: iterations must be 1 to 8, got " + std::to_string(s.iterations));
    if (!(s.sigmaLuminance > 0.0f) || !(s.sigmaNormal >= 0.0f) || !(s.sigmaDepth > 0.0f) || !(s.sigmaAlbedo > 0.0f))
        throw std::invalid_argument("denoise: the edge-stopping widths must be positive");
    if (n == 0) return color;

    Planes cur(color.width, color.height), next(color.width, color.height);
    std::vector<uint8_t> finite(n);
    // The passes filter c / (1 + L), L the pixel's luminance (Reinhard's curve on luminance, as Karis 2014
    // weights his samples): a value far above 1, which the display clips (a lamp, its reflection), weighs as
    // the display shows it, so that it neither spreads its energy into its neighbours nor takes theirs. The
    // variance follows to first order, var / (1 + L)⁴; the result is mapped back by c' / (1 − L').
    for (size_t i = 0; i < n; ++i) {
        const float* c = &color.rgba[4 * i];
        finite[i] = std::isfinite(c[0] + c[1] + c[2]) && std::isfinite(variance[i]) ? 1 : 0;
        const float l = std::max(0.0f, kLumR * c[0] + kLumG * c[1] + kLumB * c[2]), k = 1.0f / (1.0f + l);
        cur.r[i] = finite[i] ? c[0] * k : 0.0f;
        cur.g[i] = finite[i] ? c[1] * k : 0.0f;
        cur.b[i] = finite[i] ? c[2] * k : 0.0f;
        // Variances below 1e-20 (a standard error of 1e-10) are none: nothing denormal enters the sums.
        const float v = variance[i] * (k * k) * (k * k);
        cur.v[i] = finite[i] && v > 1e-20f ? v : 0.0f;
    }
    const Guides g = guidesOf(guides, finite);
    const int threads = s.threads > 0 ? s.threads : std::max(1, int(std::thread::hardware_concurrency()));
    std::vector<float> lum(n);
    for (int k = 0; k < s.iterations; ++k) {
        for (size_t i = 0; i < n; ++i) lum[i] = kLumR * cur.r[i] + kLumG * cur.g[i] + kLumB * cur.b[i];
        const std::vector<float> varBlur = blurredVariance(cur);
        // Rows in blocks of 8: enough tasks to balance, few enough that handing them out costs nothing.
        const int blocks = (color.height + 7) / 8;
        parallelFor(blocks, threads, [&](int block) {
            for (int y = 8 * block; y < std::min(color.height, 8 * block + 8); ++y)
                filterRow(cur, g, lum, varBlur, s, 1 << k, y, next);
        });
        std::swap(cur, next);
    }
    ImageF out = color;
    for (size_t i = 0; i < n; ++i) {
        if (!finite[i]) continue;
        const float l = kLumR * cur.r[i] + kLumG * cur.g[i] + kLumB * cur.b[i];
        const float k = 1.0f / std::max(1.0f - l, 1e-6f);
        out.rgba[4 * i] = cur.r[i] * k;
        out.rgba[4 * i + 1] = cur.g[i] * k;
        out.rgba[4 * i + 2] = cur.b[i] * k;
    }
    return out;
}

}  // namespace shadelab
