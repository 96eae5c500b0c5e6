// firstHitPasses: rows in parallel; each pixel's passes depend on that pixel alone.
#include "trace/first_hit_passes.h"

#include "scene/view.h"
#include "shading/lighting.h"
#include "trace/surface.h"
#include "trace/tile_renderer.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace shadelab::trace {
namespace {

bool emits(const Material& m) { return m.emission.x > 0.0f || m.emission.y > 0.0f || m.emission.z > 0.0f; }

glm::vec3 albedoOf(const Surface& s) {
    if (emits(*s.material)) return glm::vec3(1.0f);
    const glm::vec3 a = shading::physicallyBased(s.model) ? s.baseColor : s.md + s.ms + s.material->kr;
    return glm::clamp(a, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace

SurfacePasses firstHitPasses(const TraceScene& scene, int width, int height, int threads) {
    SurfacePasses out(width, height);
    const ViewSetup v = makeViewSetup(scene.scene(), width, height);
    SurfaceSetup surfaces(scene);
    surfaces.setPixelFootprint(pixelFootprint(v));
    if (threads <= 0) threads = std::max(1, int(std::thread::hardware_concurrency()));
    parallelFor(height, threads, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray{v.eye, shading::cameraRayDirection(v.forward, v.right, v.up, v.tanHalfFovY, float(width),
                                                             float(height), float(x) + 0.5f, float(y) + 0.5f)};
            const std::optional<Hit> hit = surfaces.visibleHit(ray, 0.0f, 0);
            if (!hit) continue;
            const Surface s = surfaces.at(ray, *hit, 0);
            const size_t p = size_t(y) * size_t(width) + size_t(x);
            const glm::vec3 a = albedoOf(s);
            const float len = glm::length(s.N);
            const glm::vec3 n = len > 0.0f ? s.N / len : s.Nf;
            for (int c = 0; c < 3; ++c) {
                out.albedo[3 * p + size_t(c)] = a[c];
                out.normal[3 * p + size_t(c)] = n[c];
            }
            out.depth[p] = hit->t * glm::dot(ray.dir, v.forward);
        }
    });
    return out;
}

}  // namespace shadelab::trace
