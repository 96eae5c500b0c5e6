// ReferenceRenderer: the UI-side tile collection into a CPU image and two textures; the trace itself runs on
// the controller thread (reference_work.h).
#include "app/reference_renderer.h"

#include <algorithm>
#include <cstring>

namespace shadelab::app {

ReferenceRenderer::ReferenceRenderer() : work_(meshes_, kTileSize), controller_(work_) {}

void ReferenceRenderer::resize(int width, int height) {
    width_ = width;
    height_ = height;
    image_ = ImageF(width, height);
    coverage_.assign(size_t(width) * size_t(height), 0u);
    color_ = makeImageTexture(width, height, image_.rgba.data());
}

void ReferenceRenderer::request(const Scene& scene, int width, int height, uint64_t revision, int maxDepth) {
    if (width <= 0 || height <= 0) return;
    if (active() && revision == revision_ && width == width_ && height == height_ && maxDepth == maxDepth_) return;
    if (width != width_ || height != height_ || !color_) resize(width, height);
    tiles_.reset(width, height, kTileSize);
    revision_ = revision;
    maxDepth_ = maxDepth;
    render::RenderRequest r;
    r.engine = render::Engine::Trace;
    r.width = width;
    r.height = height;
    if (maxDepth >= 0) r.depth = maxDepth;  // -1: the scene's
    r.threads = controller_.threads();
    r.coverage = true;
    controller_.post(scene, r);
}

void ReferenceRenderer::pause() { controller_.pause(); }

bool ReferenceRenderer::update() {
    bool any = false;
    for (auto& [id, t] : work_.takeArrived()) {
        if (id != controller_.job()) continue;  // from a cancelled request
        const trace::Tile& tile = t.tile;
        // CPU copy (row 0 at the top) for captures and metrics.
        for (int row = 0; row < tile.height; ++row) {
            std::memcpy(image_.pixel(tile.x0, tile.y0 + row), &t.rgba[size_t(row) * size_t(tile.width) * 4],
                        size_t(tile.width) * 4 * sizeof(float));
            if (!t.coverage.empty())
                std::memcpy(&coverage_[size_t(tile.y0 + row) * size_t(width_) + size_t(tile.x0)],
                            &t.coverage[size_t(row) * size_t(tile.width)], size_t(tile.width) * sizeof(uint32_t));
        }
        // The texture is in GL row order, as the raster target is.
        uploadRowsFlipped(color_, tile.x0, tile.y0, tile.width, tile.height, height_, t.rgba.data(), flipped_);
        tiles_.mark(tile.x0 / kTileSize, tile.y0 / kTileSize);
        any = true;
    }
    if (any && complete()) finished_ = controller_.seconds();
    tiles_.upload();
    return any;
}

double ReferenceRenderer::seconds() const { return complete() ? finished_ : controller_.seconds(); }

}  // namespace shadelab::app
