// SphereSet: the flat pass for small sets; for larger ones a BVH over padded sphere boxes and its traversals.
// The padding keeps the box test conservative, so culling never changes which sphere intersectSphere reports.
#include "trace/accel/sphere_set.h"

#include "shading/lighting.h"
#include "trace/accel/bvh_traverse.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadelab::trace {

SphereSet::SphereSet(const std::vector<Sphere>& spheres, size_t flatLimit, BvhIsa isa) : count_(spheres.size()) {
    std::vector<Bounds> boxes;
    boxes.reserve(spheres.size());
    for (const Sphere& s : spheres) {
        // Pad by a little more than intersectSphere's rounding, relative to the radius and to the
        // magnitude of the coordinates, so grazing hits are never culled.
        const float m = std::max({std::fabs(s.center.x), std::fabs(s.center.y), std::fabs(s.center.z)});
        const float r = s.radius * (1.0f + 1e-4f) + 1e-6f * m;
        Bounds b;
        b.lo = s.center - glm::vec3(r);
        b.hi = s.center + glm::vec3(r);
        boxes.push_back(b);
        bounds_.extend(b);
    }
    if (spheres.size() <= flatLimit) {
        flat_ = SphereList(spheres, isa);
        return;
    }
    BvhBuildOptions options;
    options.maxLeafSize = 2;
    bvh_ = buildBvh(boxes, options);
    for (uint32_t slot : bvh_.order) {
        spheres_.emplace_back(spheres[slot].center, spheres[slot].radius);
        index_.push_back(slot);
    }
}

bool SphereSet::closestHitInTree(const Ray& ray, float tMin, float tMax, SphereHit& out) const {
    SphereHit best{tMax, UINT32_MAX};
    traverseClosest(bvh_, makeBoxRay(ray), tMax, [&](uint32_t first, uint32_t count) {
        for (uint32_t s = first, end = first + count; s < end; ++s) {
            const glm::vec4& c = spheres_[s];
            const float t = shading::intersectSphere(ray.origin, ray.dir, glm::vec3(c), c.w, tMin);
            if (!(t > tMin)) continue;  // -1 is a miss
            if (t < best.t || (t == best.t && best.index != UINT32_MAX && index_[s] < best.index))
                best = SphereHit{t, index_[s]};
        }
        return best.t;
    });
    if (best.index == UINT32_MAX) return false;
    out = best;
    return true;
}

bool SphereSet::anyHitInTree(const Ray& ray, float tMin, float tMax) const {
    return traverseAny(bvh_, makeBoxRay(ray), tMax, [&](uint32_t first, uint32_t count) {
        for (uint32_t s = first, end = first + count; s < end; ++s) {
            const glm::vec4& c = spheres_[s];
            const float t = shading::intersectSphere(ray.origin, ray.dir, glm::vec3(c), c.w, tMin);
            if (t > tMin && t < tMax) return true;
        }
        return false;
    });
}

}  // namespace shadelab::trace
