// The AVX2 flat sphere pass (sphere_list_avx2.h). This file alone is compiled with -mavx2 (src/trace/CMakeLists.txt).
// Its code sits in an anonymous namespace and calls no inline function of a shared header (only intrinsics), so no
// code built for AVX2 can stand in for a baseline copy at link time.
#include "trace/accel/sphere_list_avx2.h"

#include <cstdint>
#include <cstdlib>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace shadelab::trace {

#if defined(__AVX2__)

namespace {

// One ray, splatted across the eight lanes.
struct Lanes {
    __m256 ox, oy, oz, dx, dy, dz, tMin;
};

Lanes lanesOf(const Ray& ray, float tMin) {
    return {_mm256_set1_ps(ray.origin.x), _mm256_set1_ps(ray.origin.y), _mm256_set1_ps(ray.origin.z),
            _mm256_set1_ps(ray.dir.x),    _mm256_set1_ps(ray.dir.y),    _mm256_set1_ps(ray.dir.z),
            _mm256_set1_ps(tMin)};
}

// mask ? a : b, for masks of whole lanes.
inline __m256 select(__m256 mask, __m256 a, __m256 b) { return _mm256_blendv_ps(b, a, mask); }

// GLM's dot of two vec3: (x·x' + y·y') + z·z'.
inline __m256 dot3(__m256 ax, __m256 ay, __m256 az, __m256 bx, __m256 by, __m256 bz) {
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(ax, bx), _mm256_mul_ps(ay, by)), _mm256_mul_ps(az, bz));
}

// intersectSphere in eight lanes: t > tMin, or -1 on a miss; false (t untouched) when every lane misses the
// ray's line, before the square root and the division. The predicates are SSE's: !(disc < 0) and q != 0 are
// true for NaN (unordered), > and < false. min(x, y) and max(x, y) as GLM's (sphere_group.h).
inline bool intersect8(const Lanes& r, const SphereGroup& g, __m256& t) {
    const __m256 zero = _mm256_setzero_ps(), minusOne = _mm256_set1_ps(-1.0f);
    const __m256 ocx = _mm256_sub_ps(r.ox, _mm256_load_ps(g.cx));
    const __m256 ocy = _mm256_sub_ps(r.oy, _mm256_load_ps(g.cy));
    const __m256 ocz = _mm256_sub_ps(r.oz, _mm256_load_ps(g.cz));
    const __m256 radius = _mm256_load_ps(g.r);
    const __m256 rr = _mm256_mul_ps(radius, radius);
    const __m256 b = dot3(ocx, ocy, ocz, r.dx, r.dy, r.dz);
    const __m256 px = _mm256_sub_ps(ocx, _mm256_mul_ps(b, r.dx));
    const __m256 py = _mm256_sub_ps(ocy, _mm256_mul_ps(b, r.dy));
    const __m256 pz = _mm256_sub_ps(ocz, _mm256_mul_ps(b, r.dz));
    const __m256 disc = _mm256_sub_ps(rr, dot3(px, py, pz, px, py, pz));
    const __m256 reached = _mm256_cmp_ps(disc, zero, _CMP_NLT_UQ);
    if (_mm256_movemask_ps(reached) == 0) return false;
    const __m256 sq = _mm256_sqrt_ps(disc);
    const __m256 c = _mm256_sub_ps(dot3(ocx, ocy, ocz, ocx, ocy, ocz), rr);
    const __m256 minusB = _mm256_xor_ps(b, _mm256_set1_ps(-0.0f));
    const __m256 q = select(_mm256_cmp_ps(b, zero, _CMP_GT_OQ), _mm256_sub_ps(minusB, sq), _mm256_add_ps(minusB, sq));
    const __m256 t0 = _mm256_and_ps(_mm256_cmp_ps(q, zero, _CMP_NEQ_UQ), _mm256_div_ps(c, q));
    const __m256 tNear = _mm256_min_ps(q, t0);
    const __m256 tFar = _mm256_max_ps(q, t0);
    t = select(_mm256_cmp_ps(tNear, r.tMin, _CMP_GT_OQ), tNear,
               select(_mm256_cmp_ps(tFar, r.tMin, _CMP_GT_OQ), tFar, minusOne));
    t = select(reached, t, minusOne);
    return true;
}

}  // namespace

bool closestSphereAvx2(const SphereGroup* groups, size_t count, const Ray& ray, float tMin, float tMax,
                       SphereHit& best) {
    const Lanes r = lanesOf(ray, tMin);
    // Each lane keeps its own nearest hit; scanning in scene order with a strict < keeps the lower index of an
    // exact tie within a lane, and the reduction below keeps it across lanes.
    __m256 bestT = _mm256_set1_ps(tMax);
    __m256 bestIndex = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
    __m256i index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i eight = _mm256_set1_epi32(8);
    for (size_t g = 0; g < count; ++g, index = _mm256_add_epi32(index, eight)) {
        __m256 t;
        if (!intersect8(r, groups[g], t)) continue;
        const __m256 nearer = _mm256_and_ps(_mm256_cmp_ps(t, r.tMin, _CMP_GT_OQ), _mm256_cmp_ps(t, bestT, _CMP_LT_OQ));
        bestT = select(nearer, t, bestT);
        bestIndex = select(nearer, _mm256_castsi256_ps(index), bestIndex);
    }
    // Lanes without a hit kept index -1 (sign bit set); most rays hit nothing or one lane.
    unsigned hitLanes = ~unsigned(_mm256_movemask_ps(bestIndex)) & 0xFFu;
    if (hitLanes == 0) return false;
    alignas(32) float ts[8];
    alignas(32) int32_t is[8];
    _mm256_store_ps(ts, bestT);
    _mm256_store_si256(reinterpret_cast<__m256i*>(is), _mm256_castps_si256(bestIndex));
    float nearT = tMax;
    uint32_t nearIndex = UINT32_MAX;
    for (; hitLanes; hitLanes &= hitLanes - 1) {
        const int lane = __builtin_ctz(hitLanes);
        const uint32_t i = uint32_t(is[lane]);
        if (ts[lane] < nearT || (ts[lane] == nearT && i < nearIndex)) {
            nearT = ts[lane];
            nearIndex = i;
        }
    }
    if (nearIndex == UINT32_MAX) return false;
    best.t = nearT;
    best.index = nearIndex;
    return true;
}

bool anySphereAvx2(const SphereGroup* groups, size_t count, const Ray& ray, float tMin, float tMax) {
    const Lanes r = lanesOf(ray, tMin);
    const __m256 bound = _mm256_set1_ps(tMax);
    for (size_t g = 0; g < count; ++g) {
        __m256 t;
        if (!intersect8(r, groups[g], t)) continue;
        if (_mm256_movemask_ps(
                _mm256_and_ps(_mm256_cmp_ps(t, r.tMin, _CMP_GT_OQ), _mm256_cmp_ps(t, bound, _CMP_LT_OQ))))
            return true;
    }
    return false;
}

#else

// Never called: bvhIsaAvailable(BvhIsa::Avx2) is false in builds without this file's AVX2 code.
bool closestSphereAvx2(const SphereGroup*, size_t, const Ray&, float, float, SphereHit&) { std::abort(); }
bool anySphereAvx2(const SphereGroup*, size_t, const Ray&, float, float) { std::abort(); }

#endif

}  // namespace shadelab::trace
