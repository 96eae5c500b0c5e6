// Renderer: the binary's render pipeline (cli/render_command.cpp) for many renders in one process: the same
// library calls with the same settings, the context and the rasterizer's programs made once.
#include "python/renderer.h"

#include "image/encode.h"
#include "python/gl_session.h"
#include "raster/offscreen.h"
#include "raster/raster_renderer.h"
#include "render/memory_budget.h"
#include "trace/path/path_render.h"
#include "trace/trace_image.h"
#include "trace/trace_scene.h"
#include "util/input_error.h"

#include <chrono>
#include <cmath>
#include <optional>
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
ImageData fromTracer(ImageF color, std::vector<uint32_t> coverage, Encoding encoding, const DisplaySettings& display,
                     const char* source, Clock::time_point started) {
    ImageData out;
    out.drawMs = msSince(started);
    const Clock::time_point t0 = Clock::now();
    out.pixels = toImage8(color, encoding, display, &out.nonFinite);
    out.readMs = msSince(t0);
    out.linear = std::move(color);
    out.coverage = std::move(coverage);
    out.encoding = encoding;
    out.display = display;
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

void validate(const render::RenderRequest& r) {
    if (r.engine == render::Engine::Both)
        throw UsageError(
            "renderer: 'both' is the command line's side-by-side picture; render raster and trace and compare them "
            "with shadelab.compare");
    if (std::optional<render::RequestProblem> p = render::check(r)) throw UsageError(p->field + ": " + p->reason);
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

ImageData Renderer::render(const Scene& scene, const render::RenderRequest& request) {
    validate(request);
    // Before any pixel, as the command line's --max-memory; Python keeps the linear floats (RenderOutput::Image).
    if (std::optional<std::string> over = render::memoryProblem(scene, request, render::RenderOutput::Image))
        throw InputError("", *over + " (max_memory)");
    std::lock_guard<std::mutex> lock(mutex_);
    BusyScope busy(busy_);
    try {
        switch (request.engine) {
            case render::Engine::Raster: return rasterize(scene, request);
            case render::Engine::Path: return pathTrace(scene, request);
            case render::Engine::Trace:
            case render::Engine::Both: break;
        }
        return trace(scene, request);
    } catch (const SettingError& e) {
        throw UsageError(e.what());  // a limit only a renderer knows (the GL's widest target), by keyword
    }
}

ImageData Renderer::rasterize(const Scene& scene, const render::RenderRequest& request) {
    if (scene.lights.size() > size_t(kMaxLights))
        throw InputError("", "lights", "the rasterizer takes at most " + std::to_string(kMaxLights) + " lights");
    ImageData out;
    std::shared_ptr<GlSession> gl = session();
    gl->run([&] {
        if (!raster_) {
            // Each program compiled by the first render that needs it (a shader error surfaces there).
            raster_ = std::make_unique<raster::RasterRenderer>(gl::ShaderLibrary(), raster::ProgramCheck::OnFirstUse);
            raster_->setTriangleBatches(true);  // one image per call, as the CLI's render
            uploaded_.reset();
        }
        std::vector<std::shared_ptr<const MeshGeometry>> geometry = geometryOf(scene);
        if (!uploaded_ || geometry != *uploaded_) {
            raster_->uploadMeshes(scene);
            uploaded_ = std::move(geometry);
        }
        raster::OffscreenOptions o = render::toOffscreen(request, scene);
        o.keepLinear = true;
        raster::OffscreenResult r = raster::renderOffscreen(*raster_, scene, o);
        out.linear = std::move(r.linear);
        out.pixels = std::move(r.pixels);
        out.nonFinite = r.nonFinite;
        out.coverage = std::move(r.coverage);
        out.drawMs = r.drawMs;
        out.readMs = r.readMs;
    });
    out.encoding = request.encoding;
    out.display = render::displayOf(request, scene);
    out.source = "raster";
    return out;
}

ImageData Renderer::trace(const Scene& scene, const render::RenderRequest& request) {
    const trace::TraceSettings s = render::toTrace(request, scene);
    const Clock::time_point t0 = Clock::now();
    const trace::TraceScene prepared(scene, bvh_.get(scene));
    trace::TraceOutput traced = trace::traceImage(prepared, s);
    return fromTracer(std::move(traced.color), std::move(traced.coverage), request.encoding,
                      render::displayOf(request, scene), "trace", t0);
}

// The path tracer as `shadelab render --renderer path` runs it (same settings, same bytes).
ImageData Renderer::pathTrace(const Scene& scene, const render::RenderRequest& request) {
    const trace::PathSettings s = render::toPath(request, scene);
    const Clock::time_point t0 = Clock::now();
    trace::PathOutput traced =
        trace::pathTraceImage(std::make_shared<const trace::TraceScene>(scene, bvh_.get(scene)), s);
    return fromTracer(std::move(traced.color), std::move(traced.coverage), request.encoding,
                      render::displayOf(request, scene), "path", t0);
}

}  // namespace shadelab::python
