// PathPassWork: the Global modes' passes on the controller thread.
#include "app/path_pass_work.h"

#include "image/encode.h"
#include "trace/path/path_denoise.h"

#include <algorithm>
#include <chrono>

namespace shadelab::app {
namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

void PathPassWork::start(const BackgroundJob& job) {
    stop();
    scene_ = std::make_shared<const trace::TraceScene>(job.scene, meshes_.get(job.scene));
    trace::PathSettings settings = render::toPath(job.request, job.scene);
    settings.tileSize = kTileSize;
    render_ = std::make_unique<trace::PathRender>(scene_, settings);
    running_ = job.id;
    threads_ = job.request.threads;
}

void PathPassWork::stop() {
    render_.reset();
    guides_.reset();
    running_ = 0;
    passProgress_ = 0.0f;
}

void PathPassWork::step(const std::atomic<bool>& cancel) {
    passProgress_ = 0.0f;
    const bool first = render_->samples() == 0;
    const double passStart = now();
    double published = passStart;
    const bool finished = render_->addSamples(1, &cancel, [&](float f) {
        // The first pass shows its finished tiles as they come (the pass reads only pixels it is done with and
        // the workers write only others: a tile is published once all its pixels have their sample).
        passProgress_ = f;
        if (!first || now() - published <= 0.3) return;
        Pass partial = snapshot(running_, *render_);
        // Tiles only, even when the last pixel is done: the whole pass, with its denoised preview, follows,
        // and only it may count as a sample (waitReference, screenshots).
        partial.samples = 0;
        partial.noise8 = 0.0;
        publish(std::move(partial));
        published = now();
    });
    if (!finished) return;  // a new job (or quit) arrived mid-pass
    Pass pass = snapshot(running_, *render_);
    tracing_ += now() - passStart;
    if (first || render_->samples() >= kMaxSamples || denoising_ <= kDenoiseShare * tracing_) {
        const double start = now();
        if (!guides_) guides_ = trace::firstHitPasses(*scene_, render_->width(), render_->height(), threads_);
        DenoiseSettings d;
        d.threads = threads_;
        pass.denoised = trace::denoisedImage(*render_, *guides_, d);
        pass.denoisedSamples = pass.samples;
        denoising_ = now() - start;
        tracing_ = 0.0;
    }
    publish(std::move(pass));
}

void PathPassWork::publish(Pass pass) {
    std::lock_guard<std::mutex> lock(arrivedMutex_);
    // A pass the window has not taken yet is replaced, but not its denoised preview when the new pass has none:
    // on a busy machine the first pass (always denoised) could otherwise be overwritten by the second before the
    // window saw it, and the window would show the raw estimate while it should show the preview.
    if (arrived_ && arrived_->job == pass.job && arrived_->denoisedSamples > 0 && pass.denoisedSamples == 0) {
        pass.denoised = std::move(arrived_->denoised);
        pass.denoisedSamples = arrived_->denoisedSamples;
    }
    arrived_ = std::move(pass);
}

std::optional<PathPassWork::Pass> PathPassWork::takeArrived() {
    std::optional<Pass> pass;
    std::lock_guard<std::mutex> lock(arrivedMutex_);
    pass.swap(arrived_);
    return pass;
}

void PathPassWork::dropArrived() {
    std::lock_guard<std::mutex> lock(arrivedMutex_);
    arrived_.reset();
}

PathPassWork::Pass PathPassWork::snapshot(uint64_t job, const trace::PathRender& render) {
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

}  // namespace shadelab::app
