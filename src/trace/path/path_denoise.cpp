#include "trace/path/path_denoise.h"

#include "trace/luminance.h"
#include "util/parallel_for.h"

#include <algorithm>

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

ImageF denoisedImage(const PathRender& render, const SurfacePasses& passes, const DenoiseSettings& settings) {
    DenoiseSettings s = settings;
    if (s.threads == 0) s.threads = render.settings().threads;
    return denoise(render.image(), luminanceVariance(render), passes, s);
}

}  // namespace shadelab::trace
