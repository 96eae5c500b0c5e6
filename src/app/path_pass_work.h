// PathPassWork: what the Global modes' controller thread runs (background_controller.h): a trace::PathRender
// that gains one sample per pixel per step, up to kMaxSamples. After each pass it leaves the mean image and
// each pixel's standard error for the UI thread; during the first pass it leaves the tiles done so far every
// ~0.3 s (pending tiles show the raster image, as the reference's do). Whole passes also carry the denoised
// preview (trace/path/path_denoise.h), guided by first-hit passes computed once per job: after the first pass,
// and then whenever the time since the last one is at least kDenoiseShare⁻¹ times what it took, so the
// denoiser never takes more than about a fifth of the path tracer's time.
#pragma once

#include "app/background_controller.h"
#include "image/image.h"
#include "trace/accel/mesh_bvh_cache.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_render.h"
#include "trace/trace_scene.h"

#include <atomic>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace shadelab::app {

class PathPassWork : public BackgroundWork {
public:
    static constexpr int kMaxSamples = 4096;
    static constexpr int kTileSize = 16;
    static constexpr double kDenoiseShare = 0.25;  // denoising time over tracing time, at most

    // One pass, or the first pass's tiles so far (samples 0 then, and no denoised image).
    struct Pass {
        uint64_t job = 0;
        int samples = 0;
        double noise8 = 0.0;  // mean standard error, 8-bit sRGB units
        ImageF image;         // linear, row 0 at the top; pixels of tiles not yet done are 0
        std::vector<glm::vec3> standardError;
        std::vector<uint8_t> tiles;  // tilesX × tilesY, row 0 at the top: 255 = every pixel has a sample
        ImageF denoised;             // whole passes only, and not every one (kDenoiseShare); empty otherwise
        int denoisedSamples = 0;     // the samples per pixel `denoised` was made from (at most `samples`)
    };

    explicit PathPassWork(trace::MeshBvhCache& meshes) : meshes_(meshes) {}

    void start(const BackgroundJob& job) override;
    bool busy() const override { return render_ && render_->samples() < kMaxSamples; }
    void step(const std::atomic<bool>& cancel) override;  // one pass
    void stop() override;

    // Any thread: the newest pass not yet taken (older ones are dropped).
    std::optional<Pass> takeArrived();
    // UI thread: forget the pass not yet taken (a new job was posted).
    void dropArrived();
    float passProgress() const { return passProgress_; }  // of the pass under way, [0, 1]

private:
    // The render as it stands: during the first pass, only the tiles done so far.
    static Pass snapshot(uint64_t job, const trace::PathRender& render);
    void publish(Pass pass);

    trace::MeshBvhCache& meshes_;
    std::unique_ptr<trace::PathRender> render_;
    std::shared_ptr<const trace::TraceScene> scene_;
    std::optional<SurfacePasses> guides_;  // the denoiser's, computed after the first pass of each job
    uint64_t running_ = 0;
    int threads_ = 1;
    double tracing_ = 0.0, denoising_ = 0.0;  // seconds since the last denoised preview, and what it took
    std::atomic<float> passProgress_{0.0f};
    std::mutex arrivedMutex_;
    std::optional<Pass> arrived_;  // under arrivedMutex_
};

}  // namespace shadelab::app
