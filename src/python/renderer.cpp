// Renderer: the binary's render pipeline (cli/render_command.cpp) for many renders in one process: the same
// library calls with the same settings, the context and the rasterizer's programs made once.
#include "python/renderer.h"

#include "image/encode.h"
#include "python/gl_session.h"
#include "raster/offscreen.h"
#include "raster/raster_renderer.h"
#include "trace/path_render.h"
#include "trace/trace_image.h"
#include "trace/trace_scene.h"
#include "util/input_error.h"

#include <chrono>
#include <cmath>
#include <string>

namespace shadelab::python {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// What RasterRenderer::uploadMeshes reads: each mesh's parts' geometry, a null after each mesh (its draw ranges
// name (mesh, part)). Held, not only compared: a freed geometry's address could come back with other triangles.
std::vector<std::shared_ptr<const MeshGeometry>> geometryOf(const Scene& scene) {
    std::vector<std::shared_ptr<const MeshGeometry>> g;
    for (const Mesh& mesh : scene.meshes) {
        for (const MeshPart& part : mesh.parts) g.push_back(part.geometry);
        g.push_back(nullptr);
    }
    return g;
}

// A CPU tracer's linear image as an ImageData: the 8-bit conversion timed as the raster's readback is. `started`:
// when tracing began (drawMs runs from it).
ImageData fromTracer(ImageF color, std::vector<uint32_t> coverage, Encoding encoding, const char* source,
                     Clock::time_point started) {
    ImageData out;
    out.drawMs = msSince(started);
    const Clock::time_point t0 = Clock::now();
    out.pixels = toImage8(color, encoding);
    out.readMs = msSince(t0);
    out.linear = std::move(color);
    out.coverage = std::move(coverage);
    out.encoding = encoding;
    out.source = source;
    return out;
}

// Sets busy while a render runs.
struct BusyScope {
    explicit BusyScope(std::atomic<bool>& flag) : flag_(flag) { flag_ = true; }
    ~BusyScope() { flag_ = false; }
    std::atomic<bool>& flag_;
};

}  // namespace

void validate(const RenderRequest& r) {
    constexpr int kMaxSide = 16384;  // the binary's --size limit
    if (r.width < 1 || r.height < 1 || r.width > kMaxSide || r.height > kMaxSide)
        throw UsageError("size: each side must be 1..16384 pixels, got " + std::to_string(r.width) + "x" +
                         std::to_string(r.height));
    const int k = int(std::lround(std::sqrt(double(std::max(r.spp, 0)))));
    if (r.engine == Engine::Path && (r.spp < 1 || r.spp > 1 << 20))
        throw UsageError("spp: the path tracer takes 1 to 1048576 samples per pixel, got " + std::to_string(r.spp));
    if (r.engine != Engine::Path && (r.spp < 1 || r.spp > 64 || k * k != r.spp))
        throw UsageError("spp: expected a perfect square from 1 to 64 (1, 4, 9, 16, ...), got " +
                         std::to_string(r.spp));
    if (r.depth && (*r.depth < 0 || *r.depth > 64))
        throw UsageError("depth: must be in [0, 64], got " + std::to_string(*r.depth));
    if (r.threads < 0 || r.threads > 1024)
        throw UsageError("threads: must be in [0, 1024] (0 = every core), got " + std::to_string(r.threads));
}

Renderer::Renderer(gl::GlBackend backend) : backend_(backend) {}

Renderer::~Renderer() { close(); }

std::shared_ptr<GlSession> Renderer::session() {
    if (!session_) session_ = GlSession::acquire(backend_);
    return session_;
}

void Renderer::close() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (raster_) {
        // GL objects are deleted with the context current.
        session_->run([this] { raster_.reset(); });
        uploaded_.reset();
    }
    session_.reset();
}

gl::ContextInfo Renderer::contextInfo() {
    std::lock_guard<std::mutex> lock(mutex_);
    return session()->info();
}

ImageData Renderer::render(const Scene& scene, const RenderRequest& request) {
    validate(request);
    std::lock_guard<std::mutex> lock(mutex_);
    BusyScope busy(busy_);
    switch (request.engine) {
        case Engine::Raster: return rasterize(scene, request);
        case Engine::Path: return pathTrace(scene, request);
        case Engine::Trace: break;
    }
    return trace(scene, request);
}

ImageData Renderer::rasterize(const Scene& scene, const RenderRequest& request) {
    if (scene.lights.size() > size_t(kMaxLights))
        throw InputError("", "lights", "the rasterizer takes at most " + std::to_string(kMaxLights) + " lights");
    ImageData out;
    std::shared_ptr<GlSession> gl = session();
    gl->run([&] {
        if (!raster_) {
            raster_ = std::make_unique<raster::RasterRenderer>();
            uploaded_.reset();
        }
        std::vector<std::shared_ptr<const MeshGeometry>> geometry = geometryOf(scene);
        if (!uploaded_ || geometry != *uploaded_) {
            raster_->uploadMeshes(scene);
            uploaded_ = std::move(geometry);
        }
        raster::OffscreenOptions o;
        o.width = request.width;
        o.height = request.height;
        o.spp = request.spp;
        o.encoding = request.encoding;
        o.coverage = request.coverage;
        o.keepLinear = true;
        raster::OffscreenResult r = raster::renderOffscreen(*raster_, scene, o);
        out.linear = std::move(r.linear);
        out.pixels = std::move(r.pixels);
        out.coverage = std::move(r.coverage);
        out.drawMs = r.drawMs;
        out.readMs = r.readMs;
    });
    out.encoding = request.encoding;
    out.source = "raster";
    return out;
}

ImageData Renderer::trace(const Scene& scene, const RenderRequest& request) {
    trace::TraceSettings s;
    s.width = request.width;
    s.height = request.height;
    s.spp = request.spp;
    s.threads = request.threads;
    s.maxDepth = request.depth.value_or(scene.maxDepth);
    s.coverage = request.coverage;
    const Clock::time_point t0 = Clock::now();
    const trace::TraceScene prepared(scene, bvh_.get(scene));
    trace::TraceOutput traced = trace::traceImage(prepared, s);
    return fromTracer(std::move(traced.color), std::move(traced.coverage), request.encoding, "trace", t0);
}

// The path tracer as `shadelab render --renderer path` runs it (same settings, same bytes).
ImageData Renderer::pathTrace(const Scene& scene, const RenderRequest& request) {
    trace::PathSettings s;
    s.width = request.width;
    s.height = request.height;
    s.spp = request.spp;
    s.threads = request.threads;
    s.maxDepth = request.depth.value_or(scene.maxDepth);
    s.coverage = request.coverage;
    const Clock::time_point t0 = Clock::now();
    trace::PathOutput traced =
        trace::pathTraceImage(std::make_shared<const trace::TraceScene>(scene, bvh_.get(scene)), s);
    return fromTracer(std::move(traced.color), std::move(traced.coverage), request.encoding, "path", t0);
}

}  // namespace shadelab::python
