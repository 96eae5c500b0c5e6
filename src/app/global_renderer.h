// GlobalRenderer: the path tracer (design.md §8) for the viewer's Global and Local | Global modes. A
// BackgroundController runs PathPassWork (path_pass_work.h), which adds one sample per pixel per pass, forever
// refining until kMaxSamples, restarting whenever the state (or the part of the light shown) changes. The UI
// thread uploads the newest pass, and its denoised preview when it carries one, to float textures.
#pragma once

#include "app/background_controller.h"
#include "app/background_textures.h"
#include "app/path_pass_work.h"
#include "gl/objects.h"
#include "image/image.h"
#include "render/render_request.h"
#include "scene/scene.h"
#include "trace/accel/mesh_bvh_cache.h"
#include "trace/path/path_settings.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
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
    static constexpr int kMaxSamples = PathPassWork::kMaxSamples;
    static constexpr int kTileSize = PathPassWork::kTileSize;

    // Shares the mesh BVH cache with the Whitted reference (built once per geometry).
    explicit GlobalRenderer(trace::MeshBvhCache& meshes);
    GlobalRenderer(const GlobalRenderer&) = delete;
    GlobalRenderer& operator=(const GlobalRenderer&) = delete;

    // UI thread. Restarts when (revision, size, part) differ from the last request; cheap otherwise.
    void request(const Scene& scene, int width, int height, uint64_t revision, trace::PathPart part);
    // Stops the passes (another mode); the next request starts afresh.
    void pause();
    // UI thread, GL context current: uploads the newest pass. True when one arrived.
    bool update();

    bool active() const { return controller_.active(); }
    // Whether the texture holds an image of the current request yet (after its first pass).
    bool ready() const { return active() && samples_ > 0; }
    GLuint texture() const { return color_.id(); }  // RGBA32F, GL row order: the raw estimate
    // The denoised preview, RGBA32F, GL row order; valid once denoisedSamples() > 0.
    GLuint denoisedTexture() const { return denoised_.id(); }
    GLuint tileTexture() const { return tiles_.texture(); }  // R8, one texel per tile: 1 = has its first sample
    int tileSize() const { return kTileSize; }
    int samples() const { return samples_; }
    // The samples per pixel of the newest denoised preview (0: none yet); at most samples().
    int denoisedSamples() const { return denoisedSamples_; }
    const ImageF& denoisedImage() const { return denoisedImage_; }  // linear, row 0 at the top
    uint64_t revision() const { return revision_; }                 // the state revision being rendered
    float passProgress() const { return work_.passProgress(); }     // of the pass under way, [0, 1]
    double noise8() const { return noise8_; }                       // mean standard error, 8-bit sRGB units
    double seconds() const { return controller_.seconds(); }
    int threads() const { return controller_.threads(); }
    std::string error() const { return controller_.error(); }
    const ImageF& image() const { return image_; }  // the raw estimate, linear, row 0 at the top
    // The estimate at pixel (x, y), row 0 at the top; samples 0 before the first pass.
    GlobalEstimate estimate(int x, int y) const;

private:
    PathPassWork work_;

    // UI thread only.
    uint64_t revision_ = 0;
    trace::PathPart part_ = trace::PathPart::All;
    int width_ = 0, height_ = 0, samples_ = 0, denoisedSamples_ = 0;
    double noise8_ = 0.0;
    ImageF image_, denoisedImage_;
    std::vector<glm::vec3> standardError_;
    gl::Texture color_, denoised_;
    TileMask tiles_;
    std::vector<float> flipped_;

    BackgroundController controller_;  // last: its thread starts once the work exists
};

}  // namespace shadelab::app
