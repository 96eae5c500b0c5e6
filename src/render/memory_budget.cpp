// Render memory estimate and its limit. Per-item costs measured with `/usr/bin/time -f %M` on the shipped scenes
// and 2CylinderEngine (bench/README.md), rounded up.
#include "render/memory_budget.h"

#include "raster/raster_limits.h"
#include "raster/shadow_fit.h"
#include "scene/sample_grid.h"
#include "scene/scene_load.h"
#include "trace/accel/mesh_bvh.h"
#include "util/heap_warmup.h"
#include "util/input_error.h"

#include <sys/resource.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

namespace shadelab::render {
namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;
// The process around any render: the program and its libraries, the tracer's threads (measured 8.3 to 8.5 MiB
// for a 1x1 trace of the default scene since OpenEXR's libraries are linked, 7 MiB before).
constexpr uint64_t kProcessBytes = 10 * kMiB;
// A headless GL context with the rasterizer's programs compiled: a 1x1 raster render without shadow maps
// peaks at 92 to 107 MiB on llvmpipe (its JIT and its shader cache) before any image is counted.
constexpr uint64_t kGlContextBytes = 104 * kMiB;
// Of that, what llvmpipe (Mesa 22.3, LLVM 15) takes from the creating thread's heap while the context starts
// and its first programs compile: the heap grew 24.5 to 26 MiB beyond the render's images (strace of brk
// while rendering 2CylinderEngine at three sizes, with HeapWarmup's malloc settings).
constexpr uint64_t kSoftwareContextHeapBytes = 24 * kMiB;
constexpr uint64_t kTraceBytesPerTriangle =
    128;  // MeshBvh: 8-wide nodes, positions, ids (about 85 kept) and build scratch
// Spatial splits, on scenes small enough for them, add slots and their pass's scratch: peak RSS of a 2CylinderEngine
// render went from 30 to 36 MiB (+55 B per triangle), and the budget allows twice the slots that made.
constexpr uint64_t kSplitBytesPerTriangle = 128;
constexpr uint64_t kRasterBytesPerTriangle = 160;  // vertex and index buffers, the driver's copy included
// Per pixel. The rasterizer draws in bands, so only its 8-bit image and the PNG rows span the whole image
// (16384² measured 6.3 B/pixel); Python keeps the linear floats too. The tracer keeps float RGBA and coverage
// too (measured 18.6 B/pixel).
constexpr uint64_t kRasterPngBytesPerPixel = 4 + 4;       // 8-bit RGBA, PNG rows
constexpr uint64_t kRasterImageBytesPerPixel = 16 + 4;    // float RGBA kept, 8-bit
constexpr uint64_t kTraceBytesPerPixel = 16 + 4 + 4 + 4;  // float RGBA, coverage, 8-bit RGBA, PNG rows
constexpr uint64_t kPathBytesPerPixel = 48 + 4;           // the sums and squares (2 × 3 doubles), sample count
constexpr uint64_t kBothBytesPerPixel = 4 + 1 + 4 + 12;   // raster coverage, band mask, heatmap, side-by-side
// The rasterizer's band: per sample, RGBA32F colour, 32-bit depth, coverage ids when asked for, and the float
// readback; each mirror plane adds a target of colour and depth.
constexpr uint64_t kBandBytesPerSample = 16 + 4 + 16;
constexpr uint64_t kMirrorBytesPerSample = 16 + 4;
constexpr uint64_t kCubeBytesPerTexel = 8 + 4;  // RGBA16F colour and depth, per face texel

bool rasterizes(const RenderRequest& r) { return r.engine == Engine::Raster || r.engine == Engine::Both; }
bool traces(const RenderRequest& r) { return r.engine != Engine::Raster; }

uint64_t pixelsOf(const RenderRequest& r) { return uint64_t(r.width) * uint64_t(r.height); }

// The samples of the rasterizer's largest band (raster/offscreen.cpp: whole output rows, near the float target
// budget) at k x k samples per pixel.
uint64_t bandSamples(const RenderRequest& r) {
    const raster::OffscreenOptions o;  // the budget every front end renders with
    const uint64_t k = uint64_t(gridSamplesPerSide(r.samples()));
    const uint64_t rowSamples = uint64_t(r.width) * k * k;  // one output row
    const uint64_t budget = o.maxTargetBytes / 16;
    return std::min(pixelsOf(r) * k * k, std::max(rowSamples, (budget / rowSamples + 1) * rowSamples));
}

// The images and fixed costs of the request, with the 8-bit output as `output` keeps it.
uint64_t requestBytes(const RenderRequest& r, RenderOutput output) {
    const uint64_t pixels = pixelsOf(r);
    uint64_t bytes = kProcessBytes;
    if (rasterizes(r)) {
        bytes += kGlContextBytes;
        bytes += pixels * (output == RenderOutput::Image && r.engine == Engine::Raster ? kRasterImageBytesPerPixel
                                                                                       : kRasterPngBytesPerPixel);
        if (r.coverage && r.engine == Engine::Raster) bytes += pixels * 4;  // the ids (Both: kBothBytesPerPixel)
        bytes += bandSamples(r) * (kBandBytesPerSample + (r.coverage || r.engine == Engine::Both ? 4 : 0));
    }
    if (traces(r)) bytes += pixels * kTraceBytesPerPixel;
    if (r.engine == Engine::Path) bytes += pixels * kPathBytesPerPixel;
    if (r.engine == Engine::Both) bytes += pixels * kBothBytesPerPixel;
    return bytes;
}

// A block's bytes if the heap serves it, else 0.
uint64_t heapBlock(uint64_t bytes) { return bytes <= kHeapWarmupLargestBlock ? bytes : 0; }

uint64_t triangles(const Scene& scene) {
    uint64_t n = 0;
    for (const Mesh& m : scene.meshes) n += m.triangleCount();
    return n;
}

bool reflective(const Material& m) { return m.kr.x > 0.0f || m.kr.y > 0.0f || m.kr.z > 0.0f; }

// What the loaded scene itself holds: its meshes' geometry and textures and the prefiltered environment map
// (each shared one once). Counted too, so that the estimate is the process's, as a limit on it is meant.
uint64_t loadedSceneBytes(const Scene& scene) {
    uint64_t bytes = 0;
    std::set<const void*> seen;
    const auto once = [&seen](const void* p) { return p && seen.insert(p).second; };
    for (const Mesh& mesh : scene.meshes)
        for (const MeshPart& part : mesh.parts) {
            if (const MeshGeometry* g = part.geometry.get(); once(g))
                bytes += g->positions.size() * sizeof(glm::vec3) + g->normals.size() * sizeof(glm::vec3) +
                         g->texcoords0.size() * sizeof(glm::vec2) + g->texcoords1.size() * sizeof(glm::vec2) +
                         g->tangents.size() * sizeof(glm::vec4) + g->indices.size() * sizeof(uint32_t);
            for (const TextureBinding* b :
                 {&part.material.baseColorTexture, &part.material.metallicRoughnessTexture,
                  &part.material.normalTexture, &part.material.occlusionTexture, &part.material.emissiveTexture})
                if (once(b->texture.get())) bytes += b->texture->texelBytes();
        }
    if (scene.environment && once(scene.environment->map.get())) bytes += scene.environment->map->atlas.size() * 4;
    return bytes;
}

// What the rasterizer allocates for this scene: mesh buffers, textures (the driver's copy), shadow maps,
// reflection cubes, mirror targets and the environment atlas.
uint64_t rasterSceneBytes(const Scene& scene, const RenderRequest& r) {
    uint64_t bytes = triangles(scene) * kRasterBytesPerTriangle;
    std::set<const Texture*> textures;
    for (const Mesh& mesh : scene.meshes)
        for (const MeshPart& part : mesh.parts)
            for (const TextureBinding* b :
                 {&part.material.baseColorTexture, &part.material.metallicRoughnessTexture,
                  &part.material.normalTexture, &part.material.occlusionTexture, &part.material.emissiveTexture})
                if (b->texture && textures.insert(b->texture.get()).second) bytes += b->texture->texelBytes();
    const int k = gridSamplesPerSide(r.samples());
    if (scene.terms.shadows && !scene.lights.empty()) {
        RasterSettings settings = scene.raster;
        settings.shadowMapSize = raster::shadowMapSizeFor(scene.raster, r.width * k, r.height * k);
        const raster::ShadowFit fit = raster::fitShadows(scene, sceneBounds(scene), settings);
        const uint64_t side = uint64_t(settings.shadowMapSize);
        bytes += uint64_t(std::max(fit.layers, 1)) * side * side * 4;  // DEPTH_COMPONENT32F layers
    }
    if (scene.terms.reflections) {
        uint64_t cubes = 0, mirrors = 0;
        for (const Sphere& s : scene.spheres) cubes += reflective(s.material);
        for (const Mesh& mesh : scene.meshes)
            for (const MeshPart& part : mesh.parts) cubes += reflective(part.material);
        for (const Plane& p : scene.planes) mirrors += reflective(p.material);
        const uint64_t side = uint64_t(std::max(scene.raster.reflectionCubeSize, 1));
        bytes += std::min<uint64_t>(cubes, raster::kMaxEnvironmentCubes) * 6 * side * side * kCubeBytesPerTexel;
        bytes += std::min<uint64_t>(mirrors, raster::kMaxMirrorPlanes) * bandSamples(r) * kMirrorBytesPerSample;
    }
    if (scene.environment && scene.environment->map)
        bytes += scene.environment->map->atlas.size() * sizeof(float) / 3 * 4;  // RGB32F, padded to RGBA
    return bytes;
}

// What the tracers allocate for this scene: the BVH, and for the path tracer the environment's sampler.
uint64_t traceSceneBytes(const Scene& scene, const RenderRequest& r) {
    const uint64_t n = triangles(scene);
    uint64_t bytes = n * kTraceBytesPerTriangle;
    if (n <= trace::kMaxSpatialSplitTriangles) bytes += n * kSplitBytesPerTriangle;
    if (r.engine == Engine::Path && scene.environment && scene.environment->map) {
        const uint64_t side = uint64_t(scene.environment->map->size);
        bytes += 6 * side * side * 2 * sizeof(double);  // the texels' weights and their CDF
    }
    return bytes;
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

uint64_t memoryLimit(const RenderRequest& request) { return request.maxMemory.value_or(defaultMaxMemory()); }

uint64_t parseMemorySize(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    const std::string unit = end ? std::string(end) : std::string();
    double scale = 0.0;
    if (unit == "G" || unit == "g" || unit == "GiB")
        scale = double(kMiB) * 1024.0;
    else if (unit == "M" || unit == "m" || unit == "MiB" || unit.empty())
        scale = double(kMiB);
    if (text.empty() || end == text.c_str() || !std::isfinite(v) || v <= 0.0 || scale == 0.0 || v * scale > 1e18 ||
        v * scale < 1.0)
        throw SettingError("max_memory", "expected a size such as 512M or 2G, got '" + text.substr(0, 64) + "'");
    return uint64_t(v * scale);
}

uint64_t minimumRenderBytes(const RenderRequest& request) {
    return std::min(requestBytes(request, RenderOutput::Png), requestBytes(request, RenderOutput::Image));
}

uint64_t estimateRenderBytes(const Scene& scene, const RenderRequest& request, RenderOutput output) {
    uint64_t bytes = requestBytes(request, output) + loadedSceneBytes(scene);
    if (rasterizes(request)) bytes += rasterSceneBytes(scene, request);
    if (traces(request)) bytes += traceSceneBytes(scene, request);
    return bytes;
}

std::optional<std::string> memoryProblem(const Scene& scene, const RenderRequest& request, RenderOutput output) {
    const uint64_t need = estimateRenderBytes(scene, request, output), limit = memoryLimit(request);
    if (need <= limit) return std::nullopt;
    return "a " + std::to_string(request.width) + "x" + std::to_string(request.height) + " " +
           toString(request.engine) + " render of this scene needs about " + memoryText(need, true) +
           ", over the limit of " + memoryText(limit);
}

uint64_t softwareRasterHeapBytes(const RenderRequest& request) {
    if (!rasterizes(request)) return 0;
    const uint64_t samples = bandSamples(request);
    return kSoftwareContextHeapBytes + heapBlock(samples * 12) + heapBlock(samples * 4) +
           heapBlock(pixelsOf(request) * 3);
}

std::string memoryText(uint64_t bytes, bool roundUp) {
    if (bytes < kMiB) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
    return std::to_string(roundUp ? (bytes + kMiB - 1) / kMiB : bytes / kMiB) + " MiB";
}

}  // namespace shadelab::render
