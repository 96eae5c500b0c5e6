// Bounds: the one axis-aligned box type of every module (scene framing, mesh geometry, the tracer's BVH,
// shadow-map fitting). Plain data; no ray tests here (trace/accel/slab_test.h has the slab test).
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace shadelab {

struct Bounds {
    glm::vec3 lo{1e30f};  // world units; lo > hi on some axis means empty
    glm::vec3 hi{-1e30f};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Bounds& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    glm::vec3 centroid() const { return 0.5f * (lo + hi); }
    // Corner k of 8: bit 0 picks hi.x, bit 1 hi.y, bit 2 hi.z.
    glm::vec3 corner(int k) const { return {k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z}; }
    // Surface area, the SAH's probability measure (MacDonald & Booth 1990). 0 for an empty box.
    float area() const {
        if (empty()) return 0.0f;
        const glm::vec3 e = hi - lo;
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

}  // namespace shadelab
