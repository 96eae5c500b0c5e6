// SphereList: a small set of spheres tested all at once, four per step, with no tree. For the tens of spheres
// of a lecture scene one flat, branch-light pass over every sphere is cheaper than a BVH walk (bench/README.md,
// "Spheres: flat list or tree"). Not for large sets: its cost grows linearly with the spheres.
#pragma once

#include "scene/objects.h"
#include "trace/accel/sphere_group.h"
#include "trace/ray.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace shadelab::trace {

struct SphereHit {
    float t;         // ray parameter
    uint32_t index;  // into Scene::spheres
};

class SphereList {
public:
    SphereList() = default;  // no spheres
    explicit SphereList(const std::vector<Sphere>& spheres);

    // The nearest shading::intersectSphere(origin, dir, centre, radius, tMin) result below tMax, bit for bit;
    // an exact tie goes to the lower sphere index, as a loop over the spheres in scene order gives.
    std::optional<SphereHit> closestHit(const Ray& ray, float tMin, float tMax) const;
    // Whether some sphere is hit at tMin < t < tMax (shadow rays).
    bool anyHit(const Ray& ray, float tMin, float tMax) const;

    size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }

private:
    // Sphere 4·g + lane in lane `lane` of group g. The lanes after the last sphere hold NaN, which every test
    // misses, so the loop needs no tail.
    std::vector<SphereGroup> groups_;
    size_t count_ = 0;
};

}  // namespace shadelab::trace
