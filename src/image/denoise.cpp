// denoise: checks its input, prepares the planes the passes read (image/denoise_layout.h) and runs the passes
// in the widest build this CPU has (image/denoise_builds.h); the x86-64 baseline's is built here.
#include "image/denoise.h"

#include "image/denoise_builds.h"
#include "image/denoise_kernel.h"
#include "util/parallel_for.h"

#include <algorithm>
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

// Row y of the prepared image: the colour c / (1 + L) (see denoise()) and the guides, padding included.
inline void prepareRow(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
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
        p[kColour][x] = finite ? c[0] * k : 0.0f;
        p[kColour + 1][x] = finite ? c[1] * k : 0.0f;
        p[kColour + 2][x] = finite ? c[2] * k : 0.0f;
        // Variances below 1e-20 (a standard error of 1e-10) are none: nothing denormal enters the sums.
        const float v = variance[i] * (k * k) * (k * k);
        p[kColour + 3][x] = finite && v > 1e-20f ? v : 0.0f;
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
