// denoise: checks its input, prepares the planes the passes read (image/denoise_layout.h) and runs the passes
// in the widest build this CPU has (image/denoise_builds.h); the x86-64 baseline's is built here.
#include "image/denoise.h"

#include "image/denoise_builds.h"
#include "image/denoise_kernel.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

namespace shadelab {

namespace denoise_detail {
namespace {

// Rows per task of the preparation: enough tasks to balance, the threads' rows close together.
constexpr int kRowsPerTask = 4;
// The fewest rows a strip has: each strip also filters, for its neighbours' sake, up to 2^iterations rows of
// each pass beyond its edges (filterStrip), which should stay few beside its own.
constexpr int kMinStripRows = 64;

// The colour c / (1 + L) (see denoise()) of n pixels, their variance, and their albedo over σ_a; loops over
// pointers that alias nothing, which the compiler vectorises.
void prepareColour(int n, const float* __restrict rgba, const float* __restrict variance,
                   const float* __restrict albedo, float invA, float* __restrict r, float* __restrict g,
                   float* __restrict b, float* __restrict v, float* __restrict ar, float* __restrict ag,
                   float* __restrict ab) {
    for (int x = 0; x < n; ++x) {
        const float* c = rgba + 4 * x;
        // std::isfinite, written so that it vectorises (no branch): not a number and infinity both fail. The
        // bitwise & of two bools is deliberate (clang's -Wbitwise-instead-of-logical would have &&).
        const bool finite =
            bool(unsigned(std::abs(c[0] + c[1] + c[2]) <= FLT_MAX) & unsigned(std::abs(variance[x]) <= FLT_MAX));
        const float l = std::max(0.0f, kLumR * c[0] + kLumG * c[1] + kLumB * c[2]), k = 1.0f / (1.0f + l);
        r[x] = finite ? c[0] * k : 0.0f;
        g[x] = finite ? c[1] * k : 0.0f;
        b[x] = finite ? c[2] * k : 0.0f;
        // Variances below 1e-20 (a standard error of 1e-10) are none: nothing denormal enters the sums.
        const float vk = variance[x] * (k * k) * (k * k);
        v[x] = (finite & (vk > 1e-20f)) ? vk : 0.0f;
        // A pixel whose colour is not finite lends nothing: its albedo guide is infinite, as the padding's.
        // (Added rather than chosen, once for three: GCC 12 vectorises the loop only so.)
        const float outside = finite ? 0.0f : INFINITY;
        ar[x] = albedo[3 * x] * invA + outside;
        ag[x] = albedo[3 * x + 1] * invA + outside;
        ab[x] = albedo[3 * x + 2] * invA + outside;
    }
}

void prepareNormal(int n, const float* __restrict normal, float* __restrict nx, float* __restrict ny,
                   float* __restrict nz) {
    for (int x = 0; x < n; ++x) {
        nx[x] = normal[3 * x];
        ny[x] = normal[3 * x + 1];
        nz[x] = normal[3 * x + 2];
    }
}

// The depth change per pixel step along one axis: the smaller of the two one-sided differences, so that a
// silhouette (a jump on one side only) does not count as slope; 0 where the image has no neighbour. A
// missing neighbour's difference is infinite (`up` is then the row itself, `upMissing` infinite).
float alongOf(float before, float after) { return std::min(before, after) <= FLT_MAX ? std::min(before, after) : 0.0f; }

void prepareDepth(int w, const float* __restrict z, const float* __restrict up, float upMissing,
                  const float* __restrict down, float downMissing, float sigmaDepth, float* __restrict depth,
                  float* __restrict slope) {
    const auto at = [&](int x, float left, float right) {
        const float vertical = alongOf(std::abs(up[x] - z[x]) + upMissing, std::abs(down[x] - z[x]) + downMissing);
        depth[x] = z[x];
        slope[x] = sigmaDepth * std::max(alongOf(left, right), vertical);
    };
    at(0, INFINITY, w > 1 ? std::abs(z[1] - z[0]) : INFINITY);
    for (int x = 1; x + 1 < w; ++x) at(x, std::abs(z[x - 1] - z[x]), std::abs(z[x + 1] - z[x]));
    if (w > 1) at(w - 1, std::abs(z[w - 2] - z[w - 1]), INFINITY);
}

// Row y of the prepared image: the colour and the guides, padding included.
void prepareRow(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                const SurfacePasses& g, const DenoiseSettings& s, int y) {
    const int w = layout.width(), h = layout.height(), pad = layout.pad(), end = layout.stride() - pad;
    float* p[kImagePlanes];
    for (int k = 0; k < kImagePlanes; ++k) p[k] = layout.image(k, y);
    const auto fillOutside = [&](int x) {
        for (int k = kColour; k < kColour + kColourPlanes; ++k) p[k][x] = 0.0f;
        p[kNx][x] = p[kNy][x] = p[kNz][x] = p[kDepth][x] = p[kSlope][x] = 0.0f;
        p[kAlbedoR][x] = p[kAlbedoG][x] = p[kAlbedoB][x] = INFINITY;
    };
    for (int x = -pad; x < 0; ++x) fillOutside(x);
    for (int x = w; x < end; ++x) fillOutside(x);

    const size_t row = size_t(y) * size_t(w);
    prepareColour(w, &color.rgba[4 * row], &variance[row], &g.albedo[3 * row], 1.0f / s.sigmaAlbedo, p[kColour],
                  p[kColour + 1], p[kColour + 2], p[kColour + 3], p[kAlbedoR], p[kAlbedoG], p[kAlbedoB]);
    prepareNormal(w, &g.normal[3 * row], p[kNx], p[kNy], p[kNz]);
    const float* z = &g.depth[row];
    prepareDepth(w, z, y > 0 ? z - w : z, y > 0 ? 0.0f : INFINITY, y + 1 < h ? z + w : z, y + 1 < h ? 0.0f : INFINITY,
                 s.sigmaDepth, p[kDepth], p[kSlope]);
}

void filterStripBaseline(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                         const DenoiseSettings& s, int strip, int y0, int y1, ImageF& out) {
    filterStrip<4>(layout, color, variance, s, strip, y0, y1, out);
}

}  // namespace

std::vector<DenoiseIsa> denoiseIsas() {
    std::vector<DenoiseIsa> isas{DenoiseIsa::Baseline};
#if defined(SHADELAB_DENOISE_X86_BUILDS)
    __builtin_cpu_init();
    const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) isas.push_back(DenoiseIsa::Avx2);
    if (avx2 && __builtin_cpu_supports("avx512f")) isas.push_back(DenoiseIsa::Avx512);
#endif
    return isas;
}

ImageF denoiseWith(DenoiseIsa isa, const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                   const DenoiseSettings& s, int threads) {
    StripFilter filter = filterStripBaseline;
#if defined(SHADELAB_DENOISE_X86_BUILDS)
    if (isa == DenoiseIsa::Avx2) filter = filterStripAvx2;
    if (isa == DenoiseIsa::Avx512) filter = filterStripAvx512;
#else
    (void)isa;
#endif
    const int h = color.height;
    const int strips = std::max(1, std::min(threads, h / kMinStripRows));
    const DenoiseLayout layout(color.width, h, s.iterations, strips);
    parallelFor((h + kRowsPerTask - 1) / kRowsPerTask, threads, [&](int task) {
        for (int y = task * kRowsPerTask; y < std::min(h, (task + 1) * kRowsPerTask); ++y)
            prepareRow(layout, color, variance, guides, s, y);
    });
    ImageF out(color.width, h);
    parallelFor(strips, threads, [&](int strip) {
        filter(layout, color, variance, s, strip, int(int64_t(h) * strip / strips),
               int(int64_t(h) * (strip + 1) / strips), out);
    });
    return out;
}

}  // namespace denoise_detail

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
    const int threads = s.threads > 0 ? s.threads : std::max(1, int(std::thread::hardware_concurrency()));
    static const denoise_detail::DenoiseIsa widest = denoise_detail::denoiseIsas().back();
    return denoise_detail::denoiseWith(widest, color, variance, guides, s, threads);
}

}  // namespace shadelab
