// SphereList: every group of eight spheres tested in turn, each lane keeping its own nearest hit: four lanes at a
// time in SSE2 (sphere_group.h), eight in AVX2 (sphere_list_avx2.h), a scalar loop elsewhere. A group half whose
// spheres all miss the ray's line (most of them, for any one ray) skips the square root and the division.
#include "trace/accel/sphere_list.h"

#include "shading/lighting.h"
#include "trace/accel/sphere_list_avx2.h"

namespace shadelab::trace {

SphereList::SphereList(const std::vector<Sphere>& spheres, BvhIsa isa)
    : count_(spheres.size()), avx2_(isa == BvhIsa::Avx2 && bvhIsaAvailable(BvhIsa::Avx2)) {
    groups_.assign((count_ + kSphereGroupLanes - 1) / kSphereGroupLanes, SphereGroup::empty());
    for (size_t k = 0; k < count_; ++k)
        groups_[k / kSphereGroupLanes].set(int(k % kSphereGroupLanes), glm::vec4(spheres[k].center, spheres[k].radius));
}

#ifdef SHADELAB_SIMD4_SSE2

std::optional<SphereHit> SphereList::closestHit(const Ray& ray, float tMin, float tMax) const {
    SphereHit best;
    if (avx2_)
        return closestSphereAvx2(groups_.data(), groups_.size(), ray, tMin, tMax, best) ? std::optional<SphereHit>(best)
                                                                                        : std::nullopt;
    const GroupRay r = groupRay(ray, tMin);
    // Each lane keeps its own nearest hit; scanning in scene order with a strict < keeps the lower index of an
    // exact tie within a lane, and the reduction below keeps it across lanes.
    __m128 bestT = _mm_set1_ps(tMax);
    __m128i bestIndex = _mm_set1_epi32(-1);
    __m128i index = _mm_set_epi32(3, 2, 1, 0);
    const __m128i four = _mm_set1_epi32(4);
    for (const SphereGroup& g : groups_)
        for (int half = 0; half < 2; ++half, index = _mm_add_epi32(index, four)) {
            const GroupReach q = reachGroup(r, g, half);
            if (!q.reached) continue;
            const __m128 t = finishGroup(r, q);
            const __m128 nearer = _mm_and_ps(_mm_cmpgt_ps(t, r.tMin), _mm_cmplt_ps(t, bestT));
            bestT = sphere_group_detail::select(nearer, t, bestT);
            bestIndex = _mm_castps_si128(
                sphere_group_detail::select(nearer, _mm_castsi128_ps(index), _mm_castsi128_ps(bestIndex)));
        }
    // Lanes without a hit kept index -1 (sign bit set); most rays hit nothing or one lane.
    unsigned hitLanes = ~unsigned(_mm_movemask_ps(_mm_castsi128_ps(bestIndex))) & 0xFu;
    if (hitLanes == 0) return std::nullopt;
    alignas(16) float ts[4];
    alignas(16) int32_t is[4];
    _mm_store_ps(ts, bestT);
    _mm_store_si128(reinterpret_cast<__m128i*>(is), bestIndex);
    best = SphereHit{tMax, UINT32_MAX};
    for (; hitLanes; hitLanes &= hitLanes - 1) {
        const int lane = __builtin_ctz(hitLanes);
        const uint32_t i = uint32_t(is[lane]);
        if (ts[lane] < best.t || (ts[lane] == best.t && i < best.index)) best = SphereHit{ts[lane], i};
    }
    return best.index == UINT32_MAX ? std::nullopt : std::optional<SphereHit>(best);
}

#else

std::optional<SphereHit> SphereList::closestHit(const Ray& ray, float tMin, float tMax) const {
    SphereHit best{tMax, UINT32_MAX};
    for (size_t k = 0; k < count_; ++k) {
        const SphereGroup& g = groups_[k / kSphereGroupLanes];
        const size_t l = k % kSphereGroupLanes;
        const float t =
            shading::intersectSphere(ray.origin, ray.dir, glm::vec3(g.cx[l], g.cy[l], g.cz[l]), g.r[l], tMin);
        if (t > tMin && t < best.t) best = SphereHit{t, uint32_t(k)};
    }
    return best.index == UINT32_MAX ? std::nullopt : std::optional<SphereHit>(best);
}

#endif

bool SphereList::anyHit(const Ray& ray, float tMin, float tMax) const {
    if (avx2_) return anySphereAvx2(groups_.data(), groups_.size(), ray, tMin, tMax);
    const GroupRay r = groupRay(ray, tMin);
    for (const SphereGroup& g : groups_)
        if (groupHitsAny(r, g, tMax)) return true;
    return false;
}

}  // namespace shadelab::trace
