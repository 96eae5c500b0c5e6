// SphereSet: a scene's spheres, tested in one flat pass when they are few (SphereList) and behind a small BVH
// when they are many, so a ray tests only the spheres whose boxes it crosses. Both find the hits of
// shading::intersectSphere, the function the rasterizer's impostors run, bit for bit.
#pragma once

#include "scene/objects.h"
#include "trace/accel/bvh.h"
#include "trace/accel/sphere_list.h"
#include "trace/ray.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>
#include <optional>
#include <vector>

namespace shadelab::trace {

// Up to this many spheres a flat pass over all of them beats the BVH walk. The pass skips the square root and the
// division for four or eight spheres at once when the ray's line misses them all, so it costs about a cheap box
// test per sphere: on sphere_bench's rays it takes 0.5-0.6 of the walk's time at 40 spheres in AVX2, 0.6-0.7 in
// SSE2, and still 0.8 at 64 in SSE2 (bench/README.md, "Spheres: a flat pass or the tree").
inline constexpr size_t kFlatSphereLimit = 64;

class SphereSet {
public:
    // `flatLimit`: the largest set tested flat (the tests compare both ways on one set); `isa`: the flat pass's
    // instruction set (SphereList).
    explicit SphereSet(const std::vector<Sphere>& spheres, size_t flatLimit = kFlatSphereLimit,
                       BvhIsa isa = defaultBvhIsa());

    // The nearest intersectSphere(origin, dir, centre, radius, tMin) result below tMax; an exact tie goes
    // to the lower sphere index, as a loop over the spheres in scene order gives.
    std::optional<SphereHit> closestHit(const Ray& ray, float tMin, float tMax) const {
        SphereHit h;
        return closestHit(ray, tMin, tMax, h) ? std::optional<SphereHit>(h) : std::nullopt;
    }
    // The same into `out` (left alone without a hit): the per-ray path TraceScene takes. An optional returned
    // here was assembled on the stack from a byte store and read back wider, a store-forwarding stall per ray.
    bool closestHit(const Ray& ray, float tMin, float tMax, SphereHit& out) const {
        // Inline, so scenes without spheres pay no call per ray.
        if (!flat_.empty()) {
            const std::optional<SphereHit> h = flat_.closestHit(ray, tMin, tMax);
            if (h) out = *h;
            return h.has_value();
        }
        return !bvh_.empty() && closestHitInTree(ray, tMin, tMax, out);
    }
    // Whether some sphere is hit at tMin < t < tMax (shadow rays).
    bool anyHit(const Ray& ray, float tMin, float tMax) const {
        if (!flat_.empty()) return flat_.anyHit(ray, tMin, tMax);
        return !bvh_.empty() && anyHitInTree(ray, tMin, tMax);
    }

    size_t size() const { return count_; }
    bool flat() const { return !flat_.empty(); }
    Bounds bounds() const { return bounds_; }

private:
    bool closestHitInTree(const Ray& ray, float tMin, float tMax, SphereHit& out) const;
    bool anyHitInTree(const Ray& ray, float tMin, float tMax) const;

    SphereList flat_;  // every sphere when there are at most flatLimit of them, else empty
    // The tree, for larger sets (else empty):
    Bvh bvh_;
    std::vector<glm::vec4> spheres_;  // centre and radius, in BVH order
    std::vector<uint32_t> index_;     // scene index, in BVH order
    size_t count_ = 0;
    Bounds bounds_;
};

}  // namespace shadelab::trace
