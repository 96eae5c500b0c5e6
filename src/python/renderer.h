// Renderer: many renders through one GL context (GlSession) and one RasterRenderer, whose programs, shadow maps and
// environment cubes stay warm between renders, plus the tracer with its mesh BVH kept while the geometry is the
// same. The same library calls as `shadelab render` (raster::renderOffscreen, trace::traceImage, toImage8), so the
// pixels are the binary's. Thread-safe: renders are serialised. Pure C++, no Python.
#pragma once

#include "gl/headless_context.h"
#include "image/encoding.h"
#include "python/image_data.h"
#include "scene/scene.h"
#include "trace/mesh_bvh_cache.h"
#include "util/name_table.h"

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

enum class Engine { Raster, Trace, Path };

// The words of render(renderer=...), as the binary's --renderer.
inline constexpr EnumName<Engine> kEngineNames[] = {
    {Engine::Raster, "raster"},
    {Engine::Trace, "trace"},
    {Engine::Path, "path"},
};

struct RenderRequest {
    int width = 1280, height = 720;  // pixels, 1..16384 each (the binary's --size)
    Engine engine = Engine::Raster;
    int spp = 1;                         // a perfect square k² from 1 to 64 (raster, trace); path: 1..1048576
    Encoding encoding = Encoding::Srgb;  // of the 8-bit pixels; the linear floats are kept either way
    std::optional<int> depth;            // tracer's secondary-ray depth; unset: the scene's maxDepth
    int threads = 0;                     // tracer workers; 0 = every core
    bool coverage = false;               // also return coverage ids
};

// Throws UsageError naming the argument (size, spp, depth, threads) when a request is out of range.
void validate(const RenderRequest& r);

class Renderer {
public:
    explicit Renderer(gl::GlBackend backend = gl::GlBackend::Auto);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders; the GL context is created by the first raster render. Throws InputError, UsageError,
    // gl::ContextError.
    ImageData render(const Scene& scene, const RenderRequest& request);

    // The GL context's backend, device and strings (creating the context when there is none yet).
    gl::ContextInfo contextInfo();

    // Frees the GL objects and drops this renderer's share of the context; a later render starts again.
    void close();

    // True while a render runs (read without any lock: the Python tests watch it from another thread).
    bool busy() const { return busy_.load(); }

private:
    std::shared_ptr<GlSession> session();  // under mutex_
    ImageData rasterize(const Scene& scene, const RenderRequest& request);
    ImageData trace(const Scene& scene, const RenderRequest& request);
    ImageData pathTrace(const Scene& scene, const RenderRequest& request);

    std::mutex mutex_;
    gl::GlBackend backend_;
    std::shared_ptr<GlSession> session_;
    std::unique_ptr<raster::RasterRenderer> raster_;
    std::optional<std::vector<std::shared_ptr<const MeshGeometry>>> uploaded_;  // what raster_ holds; unset: none
    trace::MeshBvhCache bvh_;
    std::atomic<bool> busy_{false};
};

}  // namespace shadelab::python
