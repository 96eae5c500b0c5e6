// The robust ray–box slab test the BVH traversals share, four boxes at a time (Kay & Kajiya 1986 slabs;
// Ize 2013 "Robust BVH Ray Traversal" for the conservative far distance). No primitives here.
#pragma once

#include "scene/bounds.h"
#include "trace/accel/simd4.h"
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

// The slab test of one ray against four child boxes of a BVH node, `bounds[side][first + k]` for k = 0-3
// (side 0-2 lo x, y, z; 3-5 hi x, y, z; 16-byte aligned rows). Returns a mask with bit k set when the ray meets
// box k at some 0 <= t <= tMax, and sets tNear to where it enters each (clamped to 0 when the origin is
// inside). An inverted box (lo > hi) is always missed. Per lane:
//   max(tx0, ty0, tz0, 0) <= min(tx1 · s, ty1 · s, tz1 · s, tMax), with s = kSlabFarScale
// (for tMax >= 0 the same as tNear <= tFar, tFar >= 0, tNear <= tMax; a negative tMax, for which no hit with
// t > 0 exists, misses everything). bvh_traverse_avx2.cpp evaluates it on eight lanes at once with fused
// multiply-subtracts (conservative too, not the same bits).
struct BoxRay4 {
    F4 org[3], invDir[3];
    int nearIdx[3], farIdx[3];
};

inline BoxRay4 makeBoxRay4(const BoxRay& r) {
    BoxRay4 b;
    for (int a = 0; a < 3; ++a) {
        b.org[a] = splat4(r.org[a]);
        b.invDir[a] = splat4(r.invDir[a]);
        b.nearIdx[a] = r.nearIdx[a];
        b.farIdx[a] = r.farIdx[a];
    }
    return b;
}

template <int Width>
inline int slabHits4(const BoxRay4& r, const float (*bounds)[Width], int first, float tMax, F4& tNear) {
    const F4 tx0 = (load4(bounds[r.nearIdx[0]] + first) - r.org[0]) * r.invDir[0];
    const F4 tx1 = (load4(bounds[r.farIdx[0]] + first) - r.org[0]) * r.invDir[0];
    const F4 ty0 = (load4(bounds[r.nearIdx[1]] + first) - r.org[1]) * r.invDir[1];
    const F4 ty1 = (load4(bounds[r.farIdx[1]] + first) - r.org[1]) * r.invDir[1];
    const F4 tz0 = (load4(bounds[r.nearIdx[2]] + first) - r.org[2]) * r.invDir[2];
    const F4 tz1 = (load4(bounds[r.farIdx[2]] + first) - r.org[2]) * r.invDir[2];
    const F4 tn = max4(max4(tx0, ty0), max4(tz0, splat4(0.0f)));
    const F4 tf = min4(min4(tx1, ty1), tz1) * splat4(kSlabFarScale);
    tNear = tn;
    return lessEqualMask(tn, min4(tf, splat4(tMax)));
}

// The same for eight boxes, `bounds[side][k]` for k = 0-7, as two groups of four: bit k of the mask for box
// k, tNear[k] its entry distance.
inline int slabHits8(const BoxRay4& r, const float (*bounds)[8], float tMax, float* tNear) {
    F4 lo, hi;
    const int m = slabHits4(r, bounds, 0, tMax, lo) | slabHits4(r, bounds, 4, tMax, hi) << 4;
    store4(tNear, lo);
    store4(tNear + 4, hi);
    return m;
}

}  // namespace shadelab::trace
