// SphereList: a small set of spheres tested all at once, eight per AVX2 step or four per SSE2 step, with no tree.
// For the tens of spheres of a lecture scene or a benchmark one flat, branch-light pass over every sphere is
// cheaper than a BVH walk (bench/README.md, "Spheres: a flat pass or the tree"). Not for large sets: its cost grows
// linearly with the spheres.
#pragma once

#include "scene/objects.h"
#include "trace/accel/bvh_isa.h"
#include "trace/accel/sphere_group.h"
#include "trace/ray.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace shadelab::trace {

class SphereList {
public:
    SphereList() = default;  // no spheres
    // `isa`: the baseline SSE2 pass, or the AVX2 one (eight spheres per step) where bvhIsaAvailable says so;
    // both give the same answers bit for bit.
    explicit SphereList(const std::vector<Sphere>& spheres, BvhIsa isa = defaultBvhIsa());

    // The nearest shading::intersectSphere(origin, dir, centre, radius, tMin) result below tMax, bit for bit;
    // an exact tie goes to the lower sphere index, as a loop over the spheres in scene order gives.
    std::optional<SphereHit> closestHit(const Ray& ray, float tMin, float tMax) const;
    // Whether some sphere is hit at tMin < t < tMax (shadow rays).
    bool anyHit(const Ray& ray, float tMin, float tMax) const;

    size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }

private:
    // Sphere 8·g + lane in lane `lane` of group g. The lanes after the last sphere hold NaN, which every test
    // misses, so the loop needs no tail.
    std::vector<SphereGroup> groups_;
    size_t count_ = 0;
    bool avx2_ = false;
};

}  // namespace shadelab::trace
