// Renderer: many renders through one GL context (GlSession) and one RasterRenderer, whose programs, shadow maps and
// environment cubes stay warm between renders, plus the tracer with its mesh BVH kept while the geometry is the
// same. The same request (render/render_request.h) and library calls as `shadelab render` (raster::renderOffscreen,
// trace::traceImage, toImage8), so the pixels are the binary's. Thread-safe: renders are serialised. Pure C++, no
// Python.
#pragma once

#include "gl/headless_context.h"
#include "python/image_data.h"
#include "render/render_request.h"
#include "scene/scene.h"
#include "trace/accel/mesh_bvh_cache.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace shadelab::raster {
class RasterRenderer;
}

namespace shadelab::python {

class GlSession;

// The request's problem as Python words it: UsageError "<keyword>: <reason>" (the keyword is the request's
// field: size, spp, depth, threads, time_limit, estimator, light_paths, sampler, max_memory). Also refuses
// Engine::Both, which is the command line's side-by-side picture; Python compares two renders with
// shadelab.compare.
void validate(const render::RenderRequest& r);

class Renderer {
public:
    explicit Renderer(gl::GlBackend backend = gl::GlBackend::Auto);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders; the GL context is created by the first raster render. Throws InputError (also for a render
    // estimated to need more than the request's memory limit, render/memory_budget.h), UsageError,
    // gl::ContextError.
    ImageData render(const Scene& scene, const render::RenderRequest& request);

    // The GL context's backend, device and strings (creating the context when there is none yet).
    gl::ContextInfo contextInfo();

    // Frees the GL objects and drops this renderer's share of the context; a later render starts again.
    void close();

    // True while a render runs (read without any lock: the Python tests watch it from another thread).
    bool busy() const { return busy_.load(); }

private:
    std::shared_ptr<GlSession> session();  // under mutex_
    ImageData rasterize(const Scene& scene, const render::RenderRequest& request);
    ImageData trace(const Scene& scene, const render::RenderRequest& request);
    ImageData pathTrace(const Scene& scene, const render::RenderRequest& request);

    std::mutex mutex_;
    gl::GlBackend backend_;
    std::shared_ptr<GlSession> session_;
    std::unique_ptr<raster::RasterRenderer> raster_;
    std::optional<std::vector<std::shared_ptr<const MeshGeometry>>> uploaded_;  // what raster_ holds; unset: none
    trace::MeshBvhCache bvh_;
    std::atomic<bool> busy_{false};
};

}  // namespace shadelab::python
