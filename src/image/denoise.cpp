// denoise: checks its input, prepares the planes the passes read (image/denoise_layout.h) and runs the passes
// in the widest build this CPU has (image/denoise_builds.h); the x86-64 baseline's is built here.
#include "image/denoise.h"

#include "image/denoise_builds.h"
#include "image/denoise_kernel.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
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

// Whether a pixel (its RGBA at `c`) takes part: its colour and its variance are finite. std::isfinite, written
// so that the loops calling it vectorise (no branch): not a number and infinity both fail. The bitwise & of
// two bools is deliberate (clang's -Wbitwise-instead-of-logical would have &&).
inline bool takesPart(const float* c, float variance) {
    return bool(unsigned(std::abs(c[0] + c[1] + c[2]) <= FLT_MAX) & unsigned(std::abs(variance) <= FLT_MAX));
}

// The colour of n pixels, their variance, and their albedo over σ_a; loops over pointers that alias nothing,
// which the compiler vectorises.
void prepareColour(int n, const float* __restrict rgba, const float* __restrict variance,
                   const float* __restrict albedo, float invA, float* __restrict r, float* __restrict g,
                   float* __restrict b, float* __restrict v, float* __restrict ar, float* __restrict ag,
                   float* __restrict ab) {
    for (int x = 0; x < n; ++x) {
        const float* c = rgba + 4 * x;
        const bool finite = takesPart(c, variance[x]);
        r[x] = finite ? c[0] : 0.0f;
        g[x] = finite ? c[1] : 0.0f;
        b[x] = finite ? c[2] : 0.0f;
        // Variances below 1e-20 (a standard error of 1e-10) are none: nothing denormal enters the sums.
        v[x] = (finite & (variance[x] > 1e-20f)) ? variance[x] : 0.0f;
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

// 1/z of a row of depths; the background (depth 0) has 0.
void inverseDepthRow(int n, const float* __restrict z, float* __restrict out) {
    for (int x = 0; x < n; ++x) out[x] = z[x] > 0.0f ? 1.0f / z[x] : 0.0f;
}

// The one-sided difference of smaller magnitude; 0 when both are infinite (no neighbour either side).
float gradientOf(float before, float after) {
    const float g = std::abs(before) <= std::abs(after) ? before : after;
    return std::abs(g) <= FLT_MAX ? g : 0.0f;
}

// The guides' depth as 1/z, which is affine in the image's coordinates over any plane: a tap is compared with
// the plane through the pixel (its value plus the gradient times the tap's offset), so that a wall seen at a
// grazing angle is smoothed as much along its depth as across it. The gradient along an axis is the smaller of
// the two one-sided differences, so that a silhouette (a jump on one side only) does not count as slope; 0
// where the image has no neighbour. `iz`, `up`, `down`: rows of 1/z (inverseDepthRow); where the image has no
// row above, `up` is the row itself and `upMissing` infinite (its difference then loses), and alike below.
void prepareDepth(int w, const float* __restrict iz, const float* __restrict up, float upMissing,
                  const float* __restrict down, float downMissing, float sigmaDepth, float* __restrict depth,
                  float* __restrict gradX, float* __restrict gradY, float* __restrict slope) {
    const auto at = [&](int x, float left, float right) {
        const float horizontal = gradientOf(left, right);
        const float vertical = gradientOf(iz[x] - up[x] + upMissing, down[x] - iz[x] + downMissing);
        depth[x] = iz[x];
        gradX[x] = horizontal;
        gradY[x] = vertical;
        slope[x] = sigmaDepth * std::max(std::abs(horizontal), std::abs(vertical));
    };
    at(0, INFINITY, w > 1 ? iz[1] - iz[0] : INFINITY);
    for (int x = 1; x + 1 < w; ++x) at(x, iz[x] - iz[x - 1], iz[x + 1] - iz[x]);
    if (w > 1) at(w - 1, iz[w - 1] - iz[w - 2], INFINITY);
}

// One row's luminance (0 where the colour or its variance is not finite) and its weight (1, or 0 there).
void luminanceRow(int n, const float* __restrict rgba, const float* __restrict variance, float* __restrict lum,
                  float* __restrict weight) {
    for (int x = 0; x < n; ++x) {
        const float* c = rgba + 4 * x;
        const bool finite = takesPart(c, variance[x]);
        lum[x] = finite ? kLumR * c[0] + kLumG * c[1] + kLumB * c[2] : 0.0f;
        weight[x] = finite ? 1.0f : 0.0f;
    }
}

// Row y of the first pass's luminance guide: each pixel's luminance averaged with its 3x3 neighbours' (B-spline
// weights 1/4, 1/2, 1/4 each way, normalised over the finite pixels inside the image). Compared at the first
// pass, where the colour is the raw estimate, it tells an edge from noise about three times as surely.
// `scratch`: scratchFloats(w) floats (prepareRow's 1/z rows use it after).
constexpr size_t scratchFloats(int w) { return 4 * size_t(w + 2); }

void prepareLuminance(const ImageF& color, const std::vector<float>& variance, int y, float* __restrict scratch,
                      float* __restrict out) {
    const int w = color.width, h = color.height;
    // The rows' luminance and weight summed vertically (1/4, 1/2, 1/4), then across: one zero each side.
    float* __restrict sumL = scratch + 1;
    float* __restrict sumW = sumL + (w + 2);
    float* __restrict lum = sumW + (w + 2);
    float* __restrict weight = lum + (w + 2);
    sumL[-1] = sumL[w] = sumW[-1] = sumW[w] = 0.0f;
    for (int x = 0; x < w; ++x) sumL[x] = sumW[x] = 0.0f;
    for (int j = -1; j <= 1; ++j) {
        if (y + j < 0 || y + j >= h) continue;
        const size_t row = size_t(y + j) * size_t(w);
        luminanceRow(w, &color.rgba[4 * row], &variance[row], lum, weight);
        const float k = kB3[j + 1];
        for (int x = 0; x < w; ++x) {
            sumL[x] += k * lum[x];
            sumW[x] += k * weight[x];
        }
    }
    for (int x = 0; x < w; ++x) {
        const float l = 0.25f * sumL[x - 1] + 0.5f * sumL[x] + 0.25f * sumL[x + 1];
        const float wt = 0.25f * sumW[x - 1] + 0.5f * sumW[x] + 0.25f * sumW[x + 1];
        out[x] = wt > 0.0f ? l / wt : 0.0f;
    }
}

// Row y of the prepared image: the colour and the guides, padding included. `scratch`: scratchFloats(w) floats.
void prepareRow(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                const SurfacePasses& g, const DenoiseSettings& s, float* scratch, int y) {
    const int w = layout.width(), h = layout.height(), pad = layout.pad(), end = layout.stride() - pad;
    float* p[kImagePlanes];
    for (int k = 0; k < kImagePlanes; ++k) p[k] = layout.image(k, y);
    const auto fillOutside = [&](int x) {
        for (int k = kColour; k < kColour + kColourPlanes; ++k) p[k][x] = 0.0f;
        p[kNx][x] = p[kNy][x] = p[kNz][x] = p[kDepth][x] = p[kLuminance][x] = 0.0f;
        p[kGradX][x] = p[kGradY][x] = p[kSlope][x] = 0.0f;
        p[kAlbedoR][x] = p[kAlbedoG][x] = p[kAlbedoB][x] = INFINITY;
    };
    for (int x = -pad; x < 0; ++x) fillOutside(x);
    for (int x = w; x < end; ++x) fillOutside(x);

    const size_t row = size_t(y) * size_t(w);
    prepareColour(w, &color.rgba[4 * row], &variance[row], &g.albedo[3 * row], 1.0f / s.sigmaAlbedo, p[kColour],
                  p[kColour + 1], p[kColour + 2], p[kColour + 3], p[kAlbedoR], p[kAlbedoG], p[kAlbedoB]);
    prepareNormal(w, &g.normal[3 * row], p[kNx], p[kNy], p[kNz]);
    prepareLuminance(color, variance, y, scratch, p[kLuminance]);
    const float* z = &g.depth[row];
    float* const iz[3] = {scratch, scratch + w, scratch + 2 * size_t(w)};
    inverseDepthRow(w, z, iz[1]);
    if (y > 0) inverseDepthRow(w, z - w, iz[0]);
    if (y + 1 < h) inverseDepthRow(w, z + w, iz[2]);
    prepareDepth(w, iz[1], y > 0 ? iz[0] : iz[1], y > 0 ? 0.0f : INFINITY, y + 1 < h ? iz[2] : iz[1],
                 y + 1 < h ? 0.0f : INFINITY, s.sigmaDepth, p[kDepth], p[kGradX], p[kGradY], p[kSlope]);
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
        const std::unique_ptr<float[]> scratch(new float[scratchFloats(color.width)]);
        for (int y = task * kRowsPerTask; y < std::min(h, (task + 1) * kRowsPerTask); ++y)
            prepareRow(layout, color, variance, guides, s, scratch.get(), y);
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
