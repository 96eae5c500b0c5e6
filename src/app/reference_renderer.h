// ReferenceRenderer: the CPU ray-traced reference for the viewer, rendered progressively on background threads
// (a BackgroundController running ReferenceWork) and restarted whenever the state changes. The UI thread
// collects finished tiles each frame into a float texture, so the window stays responsive while it runs.
#pragma once

#include "app/background_controller.h"
#include "app/background_textures.h"
#include "app/reference_work.h"
#include "gl/objects.h"
#include "image/image.h"
#include "render/render_request.h"
#include "scene/scene.h"
#include "trace/accel/mesh_bvh_cache.h"
#include "trace/tile_renderer.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace shadelab::app {

class ReferenceRenderer {
public:
    // Starts the controller thread (at idle priority, so the UI thread keeps the cores it needs). Workers:
    // max(1, cores - 1).
    ReferenceRenderer();
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

    GLuint texture() const { return color_.id(); }           // RGBA32F, GL row order, like the raster target
    GLuint tileTexture() const { return tiles_.texture(); }  // R8, 1 = tile rendered for the current request
    int tileSize() const { return kTileSize; }
    bool active() const { return controller_.active(); }
    bool complete() const { return active() && tiles_.done() == tiles_.total(); }
    float progress() const { return tiles_.total() ? float(tiles_.done()) / float(tiles_.total()) : 0.0f; }
    double seconds() const;                          // since the current request, or its total
    uint64_t revision() const { return revision_; }  // the state revision being traced
    const ImageF& image() const { return image_; }   // linear, row 0 at the top
    const std::vector<uint32_t>& coverage() const { return coverage_; }
    std::string error() const { return controller_.error(); }
    int threads() const { return controller_.threads(); }

private:
    static constexpr int kTileSize = 32;
    void resize(int width, int height);

    trace::MeshBvhCache meshes_;  // shared with the controller thread's work
    ReferenceWork work_;

    // UI thread only.
    uint64_t revision_ = 0;
    int maxDepth_ = -1;
    int width_ = 0, height_ = 0;
    ImageF image_;
    std::vector<uint32_t> coverage_;
    TileMask tiles_;
    double finished_ = 0.0;  // seconds() when the last tile arrived
    gl::Texture color_;
    std::vector<float> flipped_;

    BackgroundController controller_;  // last: its thread starts once the work exists
};

}  // namespace shadelab::app
