// The robust ray–box slab test the BVH traversals share, over scene/bounds.h boxes (Kay & Kajiya 1986
// slabs; Ize 2013 "Robust BVH Ray Traversal" for the conservative far distance). No primitives here.
#pragma once

#include "scene/bounds.h"
#include "trace/ray.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace shadelab::trace {

// Per-ray constants of the slab test. A zero (or denormal) direction component becomes a huge finite
// reciprocal, so a ray parallel to a slab never multiplies 0 by infinity (which would give NaN).
struct BoxRay {
    float org[3];
    float invDir[3];
    int nearIdx[3];  // per axis, the index in a bounds[6] array (lo xyz, hi xyz) of the slab entered first
    int farIdx[3];
};

inline BoxRay makeBoxRay(const Ray& ray) {
    BoxRay b{};
    const float d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    const float o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    for (int a = 0; a < 3; ++a) {
        b.org[a] = o[a];
        b.invDir[a] = std::fabs(d[a]) > 1e-30f ? 1.0f / d[a] : std::copysign(1e30f, d[a]);
        // Kay & Kajiya: with the direction's sign known per ray, the near slab needs no min/max.
        b.nearIdx[a] = b.invDir[a] < 0.0f ? 3 + a : a;
        b.farIdx[a] = b.invDir[a] < 0.0f ? a : 3 + a;
    }
    return b;
}

// 1 + 2·γ(3) with γ(n) = nε/(1 − nε) (Ize 2013; pbrt-v3 §3.9.2): widening the far distance by this makes
// the float slab test conservative, so a box is never culled while a primitive inside it is hit.
inline constexpr float kSlabFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// Entry distance of the ray into the box `bounds` (lo x, y, z, hi x, y, z), or +infinity when it misses
// the box or enters it beyond tMax. Entry may be negative when the origin is inside.
inline float slabEntry(const BoxRay& r, const float* bounds, float tMax) {
    const float tx0 = (bounds[r.nearIdx[0]] - r.org[0]) * r.invDir[0];
    const float tx1 = (bounds[r.farIdx[0]] - r.org[0]) * r.invDir[0];
    const float ty0 = (bounds[r.nearIdx[1]] - r.org[1]) * r.invDir[1];
    const float ty1 = (bounds[r.farIdx[1]] - r.org[1]) * r.invDir[1];
    const float tz0 = (bounds[r.nearIdx[2]] - r.org[2]) * r.invDir[2];
    const float tz1 = (bounds[r.farIdx[2]] - r.org[2]) * r.invDir[2];
    const float tNear = std::max(std::max(tx0, ty0), tz0);
    const float tFar = std::min(std::min(tx1, ty1), tz1) * kSlabFarScale;
    return (tNear <= tFar && tFar >= 0.0f && tNear <= tMax) ? tNear : INFINITY;
}

}  // namespace shadelab::trace
