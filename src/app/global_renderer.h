// GlobalRenderer: the path tracer (design.md §8) for the viewer's Global and Local | Global modes. A
// controller thread at idle priority owns a trace::PathRender and adds one sample per pixel per pass,
// forever refining until kMaxSamples, restarting whenever the state (or the part of the light shown)
// changes. After each pass it hands the mean image, and each pixel's standard error, to the UI thread,
// which uploads it to a float texture; during the first pass it hands over the tiles done so far every
// ~0.3 s (pending tiles show the raster image, as the reference's do). Whole passes also carry the denoised
// preview (trace/path/path_denoise.h), guided by the first-hit passes computed once per request: after the
// first pass, and then whenever the time since the last one is at least kDenoiseShare⁻¹ times what it took,
// so the denoiser never takes more than about a fifth of the path tracer's time.
#pragma once

#include "app/job_hand_off.h"
#include "gl/objects.h"
#include "image/image.h"
#include "render/render_request.h"
#include "scene/scene.h"
#include "trace/accel/mesh_bvh_cache.h"
#include "trace/path/path_render.h"
#include "trace/path/path_settings.h"

#include <atomic>
#include <cstdint>
#include <glm/vec3.hpp>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace shadelab::app {

// The path tracer's estimate at one pixel (the probe's "global" row).
struct GlobalEstimate {
    glm::vec3 mean{0.0f};           // linear RGB
    glm::vec3 standardError{0.0f};  // of that mean, per channel
    int samples = 0;
};

class GlobalRenderer {
public:
    static constexpr int kMaxSamples = 4096;
    static constexpr int kTileSize = 16;
    static constexpr double kDenoiseShare = 0.25;  // denoising time over tracing time, at most

    // Shares the mesh BVH cache with the Whitted reference (built once per geometry).
    explicit GlobalRenderer(trace::MeshBvhCache& meshes);
    ~GlobalRenderer();
    GlobalRenderer(const GlobalRenderer&) = delete;
    GlobalRenderer& operator=(const GlobalRenderer&) = delete;

    // UI thread. Restarts when (revision, size, part) differ from the last request; cheap otherwise.
    void request(const Scene& scene, int width, int height, uint64_t revision, trace::PathPart part);
    // Stops the passes (another mode); the next request starts afresh.
    void pause();
    // UI thread, GL context current: uploads the newest pass. True when one arrived.
    bool update();

    bool active() const { return job_ != 0; }
    // Whether the texture holds an image of the current request yet (after its first pass).
    bool ready() const { return active() && samples_ > 0; }
    GLuint texture() const { return color_.id(); }  // RGBA32F, GL row order: the raw estimate
    // The denoised preview, RGBA32F, GL row order; valid once denoisedSamples() > 0.
    GLuint denoisedTexture() const { return denoised_.id(); }
    GLuint tileTexture() const { return done_.id(); }  // R8, one texel per tile: 1 = has its first sample
    int tileSize() const { return kTileSize; }
    int samples() const { return samples_; }
    // The samples per pixel of the newest denoised preview (0: none yet); at most samples().
    int denoisedSamples() const { return denoisedSamples_; }
    const ImageF& denoisedImage() const { return denoisedImage_; }  // linear, row 0 at the top
    uint64_t revision() const { return revision_; }                 // the state revision being rendered
    float passProgress() const;                                     // of the pass under way, [0, 1]
    double noise8() const { return noise8_; }                       // mean standard error, 8-bit sRGB units
    double seconds() const;
    int threads() const { return threads_; }
    std::string error() const;
    const ImageF& image() const { return image_; }  // the raw estimate, linear, row 0 at the top
    // The estimate at pixel (x, y), row 0 at the top; samples 0 before the first pass.
    GlobalEstimate estimate(int x, int y) const;

private:
    struct Job {
        uint64_t id;
        Scene scene;
        render::RenderRequest request;  // the path tracer at the image's size, for the light paths asked for
    };
    struct Pass {  // one finished pass, controller → UI
        uint64_t job = 0;
        int samples = 0;
        double noise8 = 0.0;
        ImageF image;
        std::vector<glm::vec3> standardError;
        std::vector<uint8_t> tiles;  // tilesX × tilesY, row 0 at the top: 255 = every pixel has a sample
        ImageF denoised;             // whole passes only, and not every one (kDenoiseShare); empty otherwise
    };
    // The render's state for the UI: during the first pass, the tiles done so far (the rest show the raster).
    static Pass snapshot(uint64_t job, const trace::PathRender& render);
    void controllerLoop();
    void uploadTiles(const std::vector<uint8_t>& tiles);  // UI thread

    trace::MeshBvhCache& meshes_;
    JobHandOff<Job> jobs_;
    std::atomic<bool> cancel_{false};  // set by the UI thread: the pass under way stops between pixels
    std::mutex arrivedMutex_;
    std::optional<Pass> arrived_;  // under arrivedMutex_
    std::atomic<float> passProgress_{0.0f};
    int threads_ = 1;

    // UI thread only.
    uint64_t nextJob_ = 1, job_ = 0, revision_ = 0;
    trace::PathPart part_ = trace::PathPart::All;
    int width_ = 0, height_ = 0, samples_ = 0, denoisedSamples_ = 0, tilesX_ = 0, tilesY_ = 0;
    double noise8_ = 0.0;
    ImageF image_, denoisedImage_;
    std::vector<glm::vec3> standardError_;
    double started_ = 0.0;
    gl::Texture color_, denoised_, done_;
    std::vector<float> flipped_;

    std::thread controller_;  // last: it starts once every member exists
};

}  // namespace shadelab::app
