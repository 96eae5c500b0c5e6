// SphereSet: a scene's spheres behind a small BVH, so a ray tests only the spheres whose boxes it
// crosses. The hit itself is shading::intersectSphere, the function the rasterizer's impostors run.
#pragma once

#include "scene/objects.h"
#include "trace/accel/bvh.h"
#include "trace/ray.h"

#include <cstdint>
#include <glm/vec4.hpp>
#include <optional>
#include <vector>

namespace shadelab::trace {

struct SphereHit {
    float t;         // ray parameter
    uint32_t index;  // into Scene::spheres
};

class SphereSet {
public:
    explicit SphereSet(const std::vector<Sphere>& spheres);

    // The nearest intersectSphere(origin, dir, centre, radius, tMin) result below tMax; an exact tie goes
    // to the lower sphere index, as a loop over the spheres in scene order gives.
    std::optional<SphereHit> closestHit(const Ray& ray, float tMin, float tMax) const {
        if (bvh_.empty()) return std::nullopt;  // inline, so scenes without spheres pay no call per ray
        return closestHitInTree(ray, tMin, tMax);
    }
    // Whether some sphere is hit at tMin < t < tMax (shadow rays).
    bool anyHit(const Ray& ray, float tMin, float tMax) const { return !bvh_.empty() && anyHitInTree(ray, tMin, tMax); }

    size_t size() const { return spheres_.size(); }
    Bounds bounds() const { return bounds_; }

private:
    std::optional<SphereHit> closestHitInTree(const Ray& ray, float tMin, float tMax) const;
    bool anyHitInTree(const Ray& ray, float tMin, float tMax) const;

    Bvh bvh_;
    std::vector<glm::vec4> spheres_;  // centre and radius, in BVH order
    std::vector<uint32_t> index_;     // scene index, in BVH order
    Bounds bounds_;
};

}  // namespace shadelab::trace
