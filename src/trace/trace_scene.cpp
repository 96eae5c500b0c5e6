// TraceScene: building the accelerators, the scene-scaled epsilon, and the nearest-hit and occlusion
// queries over spheres, planes and triangles.
#include "trace/trace_scene.h"

#include "scene/coverage.h"
#include "scene/ray_epsilon.h"
#include "shading/lighting.h"
#include "util/check.h"

#include <algorithm>
#include <cmath>

namespace shadelab::trace {

TraceScene::TraceScene(const Scene& scene) : TraceScene(scene, std::make_shared<const MeshBvh>(scene)) {}

TraceScene::TraceScene(const Scene& scene, std::shared_ptr<const MeshBvh> meshes)
    : scene_(scene), meshes_(std::move(meshes)) {
    SHADELAB_CHECK(meshes_ != nullptr);
    SHADELAB_CHECK(meshes_->matches(scene_));
    prepare();
}

void TraceScene::prepare() {
    spheres_.emplace(scene_.spheres);
    uint32_t triangles = 0;  // MeshBvh::sourceTriangle counts every part's triangles in this order
    for (size_t m = 0; m < scene_.meshes.size(); ++m)
        for (size_t p = 0; p < scene_.meshes[m].parts.size(); ++p) {
            partRef_.emplace_back(uint32_t(m), uint32_t(p));
            partFirstTriangle_.push_back(triangles);
            triangles += uint32_t(scene_.meshes[m].parts[p].triangleCount());
        }

    epsilon_ = secondaryRayEpsilon(scene_, scene_.camera.position);
}

inline bool TraceScene::nearestAnalytic(const Ray& ray, Hit& best) const {
    // Once per ray: only the kinds of object the scene has are asked, and the spheres answer through an
    // out-parameter (an optional built and copied there stalled on a partial store).
    best.t = INFINITY;
    bool found = false;
    SphereHit s;
    if (spheres_->size() != 0 && spheres_->closestHit(ray, 0.0f, INFINITY, s)) {
        best.t = s.t;
        best.kind = HitKind::Sphere;
        best.index = s.index;
        found = true;
    }
    for (size_t i = 0; i < scene_.planes.size(); ++i) {
        const Plane& p = scene_.planes[i];
        const float t = shading::intersectPlane(ray.origin, ray.dir, p.normal, p.offset, 0.0f);
        if (t > 0.0f && t < best.t) {
            best.t = t;
            best.kind = HitKind::Plane;
            best.index = uint32_t(i);
            found = true;
        }
    }
    return found;
}

std::optional<Hit> TraceScene::intersect(const Ray& ray) const {
    Hit best;
    bool found = nearestAnalytic(ray, best);
    MeshHit m;
    if (meshes_->closestHit(ray, best.t, m)) {
        best = Hit{m.t, HitKind::Triangle, m.slot, m.b0, m.b1, m.b2};
        found = true;
    }
    if (!found) return std::nullopt;
    return best;
}

void TraceScene::intersect8(const Ray* rays, unsigned valid, std::optional<Hit>* out) const {
    Hit best[8];
    float bound[8] = {};
    unsigned found = 0;
    for (unsigned v = valid & 0xFFu; v; v &= v - 1) {
        const int k = __builtin_ctz(v);
        if (nearestAnalytic(rays[k], best[k])) found |= 1u << k;
        bound[k] = best[k].t;
    }
    MeshHit m[8];
    const unsigned meshHits = meshes_->closestHit8(rays, bound, valid, m);
    for (unsigned v = valid & 0xFFu; v; v &= v - 1) {
        const int k = __builtin_ctz(v);
        if ((meshHits >> k) & 1)
            out[k] = Hit{m[k].t, HitKind::Triangle, m[k].slot, m[k].b0, m[k].b1, m[k].b2};
        else if ((found >> k) & 1)
            out[k] = best[k];
        else
            out[k] = std::nullopt;
    }
}

inline bool TraceScene::occludedByAnalytic(const Ray& ray, float tMax) const {
    for (const Plane& p : scene_.planes) {
        const float t = shading::intersectPlane(ray.origin, ray.dir, p.normal, p.offset, 0.0f);
        if (t > 0.0f && t < tMax) return true;
    }
    return spheres_->anyHit(ray, 0.0f, tMax);
}

bool TraceScene::occluded(const Ray& ray, float tMax) const {
    return occludedByAnalytic(ray, tMax) || meshes_->anyHit(ray, tMax);
}

unsigned TraceScene::occluded8(const Ray* rays, const float* tMax, unsigned valid) const {
    unsigned occluded = 0;
    for (unsigned v = valid & 0xFFu; v; v &= v - 1) {
        const int k = __builtin_ctz(v);
        if (occludedByAnalytic(rays[k], tMax[k])) occluded |= 1u << k;
    }
    return occluded | meshes_->anyHit8(rays, tMax, valid & ~occluded);
}

uint32_t TraceScene::coverageId(const Hit& hit) const {
    switch (hit.kind) {
        case HitKind::Sphere: return sphereCoverageId(scene_, hit.index);
        case HitKind::Plane: return planeCoverageId(scene_, hit.index);
        case HitKind::Triangle: return meshCoverageId(scene_, meshes_->partMesh()[meshes_->part(hit.index)]);
    }
    return kBackgroundId;
}

const Material& TraceScene::material(const Hit& hit) const {
    switch (hit.kind) {
        case HitKind::Sphere: return scene_.spheres[hit.index].material;
        case HitKind::Plane: return scene_.planes[hit.index].material;
        case HitKind::Triangle: break;
    }
    const std::pair<uint32_t, uint32_t> ref = partRef_[meshes_->part(hit.index)];
    return scene_.meshes[ref.first].parts[ref.second].material;
}

}  // namespace shadelab::trace
