// ReferenceRenderer: the controller thread (owns ProgressiveTrace; the mesh BVH comes from the cache) and the UI-side
// tile collection into a CPU image and two textures.
#include "app/reference_renderer.h"

#include "app/background_textures.h"
#include "app/idle_priority.h"
#include "trace/progressive_trace.h"
#include "trace/trace_scene.h"

#include <algorithm>
#include <cstring>

namespace shadelab::app {

ReferenceRenderer::ReferenceRenderer() : threads_(backgroundWorkerCount()), controller_([this] { controllerLoop(); }) {}

ReferenceRenderer::~ReferenceRenderer() {
    jobs_.quit();
    controller_.join();
}

void ReferenceRenderer::controllerLoop() {
    lowerToIdlePriority();  // inherited by the trace workers started below
    trace::ProgressiveTrace trace;
    uint64_t running = 0;
    for (;;) {
        std::optional<Job> job;
        const auto event = jobs_.take(running == 0 || trace.done(), job);
        if (event == JobHandOff<Job>::Event::Quit) break;
        if (event == JobHandOff<Job>::Event::Pause) {
            trace.cancel();
            running = 0;
            continue;
        }
        if (job) {
            trace.cancel();
            running = 0;
            try {
                auto scene = std::make_shared<trace::TraceScene>(job->scene, meshes_.get(job->scene));
                trace::TraceSettings settings = render::toTrace(job->request, job->scene);
                settings.tileSize = kTileSize;
                trace.start(scene, settings);
                running = job->id;
            } catch (const std::exception& e) {
                jobs_.fail(e.what());
                continue;
            }
        }
        if (running) {
            std::vector<trace::TileResult> tiles;
            trace.wait(tiles, std::chrono::milliseconds(30));
            if (!tiles.empty()) {
                std::lock_guard<std::mutex> lock(arrivedMutex_);
                for (trace::TileResult& t : tiles) arrived_.emplace_back(running, std::move(t));
            }
        }
    }
    trace.cancel();
}

void ReferenceRenderer::resize(int width, int height) {
    width_ = width;
    height_ = height;
    image_ = ImageF(width, height);
    coverage_.assign(size_t(width) * size_t(height), 0u);
    tilesX_ = (width + kTileSize - 1) / kTileSize;
    tilesY_ = (height + kTileSize - 1) / kTileSize;
    tileState_.assign(size_t(tilesX_) * size_t(tilesY_), 0);
    color_ = makeImageTexture(width, height, image_.rgba.data());
    tiles_ = makeTileTexture();
    tilesDirty_ = true;
}

void ReferenceRenderer::request(const Scene& scene, int width, int height, uint64_t revision, int maxDepth) {
    if (width <= 0 || height <= 0) return;
    if (job_ != 0 && revision == revision_ && width == width_ && height == height_ && maxDepth == maxDepth_) return;
    if (width != width_ || height != height_ || !color_) resize(width, height);
    std::fill(tileState_.begin(), tileState_.end(), uint8_t(0));
    tilesDirty_ = true;
    tilesDone_ = 0;
    tileTotal_ = tilesX_ * tilesY_;
    revision_ = revision;
    maxDepth_ = maxDepth;
    job_ = nextJob_++;
    started_ = std::chrono::steady_clock::now();
    render::RenderRequest r;
    r.engine = render::Engine::Trace;
    r.width = width;
    r.height = height;
    if (maxDepth >= 0) r.depth = maxDepth;  // -1: the scene's
    r.threads = threads_;
    r.coverage = true;
    jobs_.post(Job{job_, scene, r});
}

void ReferenceRenderer::pause() {
    if (job_ == 0) return;
    job_ = 0;
    jobs_.pause();
}

bool ReferenceRenderer::update() {
    std::vector<std::pair<uint64_t, trace::TileResult>> tiles;
    {
        std::lock_guard<std::mutex> lock(arrivedMutex_);
        tiles.swap(arrived_);
    }
    bool any = false;
    for (auto& [id, t] : tiles) {
        if (id != job_) continue;  // from a cancelled request
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
        const int tx = tile.x0 / kTileSize, ty = tile.y0 / kTileSize;
        uint8_t& state = tileState_[size_t(ty) * size_t(tilesX_) + size_t(tx)];
        if (state == 0) ++tilesDone_;
        state = 255;
        tilesDirty_ = any = true;
    }
    if (any && tilesDone_ == tileTotal_) finished_ = std::chrono::steady_clock::now();
    if (tilesDirty_ && tiles_) {
        uploadTileMask(tiles_, tilesX_, tilesY_, tileState_.data());
        tilesDirty_ = false;
    }
    return any;
}

double ReferenceRenderer::seconds() const {
    if (job_ == 0) return 0.0;
    const auto end = complete() ? finished_ : std::chrono::steady_clock::now();
    return std::chrono::duration<double>(end - started_).count();
}

std::string ReferenceRenderer::error() const { return jobs_.error(); }

}  // namespace shadelab::app
