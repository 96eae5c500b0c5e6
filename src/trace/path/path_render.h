// PathRender: the path tracer's image, accumulated progressively (design.md §8). Every pixel keeps the sum
// and the sum of squares of its samples in double and its sample count; a pass adds samples n, n+1, ... in
// order to each pixel, one pixel wholly on one thread. Samples draw their numbers from SampleRng keyed by
// (pixel, sample index, bounce), so the image is the same bytes for any thread count, tile order or split
// into passes: a progressive run to N samples equals a one-shot run with N. The viewer's Global mode and the
// CLI (pathTraceImage) both drive it.
#pragma once

#include "image/encode.h"
#include "image/image.h"
#include "image/surface_passes.h"
#include "scene/view.h"
#include "trace/path/path_integrator.h"
#include "trace/path/path_settings.h"
#include "trace/trace_scene.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace shadelab::trace {

class PathRender {
public:
    // Validates the settings (std::invalid_argument) and resolves maxDepth −1 to the scene's.
    PathRender(std::shared_ptr<const TraceScene> scene, const PathSettings& settings);

    // Adds `count` samples to every pixel on settings.threads workers. `progress`, when set, is called on the
    // calling thread with the fraction of this pass done (every ~50 ms). A pixel's samples of one pass are
    // added all or none: when `cancel` turns true the pass stops between pixels and returns false, and the
    // pixels it did not reach keep fewer samples (pixelSamples()).
    bool addSamples(int count, const std::atomic<bool>* cancel = nullptr,
                    const std::function<void(float)>& progress = {});

    // Adds `count` samples to the pixels of rows first, first + step, ... on the calling thread alone: one Web
    // Worker's share of the image (the web page splits the rows between its workers). Each pixel gets the bytes
    // addSamples would give it, so the shares put together are the image of one PathRender.
    void addSamplesToRows(int count, int first, int step);

    int width() const { return settings_.width; }
    int height() const { return settings_.height; }
    const PathSettings& settings() const { return settings_; }
    // The fewest samples any pixel has.
    int samples() const;
    // Safe to call while a pass runs (the viewer shows the first pass's finished tiles): a count read as n
    // (acquire) makes that pixel's first n samples' sums visible.
    uint32_t pixelSamples(int x, int y) const {
        return count_[size_t(y) * size_t(width()) + size_t(x)].load(std::memory_order_acquire);
    }

    // The mean of each pixel's samples, linear RGB, alpha 1, row 0 at the top (black where none).
    ImageF image() const;
    // The pixel's mean and the standard error of that mean, per channel (0 with fewer than 2 samples).
    glm::vec3 mean(int x, int y) const;
    glm::vec3 standardError(int x, int y) const;
    // standardError(x, y) for every pixel of row y, bit for bit, three floats per pixel into `out`: a row at a
    // time, in loops the compiler vectorises, for the denoiser's variance (trace/path/path_denoise.h), which
    // a preview computes every frame.
    void standardErrorRow(int y, float* out) const;
    // The standard error averaged over pixels and channels in 8-bit units of `encoding` (through the
    // encoding's slope at each pixel's mean): the noise a reader of the PNG sees.
    double meanStandardError8(Encoding encoding) const;
    // Coverage ids of the first hit through each pixel's centre (settings.coverage), else empty.
    const std::vector<uint32_t>& coverage() const { return coverage_; }

private:
    void renderPixel(int x, int y, int count);

    std::shared_ptr<const TraceScene> scene_;
    PathSettings settings_;
    ViewSetup view_;
    std::unique_ptr<PathIntegrator> integrator_;      // over *scene_, with the resolved settings
    std::vector<double> sum_, sumSq_;                 // 3 per pixel
    std::unique_ptr<std::atomic<uint32_t>[]> count_;  // per pixel; written (release) after its sums
    std::vector<uint32_t> coverage_;
};

struct PathOutput {
    ImageF color;                     // linear RGB, alpha 1: the estimate, denoised with settings.denoise
    ImageF raw;                       // settings.denoise only: the estimate before denoising
    SurfacePasses passes;             // settings.denoise only: the first-hit passes that guided it
    std::vector<float> variance;      // per pixel, the variance of the luminance estimate (luminanceVariance)
    std::vector<uint32_t> coverage;   // settings.coverage only
    int spp = 0;                      // samples every pixel got (below settings.spp when the time limit hit)
    double seconds = 0.0;             // tracing time
    double meanStandardError8 = 0.0;  // in 8-bit sRGB units (PathRender::meanStandardError8)
};

// The one-shot render: settings.spp samples, or fewer when settings.timeLimit ends it at a whole pass
// (then passes of one sample each, so it stops at a whole sample count), and with settings.denoise its
// denoised preview (not counted in `seconds`). `progress` gets the fraction done.
PathOutput pathTraceImage(std::shared_ptr<const TraceScene> scene, const PathSettings& settings,
                          const std::function<void(float)>& progress = {});

}  // namespace shadelab::trace
