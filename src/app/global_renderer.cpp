// GlobalRenderer: the controller thread (owns the PathRender, one pass at a time) and the UI-side upload.
#include "app/global_renderer.h"

#include "app/idle_priority.h"
#include "image/encode.h"
#include "trace/path/path_render.h"
#include "trace/trace_scene.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>

namespace shadelab::app {
namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

GlobalRenderer::GlobalRenderer(trace::MeshBvhCache& meshes) : meshes_(meshes) {
    threads_ = std::max(1, int(std::thread::hardware_concurrency()) - 1);
    controller_ = std::thread([this] { controllerLoop(); });
}

GlobalRenderer::~GlobalRenderer() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quit_ = true;
    }
    cancel_ = true;
    wake_.notify_all();
    controller_.join();
}

void GlobalRenderer::controllerLoop() {
    lowerToIdlePriority();  // inherited by the pass workers
    std::unique_ptr<trace::PathRender> render;
    uint64_t running = 0;
    for (;;) {
        std::optional<Job> job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            const bool more = render && render->samples() < kMaxSamples;
            if (!more) wake_.wait(lock, [&] { return quit_ || pending_ || pauseRequested_; });
            if (quit_) break;
            if (pauseRequested_) {
                pauseRequested_ = false;
                render.reset();
                running = 0;
                continue;
            }
            job = std::move(pending_);
            pending_.reset();
            if (job) cancel_ = false;
            passProgress_ = 0.0f;
        }
        if (job) {
            try {
                auto scene = std::make_shared<const trace::TraceScene>(job->scene, meshes_.get(job->scene));
                trace::PathSettings settings = render::toPath(job->request, job->scene);
                settings.tileSize = kTileSize;
                render = std::make_unique<trace::PathRender>(scene, settings);
                running = job->id;
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(mutex_);
                error_ = e.what();
                render.reset();
                continue;
            }
        }
        if (!render) continue;
        const bool first = render->samples() == 0;
        double published = now();
        const bool finished = render->addSamples(1, &cancel_, [&](float f) {
            // The first pass shows its finished tiles as they come (the pass reads only pixels it is done with
            // and the workers write only others: a tile is published once all its pixels have their sample).
            Pass partial;
            if (first && now() - published > 0.3) {
                partial = snapshot(running, *render);
                published = now();
            }
            std::lock_guard<std::mutex> lock(mutex_);
            passProgress_ = f;
            if (partial.job) arrived_ = std::move(partial);
        });
        if (!finished) continue;  // a new request (or quit) arrived mid-pass
        Pass pass = snapshot(running, *render);
        std::lock_guard<std::mutex> lock(mutex_);
        arrived_ = std::move(pass);
    }
}

GlobalRenderer::Pass GlobalRenderer::snapshot(uint64_t job, const trace::PathRender& render) {
    Pass pass;
    pass.job = job;
    pass.samples = render.samples();
    const int w = render.width(), h = render.height();
    const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
    pass.tiles.assign(size_t(tilesX) * size_t(tilesY), 0);
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx) {
            // A tile's pixels are rendered in row order: its last pixel done means all are.
            const int x = std::min(w, (tx + 1) * kTileSize) - 1, y = std::min(h, (ty + 1) * kTileSize) - 1;
            if (render.pixelSamples(x, y) > 0) pass.tiles[size_t(ty) * size_t(tilesX) + size_t(tx)] = 255;
        }
    pass.image = ImageF(w, h);
    pass.standardError.assign(size_t(w) * size_t(h), glm::vec3(0.0f));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (pass.tiles[size_t(y / kTileSize) * size_t(tilesX) + size_t(x / kTileSize)] == 0) continue;
            const glm::vec3 m = render.mean(x, y);
            float* p = pass.image.pixel(x, y);
            p[0] = m.x;
            p[1] = m.y;
            p[2] = m.z;
            p[3] = 1.0f;
            pass.standardError[size_t(y) * size_t(w) + size_t(x)] = render.standardError(x, y);
        }
    if (pass.samples > 0) pass.noise8 = render.meanStandardError8(Encoding::Srgb);
    return pass;
}

void GlobalRenderer::request(const Scene& scene, int width, int height, uint64_t revision, trace::PathPart part) {
    if (width <= 0 || height <= 0) return;
    if (job_ != 0 && revision == revision_ && width == width_ && height == height_ && part == part_) return;
    if (width != width_ || height != height_ || !color_) {
        width_ = width;
        height_ = height;
        color_ = gl::Texture::create();
        glBindTexture(GL_TEXTURE_2D, color_.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        done_ = gl::Texture::create();
        glBindTexture(GL_TEXTURE_2D, done_.id());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    // Until the first tiles of this request arrive, the display shows the raster image (tile test 0).
    tilesX_ = (width + kTileSize - 1) / kTileSize;
    tilesY_ = (height + kTileSize - 1) / kTileSize;
    uploadTiles(std::vector<uint8_t>(size_t(tilesX_) * size_t(tilesY_), 0));
    revision_ = revision;
    part_ = part;
    samples_ = 0;
    noise8_ = 0.0;
    job_ = nextJob_++;
    started_ = now();
    cancel_ = true;  // before the job is posted: the controller clears it when it takes the job
    {
        std::lock_guard<std::mutex> lock(mutex_);
        render::RenderRequest r;
        r.engine = render::Engine::Path;
        r.width = width;
        r.height = height;
        r.threads = threads_;
        r.path.part = part;
        pending_ = Job{job_, scene, r};
        arrived_.reset();
        error_.clear();
    }
    wake_.notify_all();
}

void GlobalRenderer::pause() {
    if (job_ == 0) return;
    job_ = 0;
    samples_ = 0;
    cancel_ = true;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        pending_.reset();
        arrived_.reset();
        pauseRequested_ = true;
    }
    wake_.notify_all();
}

bool GlobalRenderer::update() {
    std::optional<Pass> pass;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        pass.swap(arrived_);
    }
    if (!pass || pass->job != job_ || pass->image.width != width_ || pass->image.height != height_) return false;
    samples_ = pass->samples;
    noise8_ = pass->noise8;
    image_ = std::move(pass->image);
    standardError_ = std::move(pass->standardError);
    // GL row order, as the raster target.
    const size_t rowFloats = size_t(width_) * 4;
    flipped_.resize(image_.rgba.size());
    for (int row = 0; row < height_; ++row)
        std::memcpy(&flipped_[size_t(height_ - 1 - row) * rowFloats], &image_.rgba[size_t(row) * rowFloats],
                    rowFloats * sizeof(float));
    glBindTexture(GL_TEXTURE_2D, color_.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, flipped_.data());
    uploadTiles(pass->tiles);
    return true;
}

void GlobalRenderer::uploadTiles(const std::vector<uint8_t>& tiles) {
    if (tiles.size() != size_t(tilesX_) * size_t(tilesY_)) return;
    glBindTexture(GL_TEXTURE_2D, done_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, tilesX_, tilesY_, 0, GL_RED, GL_UNSIGNED_BYTE, tiles.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}

float GlobalRenderer::passProgress() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return passProgress_;
}

double GlobalRenderer::seconds() const { return job_ == 0 ? 0.0 : now() - started_; }

std::string GlobalRenderer::error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
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
