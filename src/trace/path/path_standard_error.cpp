// PathRender's standard error of each pixel's mean, per pixel and a row at a time with the same expressions in
// the same order, so the same bits. Built with -fno-math-errno and -fno-trapping-math (src/trace/CMakeLists.txt),
// without which GCC 12 leaves the row's loop scalar; neither changes a result.
#include "trace/path/path_render.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab::trace {

glm::vec3 PathRender::standardError(int x, int y) const {
    const size_t p = size_t(y) * size_t(settings_.width) + size_t(x);
    const double n = double(count_[p].load(std::memory_order_acquire));
    if (n < 2.0) return glm::vec3(0.0f);
    glm::vec3 se;
    for (int ch = 0; ch < 3; ++ch) {
        const double m = sum_[3 * p + size_t(ch)] / n;
        const double var = std::max(0.0, (sumSq_[3 * p + size_t(ch)] / n - m * m) * n / (n - 1.0));
        se[ch] = float(std::sqrt(var / n));
    }
    return se;
}

void PathRender::standardErrorRow(int y, float* out) const {
    const int w = settings_.width;
    const size_t p0 = size_t(y) * size_t(w);
    // Each channel's sample count beside its sums, so that the loop below is one operation per channel.
    std::vector<double> n(3 * size_t(w));
    for (int x = 0; x < w; ++x)
        n[3 * size_t(x)] = n[3 * size_t(x) + 1] = n[3 * size_t(x) + 2] =
            double(count_[p0 + size_t(x)].load(std::memory_order_acquire));
    const double* sum = &sum_[3 * p0];
    const double* sumSq = &sumSq_[3 * p0];
    // The expressions of standardError, in its order: the same bits.
    for (size_t i = 0; i < 3 * size_t(w); ++i) {
        const double m = sum[i] / n[i];
        const double var = std::max(0.0, (sumSq[i] / n[i] - m * m) * n[i] / (n[i] - 1.0));
        const float se = float(std::sqrt(var / n[i]));
        out[i] = n[i] < 2.0 ? 0.0f : se;
    }
}

}  // namespace shadelab::trace
