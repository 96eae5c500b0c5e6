// SphereGroup: eight spheres side by side, and the baseline test of one ray against four of them at once:
// shading::intersectSphere written out for four lanes in SSE2 (x86-64's baseline), the same operations in the same
// order, so every lane rounds as the scalar function does; elsewhere a scalar loop over the same layout. The flat
// pass (SphereList) runs it over the halves of every group; sphere_list_avx2.cpp tests whole groups in AVX2.
// Translation units that include it are built with -ffp-contract=off (src/trace/CMakeLists.txt), so the compiler
// fuses neither version.
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

struct SphereHit {
    float t;         // ray parameter
    uint32_t index;  // into Scene::spheres
};

// Eight spheres, structure of arrays: one AVX register, or two SSE registers (lanes 0-3 and 4-7), holds one
// coordinate of all eight. Lanes without a sphere hold NaN, which every test misses.
inline constexpr int kSphereGroupLanes = 8;
struct alignas(32) SphereGroup {
    float cx[8], cy[8], cz[8], r[8];

    static SphereGroup empty() {
        SphereGroup g;
        for (int k = 0; k < kSphereGroupLanes; ++k) g.set(k, glm::vec4(std::numeric_limits<float>::quiet_NaN()));
        return g;
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

// shaders/lighting.glsl's intersectSphere in four lanes, in two steps. The first (reach) computes the squared
// distance test, which most spheres fail for any one ray; only when some lane passes does the second (finish)
// take the square root and the division. Together the same operations as the scalar function, in its order.
struct GroupReach {
    __m128 ocx, ocy, ocz, rr, b, disc;
    int reached;  // bit k: lane k's disc is not < 0 (a NaN goes on, as in the scalar code)
};

// Lanes 4·half .. 4·half + 3 of the group.
inline GroupReach reachGroup(const GroupRay& r, const SphereGroup& g, int half) {
    using sphere_group_detail::dot3;
    const int o = 4 * half;
    GroupReach q;
    q.ocx = _mm_sub_ps(r.ox, _mm_load_ps(g.cx + o));
    q.ocy = _mm_sub_ps(r.oy, _mm_load_ps(g.cy + o));
    q.ocz = _mm_sub_ps(r.oz, _mm_load_ps(g.cz + o));
    const __m128 radius = _mm_load_ps(g.r + o);
    q.rr = _mm_mul_ps(radius, radius);
    q.b = dot3(q.ocx, q.ocy, q.ocz, r.dx, r.dy, r.dz);
    const __m128 px = _mm_sub_ps(q.ocx, _mm_mul_ps(q.b, r.dx));
    const __m128 py = _mm_sub_ps(q.ocy, _mm_mul_ps(q.b, r.dy));
    const __m128 pz = _mm_sub_ps(q.ocz, _mm_mul_ps(q.b, r.dz));
    q.disc = _mm_sub_ps(q.rr, dot3(px, py, pz, px, py, pz));
    q.reached = _mm_movemask_ps(_mm_cmpnlt_ps(q.disc, _mm_setzero_ps()));
    return q;
}

// t > tMin, or -1 on a miss. GLM's min(x, y) is y < x ? y : x, which is _mm_min_ps(y, x); max(x, y) is
// x < y ? y : x, which is _mm_max_ps(y, x), NaN and signed zeros included.
inline __m128 finishGroup(const GroupRay& r, const GroupReach& q) {
    using sphere_group_detail::dot3;
    using sphere_group_detail::select;
    const __m128 zero = _mm_setzero_ps(), minusOne = _mm_set1_ps(-1.0f);
    const __m128 reached = _mm_cmpnlt_ps(q.disc, zero);
    const __m128 sq = _mm_sqrt_ps(q.disc);
    const __m128 c = _mm_sub_ps(dot3(q.ocx, q.ocy, q.ocz, q.ocx, q.ocy, q.ocz), q.rr);
    const __m128 minusB = _mm_xor_ps(q.b, _mm_set1_ps(-0.0f));
    const __m128 qq = select(_mm_cmpgt_ps(q.b, zero), _mm_sub_ps(minusB, sq), _mm_add_ps(minusB, sq));
    const __m128 t0 = _mm_and_ps(_mm_cmpneq_ps(qq, zero), _mm_div_ps(c, qq));  // q != 0 ? c / q : +0
    const __m128 tNear = _mm_min_ps(qq, t0);
    const __m128 tFar = _mm_max_ps(qq, t0);
    const __m128 t = select(_mm_cmpgt_ps(tNear, r.tMin), tNear, select(_mm_cmpgt_ps(tFar, r.tMin), tFar, minusOne));
    return select(reached, t, minusOne);
}

// Whether some lane of the group is hit at tMin < t < tMax.
inline bool groupHitsAny(const GroupRay& r, const SphereGroup& g, float tMax) {
    for (int half = 0; half < 2; ++half) {
        const GroupReach q = reachGroup(r, g, half);
        if (!q.reached) continue;
        const __m128 t = finishGroup(r, q);
        if (_mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(t, r.tMin), _mm_cmplt_ps(t, _mm_set1_ps(tMax))))) return true;
    }
    return false;
}

#else

struct GroupRay {
    Ray ray;
    float tMin;
};

inline GroupRay groupRay(const Ray& ray, float tMin) { return {ray, tMin}; }

inline bool groupHitsAny(const GroupRay& r, const SphereGroup& g, float tMax) {
    for (int k = 0; k < kSphereGroupLanes; ++k) {
        const float t =
            shading::intersectSphere(r.ray.origin, r.ray.dir, glm::vec3(g.cx[k], g.cy[k], g.cz[k]), g.r[k], r.tMin);
        if (t > r.tMin && t < tMax) return true;
    }
    return false;
}

#endif

}  // namespace shadelab::trace
