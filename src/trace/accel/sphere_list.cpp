// SphereList: every group of four spheres tested in turn (sphere_group.h), each lane keeping its own nearest hit
// in SSE2; elsewhere a scalar loop over the same layout.
#include "trace/accel/sphere_list.h"

#include "shading/lighting.h"

namespace shadelab::trace {

SphereList::SphereList(const std::vector<Sphere>& spheres) : count_(spheres.size()) {
    groups_.assign((count_ + 3) / 4, SphereGroup::empty());
    for (size_t k = 0; k < count_; ++k) groups_[k / 4].set(int(k % 4), glm::vec4(spheres[k].center, spheres[k].radius));
}

#ifdef SHADELAB_SIMD4_SSE2

std::optional<SphereHit> SphereList::closestHit(const Ray& ray, float tMin, float tMax) const {
    const GroupRay r = groupRay(ray, tMin);
    // Each lane keeps its own nearest hit; scanning in scene order with a strict < keeps the lower index of an
    // exact tie within a lane, and the reduction below keeps it across lanes.
    __m128 bestT = _mm_set1_ps(tMax);
    __m128i bestIndex = _mm_set1_epi32(-1);
    __m128i index = _mm_set_epi32(3, 2, 1, 0);
    const __m128i four = _mm_set1_epi32(4);
    for (const SphereGroup& g : groups_) {
        const __m128 t = intersectGroup(r, g);
        const __m128 nearer = _mm_and_ps(_mm_cmpgt_ps(t, r.tMin), _mm_cmplt_ps(t, bestT));
        bestT = sphere_group_detail::select(nearer, t, bestT);
        bestIndex =
            _mm_castps_si128(sphere_group_detail::select(nearer, _mm_castsi128_ps(index), _mm_castsi128_ps(bestIndex)));
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

#else

std::optional<SphereHit> SphereList::closestHit(const Ray& ray, float tMin, float tMax) const {
    SphereHit best{tMax, UINT32_MAX};
    for (size_t k = 0; k < count_; ++k) {
        const SphereGroup& g = groups_[k / 4];
        const size_t l = k % 4;
        const float t =
            shading::intersectSphere(ray.origin, ray.dir, glm::vec3(g.cx[l], g.cy[l], g.cz[l]), g.r[l], tMin);
        if (t > tMin && t < best.t) best = SphereHit{t, uint32_t(k)};
    }
    return best.index == UINT32_MAX ? std::nullopt : std::optional<SphereHit>(best);
}

#endif

bool SphereList::anyHit(const Ray& ray, float tMin, float tMax) const {
    const GroupRay r = groupRay(ray, tMin);
    float t[4];
    for (const SphereGroup& g : groups_)
        if (groupHits(r, g, tMax, t)) return true;
    return false;
}

}  // namespace shadelab::trace
