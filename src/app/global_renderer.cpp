// GlobalRenderer: the UI-side upload of the path tracer's passes; the passes themselves run on the controller
// thread (path_pass_work.h).
#include "app/global_renderer.h"

namespace shadelab::app {

GlobalRenderer::GlobalRenderer(trace::MeshBvhCache& meshes) : work_(meshes), controller_(work_) {}

void GlobalRenderer::request(const Scene& scene, int width, int height, uint64_t revision, trace::PathPart part) {
    if (width <= 0 || height <= 0) return;
    if (active() && revision == revision_ && width == width_ && height == height_ && part == part_) return;
    if (width != width_ || height != height_ || !color_) {
        width_ = width;
        height_ = height;
        color_ = makeImageTexture(width, height);
        denoised_ = makeImageTexture(width, height);
    }
    // Until the first tiles of this request arrive, the display shows the raster image (tile test 0).
    tiles_.reset(width, height, kTileSize);
    tiles_.upload();
    revision_ = revision;
    part_ = part;
    samples_ = 0;
    denoisedSamples_ = 0;
    noise8_ = 0.0;
    work_.dropArrived();
    render::RenderRequest r;
    r.engine = render::Engine::Path;
    r.width = width;
    r.height = height;
    r.threads = controller_.threads();
    r.path.part = part;
    controller_.post(scene, r);
}

void GlobalRenderer::pause() {
    if (!active()) return;
    samples_ = 0;
    denoisedSamples_ = 0;
    controller_.pause();
    work_.dropArrived();
}

bool GlobalRenderer::update() {
    std::optional<PathPassWork::Pass> pass = work_.takeArrived();
    if (!pass || pass->job != controller_.job() || pass->image.width != width_ || pass->image.height != height_)
        return false;
    samples_ = pass->samples;
    noise8_ = pass->noise8;
    image_ = std::move(pass->image);
    standardError_ = std::move(pass->standardError);
    // GL row order, as the raster target.
    uploadRowsFlipped(color_, 0, 0, width_, height_, height_, image_.rgba.data(), flipped_);
    tiles_.assign(pass->tiles);
    tiles_.upload();
    if (pass->denoised.width == width_ && pass->denoised.height == height_) {
        denoisedSamples_ = pass->denoisedSamples;
        denoisedImage_ = std::move(pass->denoised);
        uploadRowsFlipped(denoised_, 0, 0, width_, height_, height_, denoisedImage_.rgba.data(), flipped_);
    }
    return true;
}

GlobalEstimate GlobalRenderer::estimate(int x, int y) const {
    GlobalEstimate e;
    if (samples_ == 0 || x < 0 || y < 0 || x >= image_.width || y >= image_.height) return e;
    const float* p = image_.pixel(x, y);
    e.mean = glm::vec3(p[0], p[1], p[2]);
    e.standardError = standardError_[size_t(y) * size_t(image_.width) + size_t(x)];
    e.samples = samples_;
    return e;
}

}  // namespace shadelab::app
