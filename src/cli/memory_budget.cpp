// Render memory estimate and the --max-memory check. Per-item costs measured on 2CylinderEngine and the
// default scene (bench/README.md), rounded up.
#include "cli/memory_budget.h"

#include "trace/accel/mesh_bvh.h"
#include "util/input_error.h"

#include <sys/resource.h>
#include <unistd.h>
#include <cmath>
#include <cstdlib>

namespace shadelab::cli {
namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;
constexpr uint64_t kTraceBytesPerTriangle =
    128;  // MeshBvh: 8-wide nodes, positions, ids (about 85 kept) and build scratch
// Spatial splits, on scenes small enough for them, add slots and their pass's scratch: peak RSS of a 2CylinderEngine
// render went from 30 to 36 MiB (+55 B per triangle), and the budget allows twice the slots that made.
constexpr uint64_t kSplitBytesPerTriangle = 128;
constexpr uint64_t kRasterBytesPerTriangle = 160;  // vertex and index buffers, the driver's copy included
// Per pixel. The rasterizer draws in bands, so only its 8-bit image and the PNG rows span the whole image
// (16384² measured 6.3 B/pixel); the tracer keeps float RGBA and coverage too (measured 18.6 B/pixel).
constexpr uint64_t kRasterBytesPerPixel = 4 + 4;          // 8-bit RGBA, PNG rows
constexpr uint64_t kTraceBytesPerPixel = 16 + 4 + 4 + 4;  // float RGBA, coverage, 8-bit RGBA, PNG rows

uint64_t triangles(const Scene& scene) {
    uint64_t n = 0;
    for (const Mesh& m : scene.meshes) n += m.triangleCount();
    return n;
}

}  // namespace

uint64_t defaultMaxMemory() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    uint64_t limit = pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) / 2 : uint64_t(4) << 30;
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
        limit = std::min(limit, uint64_t(as.rlim_cur) / 4 * 3);
    return limit;
}

uint64_t estimateRenderBytes(const Scene& scene, const RenderOptions& o) {
    const render::RenderRequest& r = o.request;
    const uint64_t pixels = uint64_t(r.width) * uint64_t(r.height);
    const bool raster = r.engine == render::Engine::Raster || r.engine == render::Engine::Both;
    const bool trace = r.engine != render::Engine::Raster;
    uint64_t bytes = 0;
    // The path tracer's per-pixel sums and squares (2 × 3 doubles) and sample count.
    if (r.engine == render::Engine::Path) bytes += pixels * (48 + 4);
    if (raster) bytes += pixels * kRasterBytesPerPixel + triangles(scene) * kRasterBytesPerTriangle;
    if (trace) {
        const uint64_t n = triangles(scene);
        bytes += pixels * kTraceBytesPerPixel + n * kTraceBytesPerTriangle;
        if (n <= trace::kMaxSpatialSplitTriangles) bytes += n * kSplitBytesPerTriangle;
    }
    if (raster && trace) bytes += pixels * (4 + 1 + 4 + 12);  // raster coverage, band mask, heatmap, side-by-side
    return bytes;
}

void checkMemoryBudget(const Scene& scene, const RenderOptions& o) {
    const uint64_t need = estimateRenderBytes(scene, o), limit = o.maxMemory ? o.maxMemory : defaultMaxMemory();
    if (need <= limit) return;
    throw InputError(o.input, "a " + std::to_string(o.request.width) + "x" + std::to_string(o.request.height) + " " +
                                  toString(o.request.engine) + " render of this scene needs about " +
                                  std::to_string(need / kMiB) + " MiB, over the limit of " +
                                  std::to_string(limit / kMiB) + " MiB (--max-memory)");
}

uint64_t parseMemorySize(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    std::string unit = end ? std::string(end) : std::string();
    double scale = double(kMiB);
    if (unit == "G" || unit == "g" || unit == "GiB")
        scale = double(kMiB) * 1024.0;
    else if (unit == "M" || unit == "m" || unit == "MiB" || unit.empty())
        scale = double(kMiB);
    else
        scale = 0.0;
    if (end == text.c_str() || !std::isfinite(v) || v <= 0.0 || scale == 0.0 || v * scale > 1e18)
        throw UsageError("--max-memory: expected a size such as 512M or 2G, got '" + text + "'");
    return uint64_t(v * scale);
}

}  // namespace shadelab::cli
