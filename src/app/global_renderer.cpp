// GlobalRenderer: the controller thread (owns the PathRender, one pass at a time) and the UI-side upload.
#include "app/global_renderer.h"

#include "app/background_textures.h"
#include "app/idle_priority.h"
#include "image/encode.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_denoise.h"
#include "trace/path/path_render.h"
#include "trace/trace_scene.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>

namespace shadelab::app {
namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

GlobalRenderer::GlobalRenderer(trace::MeshBvhCache& meshes)
    : meshes_(meshes), threads_(backgroundWorkerCount()), controller_([this] { controllerLoop(); }) {}

GlobalRenderer::~GlobalRenderer() {
    jobs_.quit();
    cancel_ = true;
    controller_.join();
}

void GlobalRenderer::controllerLoop() {
    lowerToIdlePriority();  // inherited by the pass workers
    std::unique_ptr<trace::PathRender> render;
    std::shared_ptr<const trace::TraceScene> scene;
    std::optional<SurfacePasses> guides;  // the denoiser's, computed after the first pass of each request
    uint64_t running = 0;
    double tracing = 0.0, denoising = 0.0;  // seconds since the last denoised preview, and what it took
    for (;;) {
        std::optional<Job> job;
        const bool more = render && render->samples() < kMaxSamples;
        // Taking a job clears the cancel flag under the hand-off's lock, so a request posted after it cancels.
        const auto event = jobs_.take(!more, job, [&](bool gotJob) {
            if (gotJob) cancel_ = false;
            passProgress_ = 0.0f;
        });
        if (event == JobHandOff<Job>::Event::Quit) break;
        if (event == JobHandOff<Job>::Event::Pause) {
            render.reset();
            running = 0;
            continue;
        }
        if (job) {
            try {
                scene = std::make_shared<const trace::TraceScene>(job->scene, meshes_.get(job->scene));
                trace::PathSettings settings = render::toPath(job->request, job->scene);
                settings.tileSize = kTileSize;
                render = std::make_unique<trace::PathRender>(scene, settings);
                guides.reset();
                running = job->id;
            } catch (const std::exception& e) {
                jobs_.fail(e.what());
                render.reset();
                continue;
            }
        }
        if (!render) continue;
        const bool first = render->samples() == 0;
        const double passStart = now();
        double published = passStart;
        const bool finished = render->addSamples(1, &cancel_, [&](float f) {
            // The first pass shows its finished tiles as they come (the pass reads only pixels it is done with
            // and the workers write only others: a tile is published once all its pixels have their sample).
            Pass partial;
            if (first && now() - published > 0.3) {
                partial = snapshot(running, *render);
                // Tiles only, even when the last pixel is done: the whole pass, with its denoised preview,
                // follows, and only it may count as a sample (waitReference, screenshots).
                partial.samples = 0;
                partial.noise8 = 0.0;
                partial.denoised = ImageF();
                published = now();
            }
            passProgress_ = f;
            std::lock_guard<std::mutex> lock(arrivedMutex_);
            if (partial.job) arrived_ = std::move(partial);
        });
        if (!finished) continue;  // a new request (or quit) arrived mid-pass
        Pass pass = snapshot(running, *render);
        tracing += now() - passStart;
        if (first || render->samples() >= kMaxSamples || denoising <= kDenoiseShare * tracing) {
            const double start = now();
            if (!guides) guides = trace::firstHitPasses(*scene, render->width(), render->height(), threads_);
            DenoiseSettings d;
            d.threads = threads_;
            pass.denoised = trace::denoisedImage(*render, *guides, d);
            denoising = now() - start;
            tracing = 0.0;
        }
        std::lock_guard<std::mutex> lock(arrivedMutex_);
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
        color_ = makeImageTexture(width, height);
        denoised_ = makeImageTexture(width, height);
        done_ = makeTileTexture();
    }
    // Until the first tiles of this request arrive, the display shows the raster image (tile test 0).
    tilesX_ = (width + kTileSize - 1) / kTileSize;
    tilesY_ = (height + kTileSize - 1) / kTileSize;
    uploadTiles(std::vector<uint8_t>(size_t(tilesX_) * size_t(tilesY_), 0));
    revision_ = revision;
    part_ = part;
    samples_ = 0;
    denoisedSamples_ = 0;
    noise8_ = 0.0;
    job_ = nextJob_++;
    started_ = now();
    cancel_ = true;  // before the job is posted: the controller clears it when it takes the job
    {
        std::lock_guard<std::mutex> lock(arrivedMutex_);
        arrived_.reset();
    }
    render::RenderRequest r;
    r.engine = render::Engine::Path;
    r.width = width;
    r.height = height;
    r.threads = threads_;
    r.path.part = part;
    jobs_.post(Job{job_, scene, r});
}

void GlobalRenderer::pause() {
    if (job_ == 0) return;
    job_ = 0;
    samples_ = 0;
    denoisedSamples_ = 0;
    cancel_ = true;
    {
        std::lock_guard<std::mutex> lock(arrivedMutex_);
        arrived_.reset();
    }
    jobs_.pause();
}

bool GlobalRenderer::update() {
    std::optional<Pass> pass;
    {
        std::lock_guard<std::mutex> lock(arrivedMutex_);
        pass.swap(arrived_);
    }
    if (!pass || pass->job != job_ || pass->image.width != width_ || pass->image.height != height_) return false;
    samples_ = pass->samples;
    noise8_ = pass->noise8;
    image_ = std::move(pass->image);
    standardError_ = std::move(pass->standardError);
    // GL row order, as the raster target.
    uploadRowsFlipped(color_, 0, 0, width_, height_, height_, image_.rgba.data(), flipped_);
    uploadTiles(pass->tiles);
    if (pass->denoised.width == width_ && pass->denoised.height == height_) {
        denoisedSamples_ = samples_;
        denoisedImage_ = std::move(pass->denoised);
        uploadRowsFlipped(denoised_, 0, 0, width_, height_, height_, denoisedImage_.rgba.data(), flipped_);
    }
    return true;
}

void GlobalRenderer::uploadTiles(const std::vector<uint8_t>& tiles) {
    if (tiles.size() != size_t(tilesX_) * size_t(tilesY_)) return;
    uploadTileMask(done_, tilesX_, tilesY_, tiles.data());
}

float GlobalRenderer::passProgress() const { return passProgress_; }

double GlobalRenderer::seconds() const { return job_ == 0 ? 0.0 : now() - started_; }

std::string GlobalRenderer::error() const { return jobs_.error(); }

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
