// WorkerTracer: the scene rebuilt from JSON, then the same render request as the native front ends.
#include "worker_tracer.h"

#include "render/render_request.h"
#include "scene/scene_load.h"
#include "util/atomic_file.h"

#include <stdexcept>

namespace shadelab::web {
namespace {

// The worker's copy of the page's scene: its JSON written beside the file it came from, in this worker's own
// in-memory file system, and loaded as any scene file is (models, environment map, limits), so that relative
// paths resolve as they did in the page.
Scene sceneFrom(const std::string& sceneJson, const std::string& baseDir) {
    const std::string path = (baseDir.empty() ? std::string(".") : baseDir) + "/.page-scene.json";
    writeFileAtomic(path, sceneJson);
    return loadScene(path);
}

render::RenderRequest requestOf(render::Engine engine, int width, int height) {
    render::RenderRequest request;
    request.engine = engine;
    request.width = width;
    request.height = height;
    request.threads = 1;  // this worker; the page runs several
    request.coverage = engine == render::Engine::Trace;
    render::require(request);
    return request;
}

}  // namespace

WorkerTracer::WorkerTracer(const std::string& sceneJson, const std::string& baseDir)
    : scene_(std::make_shared<const trace::TraceScene>(sceneFrom(sceneJson, baseDir))) {}

int WorkerTracer::startReference(int width, int height) {
    const render::RenderRequest request = requestOf(render::Engine::Trace, width, height);
    const trace::TraceSettings settings = render::toTrace(request, scene_->scene());
    encoding_ = request.encoding;
    display_ = render::displayOf(request, scene_->scene());
    trace::validate(settings);
    job_ = std::make_unique<trace::TraceJob>(*scene_, settings);
    clearBatch();  // tiles of a job this one replaces
    return int(job_->tiles.size());
}

int WorkerTracer::traceTile(int index) {
    if (!job_ || index < 0 || index >= int(job_->tiles.size())) throw std::out_of_range("no such tile");
    job_->render(index, tile_);
    const trace::Tile& t = tile_.tile;
    batch_.tiles.insert(batch_.tiles.end(), {index, t.x0, t.y0, t.width, t.height});
    const size_t at = batch_.rgb.size();
    batch_.rgb.resize(at + size_t(t.width) * size_t(t.height) * 3);
    uint64_t nonFinite = 0;  // written black or white, as natively; the page does not count them
    encodeRgbaRows(tile_.rgba.data(), size_t(t.width) * 4, &batch_.rgb[at], size_t(t.width) * 3, t.width, t.height,
                   encoding_, display_, &nonFinite);
    batch_.coverage.insert(batch_.coverage.end(), tile_.coverage.begin(), tile_.coverage.end());
    return int(batch_.tiles.size() / 5);
}

void WorkerTracer::clearBatch() {
    batch_.tiles.clear();
    batch_.rgb.clear();
    batch_.coverage.clear();
}

void WorkerTracer::startGlobal(int width, int height) {
    path_ = std::make_unique<trace::PathRender>(
        scene_, render::toPath(requestOf(render::Engine::Path, width, height), scene_->scene()));
}

void WorkerTracer::addGlobalSamples(int count) {
    if (path_) path_->addSamples(count);
}

ImageF WorkerTracer::globalImage() const { return path_ ? path_->image() : ImageF(); }

void WorkerTracer::addGlobalRowSamples(int count, int first, int step) {
    if (path_) path_->addSamplesToRows(count, first, step);
}

std::vector<float> WorkerTracer::globalRows(int first, int step) const {
    std::vector<float> out;
    if (!path_ || step <= 0 || first < 0) return out;
    const int width = path_->width();
    for (int y = first; y < path_->height(); y += step)
        for (int x = 0; x < width; ++x) {
            const glm::vec3 m = path_->mean(x, y);
            out.insert(out.end(), {m.r, m.g, m.b, 1.0f});
        }
    return out;
}

}  // namespace shadelab::web
