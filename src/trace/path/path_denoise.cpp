#include "trace/path/path_denoise.h"

#include "trace/luminance.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadelab::trace {
namespace {

// Rows per task: the variance is a few milliseconds' work at 720p, a part of a preview's budget.
constexpr int kRowsPerTask = 8;

template <typename F>
void eachRow(const PathRender& render, F body) {
    const int h = render.height();
    parallelFor((h + kRowsPerTask - 1) / kRowsPerTask, render.settings().threads, [&](int task) {
        for (int y = task * kRowsPerTask; y < std::min(h, (task + 1) * kRowsPerTask); ++y) body(y);
    });
}

// The standard deviation of the luminances `lum` (w x h) around (x, y), itself included (3x3, inside the
// image).
float neighbourSpread(const std::vector<float>& lum, int w, int h, int x, int y) {
    double sum = 0.0, squares = 0.0;
    int n = 0;
    for (int j = std::max(0, y - 1); j <= std::min(h - 1, y + 1); ++j)
        for (int i = std::max(0, x - 1); i <= std::min(w - 1, x + 1); ++i, ++n) {
            const double l = lum[size_t(j) * size_t(w) + size_t(i)];
            sum += l;
            squares += l * l;
        }
    const double mean = sum / n;
    return float(std::sqrt(std::max(0.0, squares / n - mean * mean)));
}

}  // namespace

std::vector<float> luminanceVariance(const PathRender& render) {
    const int w = render.width(), h = render.height();
    std::vector<float> v(size_t(w) * size_t(h), 0.0f), rowLargest(size_t(h), 0.0f);
    eachRow(render, [&](int y) {
        std::vector<float> row(3 * size_t(w));
        render.standardErrorRow(y, row.data());
        for (int x = 0; x < w; ++x) {
            const float se = luminance(glm::vec3(row[3 * size_t(x)], row[3 * size_t(x) + 1], row[3 * size_t(x) + 2]));
            v[size_t(y) * size_t(w) + size_t(x)] = se * se;
            rowLargest[size_t(y)] = std::max(rowLargest[size_t(y)], se * se);
        }
    });
    const float largest = h > 0 ? *std::max_element(rowLargest.begin(), rowLargest.end()) : 0.0f;
    eachRow(render, [&](int y) {
        for (int x = 0; x < w; ++x)
            if (render.pixelSamples(x, y) < 2) v[size_t(y) * size_t(w) + size_t(x)] = largest;
    });
    return v;
}

std::vector<float> stopVariance(const PathRender& render, std::vector<float> variance) {
    // The weight of the neighbours' mean, in samples: measured on the Cornell box (bench/denoise_quality),
    // 16 to 64 do alike at 4 and 16 spp.
    constexpr float kPriorSamples = 16.0f;
    const int w = render.width(), h = render.height(), bands = (h + kRowsPerTask - 1) / kRowsPerTask;
    const size_t width = size_t(w);
    // A pixel of one sample has no variance of its own to tell: its luminance's spread over its 3x3
    // neighbours stands in (the first pass of a progressive render, which is all such pixels).
    std::vector<float> lum;
    if (render.samples() < 2) {
        lum.resize(variance.size());
        eachRow(render, [&](int y) {
            for (int x = 0; x < w; ++x) lum[size_t(y) * width + size_t(x)] = luminance(render.mean(x, y));
        });
    }
    const auto standardErrors = [&](int y, float* out) {
        for (size_t x = 0; x < width; ++x) out[x] = std::sqrt(variance[size_t(y) * width + x]);
        if (lum.empty()) return;
        for (int x = 0; x < w; ++x)
            if (render.pixelSamples(x, y) < 2) out[size_t(x)] = neighbourSpread(lum, w, h, x, y);
    };
    // In place, band by band of rows: first each band's neighbouring rows, before any band overwrites them.
    std::vector<float> edges(2 * size_t(bands) * width);
    parallelFor(bands, render.settings().threads, [&](int band) {
        const int first = band * kRowsPerTask, end = std::min(h, first + kRowsPerTask);
        if (first > 0) standardErrors(first - 1, &edges[2 * size_t(band) * width]);
        if (end < h) standardErrors(end, &edges[(2 * size_t(band) + 1) * width]);
    });
    parallelFor(bands, render.settings().threads, [&](int band) {
        const int first = band * kRowsPerTask, end = std::min(h, first + kRowsPerTask);
        // The standard errors of rows y − 1, y and y + 1, their sums down each column (one zero column each
        // side) and each pixel's samples. Plain loops over whole rows, which the compiler vectorises.
        std::vector<float> rows(3 * width), columns(width + 2), samples(width);
        float* above = rows.data();
        float* here = above + width;
        float* below = here + width;
        float* column = columns.data() + 1;
        if (first > 0) std::copy_n(&edges[2 * size_t(band) * width], width, above);
        standardErrors(first, here);
        for (int y = first; y < end; ++y) {
            if (y + 1 < end) standardErrors(y + 1, below);
            if (y + 1 == end && end < h) std::copy_n(&edges[(2 * size_t(band) + 1) * width], width, below);
            const float up = y > 0 ? 1.0f : 0.0f, down = y + 1 < h ? 1.0f : 0.0f;
            for (size_t x = 0; x < width; ++x) column[x] = here[x] + up * above[x] + down * below[x];
            for (int x = 0; x < w; ++x) samples[size_t(x)] = float(render.pixelSamples(x, y));
            // The mean over the 3x3 pixels inside the image: 3 columns but at the image's sides.
            const float rowsIn = 1.0f + up + down, inner = 1.0f / (3.0f * rowsIn);
            float* out = &variance[size_t(y) * width];
            const auto at = [&](size_t x, float inverseCount) {
                const float mean = (column[x - 1] + column[x] + column[x + 1]) * inverseCount;
                const float se = (samples[x] * here[x] + kPriorSamples * mean) / (samples[x] + kPriorSamples);
                out[x] = se * se;
            };
            for (size_t x = 1; x + 1 < width; ++x) at(x, inner);
            const float side = 1.0f / (float(std::min(w, 2)) * rowsIn);
            at(0, side);
            if (w > 1) at(width - 1, side);
            std::swap(above, here);
            std::swap(here, below);
        }
    });
    return variance;
}

DenoiseSettings previewSettings(int samples, DenoiseSettings settings) {
    settings.sigmaLuminance *=
        std::max(kNarrowestStop, std::sqrt(float(kSamplesAtUsualStop) / float(std::max(1, samples))));
    return settings;
}

namespace {

// Both overloads': `variance` is taken over (stopVariance works in place on it).
ImageF denoiseWithVariance(const PathRender& render, std::vector<float> variance, const SurfacePasses& passes,
                           const DenoiseSettings& settings) {
    DenoiseSettings s = previewSettings(render.samples(), settings);
    if (s.threads == 0) s.threads = render.settings().threads;
    return denoise(render.image(), stopVariance(render, std::move(variance)), passes, s);
}

}  // namespace

ImageF denoisedImage(const PathRender& render, const std::vector<float>& variance, const SurfacePasses& passes,
                     const DenoiseSettings& settings) {
    return denoiseWithVariance(render, variance, passes, settings);
}

ImageF denoisedImage(const PathRender& render, const SurfacePasses& passes, const DenoiseSettings& settings) {
    return denoiseWithVariance(render, luminanceVariance(render), passes, settings);
}

}  // namespace shadelab::trace
