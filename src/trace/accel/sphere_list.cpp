// SphereList: shading::intersectSphere written out for four spheres at once in SSE2 (x86-64's baseline), the
// same operations in the same order, so every lane rounds as the scalar function does; elsewhere a scalar
// loop over the same layout. -ffp-contract=off (CMakeLists.txt) keeps the compiler from fusing either.
#include "trace/accel/sphere_list.h"

#include "shading/lighting.h"
#include "trace/accel/simd4.h"

#include <cmath>
#include <limits>

namespace shadelab::trace {

SphereList::SphereList(const std::vector<Sphere>& spheres) : count_(spheres.size()) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    groups_.assign((count_ + 3) / 4,
                   Group{{nan, nan, nan, nan}, {nan, nan, nan, nan}, {nan, nan, nan, nan}, {nan, nan, nan, nan}});
    for (size_t k = 0; k < count_; ++k) {
        Group& g = groups_[k / 4];
        const size_t lane = k % 4;
        g.cx[lane] = spheres[k].center.x;
        g.cy[lane] = spheres[k].center.y;
        g.cz[lane] = spheres[k].center.z;
        g.r[lane] = spheres[k].radius;
    }
}

#ifdef SHADELAB_SIMD4_SSE2

namespace {

// One ray, splatted across the four lanes.
struct RayLanes {
    __m128 ox, oy, oz, dx, dy, dz, tMin;
};

inline __m128 select(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }

// GLM's dot of two vec3: (x·x' + y·y') + z·z'.
inline __m128 dot3(__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
}

// shaders/lighting.glsl's intersectSphere in four lanes: t > tMin, or -1 on a miss. GLM's min(x, y) is
// y < x ? y : x, which is _mm_min_ps(y, x); max(x, y) is x < y ? y : x, which is _mm_max_ps(y, x), NaN and
// signed zeros included.
inline __m128 intersect4(const RayLanes& r, const float* cx, const float* cy, const float* cz, const float* rad) {
    const __m128 zero = _mm_setzero_ps(), minusOne = _mm_set1_ps(-1.0f);
    const __m128 ocx = _mm_sub_ps(r.ox, _mm_load_ps(cx));
    const __m128 ocy = _mm_sub_ps(r.oy, _mm_load_ps(cy));
    const __m128 ocz = _mm_sub_ps(r.oz, _mm_load_ps(cz));
    const __m128 radius = _mm_load_ps(rad);
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

RayLanes lanes(const Ray& ray, float tMin) {
    return {_mm_set1_ps(ray.origin.x), _mm_set1_ps(ray.origin.y), _mm_set1_ps(ray.origin.z), _mm_set1_ps(ray.dir.x),
            _mm_set1_ps(ray.dir.y),    _mm_set1_ps(ray.dir.z),    _mm_set1_ps(tMin)};
}

}  // namespace

std::optional<SphereHit> SphereList::closestHit(const Ray& ray, float tMin, float tMax) const {
    const RayLanes r = lanes(ray, tMin);
    // Each lane keeps its own nearest hit; scanning in scene order with a strict < keeps the lower index of an
    // exact tie within a lane, and the reduction below keeps it across lanes.
    __m128 bestT = _mm_set1_ps(tMax);
    __m128i bestIndex = _mm_set1_epi32(-1);
    __m128i index = _mm_set_epi32(3, 2, 1, 0);
    const __m128i four = _mm_set1_epi32(4);
    for (const Group& g : groups_) {
        const __m128 t = intersect4(r, g.cx, g.cy, g.cz, g.r);
        const __m128 nearer = _mm_and_ps(_mm_cmpgt_ps(t, r.tMin), _mm_cmplt_ps(t, bestT));
        bestT = select(nearer, t, bestT);
        bestIndex = _mm_castps_si128(select(nearer, _mm_castsi128_ps(index), _mm_castsi128_ps(bestIndex)));
        index = _mm_add_epi32(index, four);
    }
    alignas(16) float ts[4];
    alignas(16) int32_t is[4];
    _mm_store_ps(ts, bestT);
    _mm_store_si128(reinterpret_cast<__m128i*>(is), bestIndex);
    SphereHit best{tMax, UINT32_MAX};
    for (int lane = 0; lane < 4; ++lane) {
        if (is[lane] < 0) continue;
        const uint32_t i = uint32_t(is[lane]);
        if (ts[lane] < best.t || (ts[lane] == best.t && i < best.index)) best = SphereHit{ts[lane], i};
    }
    return best.index == UINT32_MAX ? std::nullopt : std::optional<SphereHit>(best);
}

bool SphereList::anyHit(const Ray& ray, float tMin, float tMax) const {
    const RayLanes r = lanes(ray, tMin);
    const __m128 bound = _mm_set1_ps(tMax);
    for (const Group& g : groups_) {
        const __m128 t = intersect4(r, g.cx, g.cy, g.cz, g.r);
        if (_mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(t, r.tMin), _mm_cmplt_ps(t, bound)))) return true;
    }
    return false;
}

#else

std::optional<SphereHit> SphereList::closestHit(const Ray& ray, float tMin, float tMax) const {
    SphereHit best{tMax, UINT32_MAX};
    for (size_t k = 0; k < count_; ++k) {
        const Group& g = groups_[k / 4];
        const size_t l = k % 4;
        const float t =
            shading::intersectSphere(ray.origin, ray.dir, glm::vec3(g.cx[l], g.cy[l], g.cz[l]), g.r[l], tMin);
        if (t > tMin && t < best.t) best = SphereHit{t, uint32_t(k)};
    }
    return best.index == UINT32_MAX ? std::nullopt : std::optional<SphereHit>(best);
}

bool SphereList::anyHit(const Ray& ray, float tMin, float tMax) const {
    for (size_t k = 0; k < count_; ++k) {
        const Group& g = groups_[k / 4];
        const size_t l = k % 4;
        const float t =
            shading::intersectSphere(ray.origin, ray.dir, glm::vec3(g.cx[l], g.cy[l], g.cz[l]), g.r[l], tMin);
        if (t > tMin && t < tMax) return true;
    }
    return false;
}

#endif

}  // namespace shadelab::trace
