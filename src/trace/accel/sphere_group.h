// SphereGroup: four spheres tested against one ray at once. shading::intersectSphere written out for four lanes
// in SSE2 (x86-64's baseline), the same operations in the same order, so every lane rounds as the scalar function
// does; elsewhere a scalar loop over the same layout. The flat pass (SphereList) runs it over every group of a
// small set, the sphere tree (SphereSet) over the groups in the leaves a ray reaches. Translation units that
// include it are built with -ffp-contract=off (src/trace/CMakeLists.txt), so the compiler fuses neither version.
#pragma once

#include "trace/accel/simd4.h"
#include "trace/ray.h"

#include <cstdint>
#include <glm/vec4.hpp>
#include <limits>

#ifndef SHADELAB_SIMD4_SSE2
#include "shading/lighting.h"
#endif

namespace shadelab::trace {

// Four spheres side by side, structure of arrays, so one SSE register holds one coordinate of all four. Lanes
// without a sphere hold NaN, which every test misses.
struct alignas(16) SphereGroup {
    float cx[4], cy[4], cz[4], r[4];

    static SphereGroup empty() {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        return {{nan, nan, nan, nan}, {nan, nan, nan, nan}, {nan, nan, nan, nan}, {nan, nan, nan, nan}};
    }
    void set(int lane, const glm::vec4& centreRadius) {
        cx[lane] = centreRadius.x;
        cy[lane] = centreRadius.y;
        cz[lane] = centreRadius.z;
        r[lane] = centreRadius.w;
    }
};

#ifdef SHADELAB_SIMD4_SSE2

// One ray, splatted across the four lanes.
struct GroupRay {
    __m128 ox, oy, oz, dx, dy, dz, tMin;
};

inline GroupRay groupRay(const Ray& ray, float tMin) {
    return {_mm_set1_ps(ray.origin.x), _mm_set1_ps(ray.origin.y), _mm_set1_ps(ray.origin.z), _mm_set1_ps(ray.dir.x),
            _mm_set1_ps(ray.dir.y),    _mm_set1_ps(ray.dir.z),    _mm_set1_ps(tMin)};
}

namespace sphere_group_detail {

inline __m128 select(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }

// GLM's dot of two vec3: (x·x' + y·y') + z·z'.
inline __m128 dot3(__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
}

}  // namespace sphere_group_detail

// shaders/lighting.glsl's intersectSphere in four lanes: t > tMin, or -1 on a miss. GLM's min(x, y) is
// y < x ? y : x, which is _mm_min_ps(y, x); max(x, y) is x < y ? y : x, which is _mm_max_ps(y, x), NaN and
// signed zeros included.
inline __m128 intersectGroup(const GroupRay& r, const SphereGroup& g) {
    using sphere_group_detail::dot3;
    using sphere_group_detail::select;
    const __m128 zero = _mm_setzero_ps(), minusOne = _mm_set1_ps(-1.0f);
    const __m128 ocx = _mm_sub_ps(r.ox, _mm_load_ps(g.cx));
    const __m128 ocy = _mm_sub_ps(r.oy, _mm_load_ps(g.cy));
    const __m128 ocz = _mm_sub_ps(r.oz, _mm_load_ps(g.cz));
    const __m128 radius = _mm_load_ps(g.r);
    const __m128 rr = _mm_mul_ps(radius, radius);
    const __m128 b = dot3(ocx, ocy, ocz, r.dx, r.dy, r.dz);
    const __m128 px = _mm_sub_ps(ocx, _mm_mul_ps(b, r.dx));
    const __m128 py = _mm_sub_ps(ocy, _mm_mul_ps(b, r.dy));
    const __m128 pz = _mm_sub_ps(ocz, _mm_mul_ps(b, r.dz));
    const __m128 disc = _mm_sub_ps(rr, dot3(px, py, pz, px, py, pz));
    const __m128 reached = _mm_cmpnlt_ps(disc, zero);  // !(disc < 0): a NaN goes on, as in the scalar code
    const __m128 sq = _mm_sqrt_ps(disc);
    const __m128 c = _mm_sub_ps(dot3(ocx, ocy, ocz, ocx, ocy, ocz), rr);
    const __m128 minusB = _mm_xor_ps(b, _mm_set1_ps(-0.0f));
    const __m128 q = select(_mm_cmpgt_ps(b, zero), _mm_sub_ps(minusB, sq), _mm_add_ps(minusB, sq));
    const __m128 t0 = _mm_and_ps(_mm_cmpneq_ps(q, zero), _mm_div_ps(c, q));  // q != 0 ? c / q : +0
    const __m128 tNear = _mm_min_ps(q, t0);
    const __m128 tFar = _mm_max_ps(q, t0);
    const __m128 t = select(_mm_cmpgt_ps(tNear, r.tMin), tNear, select(_mm_cmpgt_ps(tFar, r.tMin), tFar, minusOne));
    return select(reached, t, minusOne);
}

// The lanes hit at tMin < t < tMax (bit k for lane k), their distances in t[4].
inline unsigned groupHits(const GroupRay& r, const SphereGroup& g, float tMax, float* t) {
    const __m128 ts = intersectGroup(r, g);
    _mm_storeu_ps(t, ts);
    return unsigned(_mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(ts, r.tMin), _mm_cmplt_ps(ts, _mm_set1_ps(tMax)))));
}

// The same with t <= tMax: a closest-hit search keeps lanes that tie with its best so far.
inline unsigned groupHitsUpTo(const GroupRay& r, const SphereGroup& g, float tMax, float* t) {
    const __m128 ts = intersectGroup(r, g);
    _mm_storeu_ps(t, ts);
    return unsigned(_mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(ts, r.tMin), _mm_cmple_ps(ts, _mm_set1_ps(tMax)))));
}

#else

struct GroupRay {
    Ray ray;
    float tMin;
};

inline GroupRay groupRay(const Ray& ray, float tMin) { return {ray, tMin}; }

inline unsigned groupHits(const GroupRay& r, const SphereGroup& g, float tMax, float* t) {
    unsigned mask = 0;
    for (int k = 0; k < 4; ++k) {
        t[k] = shading::intersectSphere(r.ray.origin, r.ray.dir, glm::vec3(g.cx[k], g.cy[k], g.cz[k]), g.r[k], r.tMin);
        if (t[k] > r.tMin && t[k] < tMax) mask |= 1u << k;
    }
    return mask;
}

inline unsigned groupHitsUpTo(const GroupRay& r, const SphereGroup& g, float tMax, float* t) {
    unsigned mask = 0;
    for (int k = 0; k < 4; ++k) {
        t[k] = shading::intersectSphere(r.ray.origin, r.ray.dir, glm::vec3(g.cx[k], g.cy[k], g.cz[k]), g.r[k], r.tMin);
        if (t[k] > r.tMin && t[k] <= tMax) mask |= 1u << k;
    }
    return mask;
}

#endif

}  // namespace shadelab::trace
