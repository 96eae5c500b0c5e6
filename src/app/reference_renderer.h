// ReferenceRenderer: the CPU ray-traced reference for the viewer, rendered progressively on background
// threads (src/trace ProgressiveTrace) and restarted whenever the state changes. The UI thread collects
// finished tiles each frame into a float texture, so the window stays responsive while it runs.
#pragma once

#include "app/job_hand_off.h"
#include "gl/objects.h"
#include "image/image.h"
#include "render/render_request.h"
#include "scene/scene.h"
#include "trace/accel/mesh_bvh_cache.h"
#include "trace/tile_renderer.h"

#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace shadelab::app {

class ReferenceRenderer {
public:
    // Starts the controller thread, which drops to SCHED_IDLE before it starts workers, so they inherit it
    // and the UI thread keeps the cores it needs. Workers: max(1, cores - 1).
    ReferenceRenderer();
    ~ReferenceRenderer();
    ReferenceRenderer(const ReferenceRenderer&) = delete;
    ReferenceRenderer& operator=(const ReferenceRenderer&) = delete;

    // UI thread. Restarts the trace when (revision, size, depth) differ from the last request; cheap
    // otherwise (the scene copy is O(objects)). maxDepth -1 keeps the scene's secondary-ray depth.
    void request(const Scene& scene, int width, int height, uint64_t revision, int maxDepth = -1);
    // The mesh BVH of `scene`'s geometry, shared with the trace workers (built once per geometry). The
    // probe traces through it, so it asks the very scene the reference renders.
    std::shared_ptr<const trace::MeshBvh> meshBvh(const Scene& scene) { return meshes_.get(scene); }
    // The cache itself, shared with the path tracer of Global mode (GlobalRenderer).
    trace::MeshBvhCache& meshCache() { return meshes_; }
    // Cancels any trace in progress (e.g. back in Raster mode); the next request starts afresh.
    void pause();
    // UI thread, GL context current: moves finished tiles into the image and the textures. True when
    // anything arrived.
    bool update();

    GLuint texture() const { return color_.id(); }      // RGBA32F, GL row order, like the raster target
    GLuint tileTexture() const { return tiles_.id(); }  // R8, 1 = tile rendered for the current request
    int tileSize() const { return kTileSize; }
    bool active() const { return job_ != 0; }
    bool complete() const { return job_ != 0 && tilesDone_ == tileTotal_; }
    float progress() const { return tileTotal_ ? float(tilesDone_) / float(tileTotal_) : 0.0f; }
    double seconds() const;                          // since the current request, or its total
    uint64_t revision() const { return revision_; }  // the state revision being traced
    const ImageF& image() const { return image_; }   // linear, row 0 at the top
    const std::vector<uint32_t>& coverage() const { return coverage_; }
    std::string error() const;
    int threads() const { return threads_; }

private:
    static constexpr int kTileSize = 32;
    struct Job {
        uint64_t id;
        Scene scene;
        render::RenderRequest request;  // the Whitted tracer at the image's size and depth, with coverage
    };
    void controllerLoop();
    void resize(int width, int height);

    // Shared with the controller thread.
    JobHandOff<Job> jobs_;
    std::mutex arrivedMutex_;
    std::vector<std::pair<uint64_t, trace::TileResult>> arrived_;  // (job id, tile), not yet collected
    trace::MeshBvhCache meshes_;
    int threads_ = 1;

    // UI thread only.
    uint64_t nextJob_ = 1, job_ = 0, revision_ = 0;
    int maxDepth_ = -1;
    int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0, tilesDone_ = 0, tileTotal_ = 0;
    ImageF image_;
    std::vector<uint32_t> coverage_;
    std::vector<uint8_t> tileState_;
    bool tilesDirty_ = false;
    std::chrono::steady_clock::time_point started_, finished_;
    gl::Texture color_, tiles_;
    std::vector<float> flipped_;

    std::thread controller_;  // last: it starts once every member exists
};

}  // namespace shadelab::app
