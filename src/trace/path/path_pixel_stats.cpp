// PathRender's per-pixel statistics a row at a time, in loops the compiler vectorises: the image of the means
// and the standard errors, which a denoised preview computes every frame. Built with -fno-math-errno and
// -fno-trapping-math (src/trace/CMakeLists.txt), without which GCC 12 leaves these loops scalar; neither changes
// a result.
#include "trace/path/path_render.h"

#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab::trace {
namespace {

constexpr int kRowsPerTask = 8;

}  // namespace

// The variance of one channel's samples, Bessel-corrected, over the count: the square of the mean's standard
// error. One division per pixel (1/n, n/(n − 1)), shared by the three channels.
glm::vec3 PathRender::standardError(int x, int y) const {
    const size_t p = size_t(y) * size_t(settings_.width) + size_t(x);
    const double n = double(count_[p].load(std::memory_order_acquire));
    if (n < 2.0) return glm::vec3(0.0f);
    const double invN = 1.0 / n, bessel = n / (n - 1.0);
    glm::vec3 se;
    for (int ch = 0; ch < 3; ++ch) {
        const double m = sum_[3 * p + size_t(ch)] * invN;
        const double var = std::max(0.0, (sumSq_[3 * p + size_t(ch)] * invN - m * m) * bessel);
        se[ch] = float(std::sqrt(var * invN));
    }
    return se;
}

void PathRender::standardErrorRow(int y, float* out) const {
    const int w = settings_.width;
    const size_t p0 = size_t(y) * size_t(w);
    // Each channel's 1/n and n/(n − 1) beside its sums, so that the loop below is one operation per channel.
    std::vector<double> invN(3 * size_t(w)), bessel(3 * size_t(w));
    for (int x = 0; x < w; ++x) {
        const double n = double(count_[p0 + size_t(x)].load(std::memory_order_acquire));
        // Fewer than two samples: no error (standardError's early return), 0 here.
        const double i = n < 2.0 ? 0.0 : 1.0 / n, b = n < 2.0 ? 0.0 : n / (n - 1.0);
        for (int c = 0; c < 3; ++c) {
            invN[3 * size_t(x) + size_t(c)] = i;
            bessel[3 * size_t(x) + size_t(c)] = b;
        }
    }
    const double* sum = &sum_[3 * p0];
    const double* sumSq = &sumSq_[3 * p0];
    // standardError's expressions in its order: the same bits.
    for (size_t i = 0; i < 3 * size_t(w); ++i) {
        const double m = sum[i] * invN[i];
        const double var = std::max(0.0, (sumSq[i] * invN[i] - m * m) * bessel[i]);
        out[i] = float(std::sqrt(var * invN[i]));
    }
}

ImageF PathRender::image() const {
    const int w = settings_.width, h = settings_.height;
    ImageF img(w, h);
    parallelFor((h + kRowsPerTask - 1) / kRowsPerTask, settings_.threads, [&](int task) {
        std::vector<double> n(3 * size_t(w));
        for (int y = task * kRowsPerTask; y < std::min(h, (task + 1) * kRowsPerTask); ++y) {
            const size_t p0 = size_t(y) * size_t(w);
            for (int x = 0; x < w; ++x)
                n[3 * size_t(x)] = n[3 * size_t(x) + 1] = n[3 * size_t(x) + 2] =
                    double(count_[p0 + size_t(x)].load(std::memory_order_acquire));
            // mean()'s expression, sum / n, the same bits; black where no sample.
            const double* sum = &sum_[3 * p0];
            float* rgb = img.pixel(0, y);
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) {
                    const size_t i = 3 * size_t(x) + size_t(c);
                    rgb[4 * x + c] = n[i] > 0.0 ? float(sum[i] / n[i]) : 0.0f;
                }
            for (int x = 0; x < w; ++x) rgb[4 * x + 3] = 1.0f;
        }
    });
    return img;
}

}  // namespace shadelab::trace
