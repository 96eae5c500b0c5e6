// The AVX2 single-ray walks of MeshBvh (bvh_traverse_avx2.h). This file is compiled with -mavx2 -mfma
// (src/trace/CMakeLists.txt). The walks are bvh_traverse.h's templates instantiated with this file's lambdas and
// bvh_avx2_lanes.h's box and leaf tests, which have internal linkage, so no code built for AVX2 leaks into the
// baseline.
#include "trace/accel/bvh_traverse_avx2.h"

#include "trace/accel/bvh_avx2_lanes.h"
#include "trace/accel/bvh_traverse.h"

#include <cstdlib>

namespace shadelab::trace {

#if defined(__AVX2__)

void closestTriangleAvx2(const BvhNode* nodes, const Ray& ray, TriangleLeafData data, TriangleLeafHit& best) {
    __m128 o, d;
    loadRay(ray, o, d);
    const BoxRay8 r = makeBoxRay8(o, reciprocals(d));
    ClosestTriangleLeaf4 leaf{makeLeafRay4(o, d), ray, data, best.t, best};
    if (r.fused)
        traverseClosestWith(
            nodes, best.t, [&r](const BvhNode& n, float t, float* tn) { return hitsFused8(r, n.bounds, t, tn); }, leaf);
    else
        traverseClosestWith(
            nodes, best.t, [&r](const BvhNode& n, float t, float* tn) { return hitsExact8(r, n.bounds, t, tn); }, leaf);
    best = leaf.best;
}

bool anyTriangleAvx2(const BvhNode* nodes, const Ray& ray, TriangleLeafData data, float tMax) {
    __m128 o, d;
    loadRay(ray, o, d);
    const BoxRay8 r = makeBoxRay8(o, reciprocals(d));
    const AnyTriangleLeaf4 leaf{makeLeafRay4(o, d), ray, data, tMax};
    if (r.fused)
        return traverseAnyWith(
            nodes, tMax, [&r](const BvhNode& n, float t, float* tn) { return hitsFused8(r, n.bounds, t, tn); }, leaf);
    return traverseAnyWith(
        nodes, tMax, [&r](const BvhNode& n, float t, float* tn) { return hitsExact8(r, n.bounds, t, tn); }, leaf);
}

void rayConstantsAvx2(const Ray& ray, BoxRay& box, WatertightRay& wt) {
    __m128 o, d;
    loadRay(ray, o, d);
    const BoxRay8 r = makeBoxRay8(o, reciprocals(d));
    alignas(16) float org[4], inv[4];
    _mm_store_ps(org, r.org);
    _mm_store_ps(inv, r.inv);
    for (int a = 0; a < 3; ++a) {
        box.org[a] = org[a];
        box.invDir[a] = inv[a];
        box.nearIdx[a] = int(r.off[a] / sizeof(float[8]));
        box.farIdx[a] = int(r.off[3 + a] / sizeof(float[8]));
    }
    wt = scalarWatertightRay(makeLeafRay4(o, d), ray);
}

int slabHits8Avx2(const BoxRay& ray, const float (*bounds)[8], float tMax, float* tNear) {
    alignas(32) float t[8];
    const BoxRay8 r = makeBoxRay8(_mm_setr_ps(ray.org[0], ray.org[1], ray.org[2], 0.0f),
                                  _mm_setr_ps(ray.invDir[0], ray.invDir[1], ray.invDir[2], 1.0f));
    const int m = r.fused ? hitsFused8(r, bounds, tMax, t) : hitsExact8(r, bounds, tMax, t);
    for (int k = 0; k < 8; ++k) tNear[k] = t[k];
    return m;
}

#else  // built without AVX2: bvhIsaAvailable(BvhIsa::Avx2) is false, so nothing calls these

void closestTriangleAvx2(const BvhNode*, const Ray&, TriangleLeafData, TriangleLeafHit&) { std::abort(); }
bool anyTriangleAvx2(const BvhNode*, const Ray&, TriangleLeafData, float) { std::abort(); }
void rayConstantsAvx2(const Ray&, BoxRay&, WatertightRay&) { std::abort(); }
int slabHits8Avx2(const BoxRay&, const float (*)[8], float, float*) { std::abort(); }

#endif

}  // namespace shadelab::trace
