// The AVX2 box test and MeshBvh's walks built on it (bvh_traverse_avx2.h). This file alone is compiled with
// -mavx2 (src/trace/CMakeLists.txt). Its own code sits in an anonymous namespace; the walks and leaf tests are
// bvh_traverse.h's and triangle_leaf.h's templates instantiated with lambdas and a tag of this file; it calls
// no other inline function (only builtins and intrinsics), so no code built for AVX2 leaks into the baseline.
#include "trace/bvh_traverse_avx2.h"

#include "trace/bvh_traverse.h"

#include <cstdlib>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace shadelab::trace {

#if defined(__AVX2__)

namespace {

// This file's own tag: the triangle-test templates instantiated here are this file's alone.
struct Avx2Tag {};

// The rows a ray reads, as byte offsets into the node (size_t, so no store of the walk's uint32_t stack entries
// can alias them and force a reload).
struct BoxRay8 {
    __m256 org[3], invDir[3];
    size_t nearOff[3], farOff[3];
};

BoxRay8 makeBoxRay8(const BoxRay& r) {
    BoxRay8 b;
    for (int a = 0; a < 3; ++a) {
        b.org[a] = _mm256_set1_ps(r.org[a]);
        b.invDir[a] = _mm256_set1_ps(r.invDir[a]);
        b.nearOff[a] = size_t(r.nearIdx[a]) * sizeof(float[8]);
        b.farOff[a] = size_t(r.farIdx[a]) * sizeof(float[8]);
    }
    return b;
}

// slabHits4's expression on eight lanes; the same operand order in every min and max, so NaN lanes agree too.
inline int hits8(const BoxRay8& r, const float (*bounds)[8], float tMax, float* tNear) {
    const char* b = reinterpret_cast<const char*>(bounds);
    auto row = [b](size_t off) { return _mm256_load_ps(reinterpret_cast<const float*>(b + off)); };
    const __m256 tx0 = _mm256_mul_ps(_mm256_sub_ps(row(r.nearOff[0]), r.org[0]), r.invDir[0]);
    const __m256 tx1 = _mm256_mul_ps(_mm256_sub_ps(row(r.farOff[0]), r.org[0]), r.invDir[0]);
    const __m256 ty0 = _mm256_mul_ps(_mm256_sub_ps(row(r.nearOff[1]), r.org[1]), r.invDir[1]);
    const __m256 ty1 = _mm256_mul_ps(_mm256_sub_ps(row(r.farOff[1]), r.org[1]), r.invDir[1]);
    const __m256 tz0 = _mm256_mul_ps(_mm256_sub_ps(row(r.nearOff[2]), r.org[2]), r.invDir[2]);
    const __m256 tz1 = _mm256_mul_ps(_mm256_sub_ps(row(r.farOff[2]), r.org[2]), r.invDir[2]);
    const __m256 tn = _mm256_max_ps(_mm256_max_ps(tx0, ty0), _mm256_max_ps(tz0, _mm256_setzero_ps()));
    const __m256 tf = _mm256_mul_ps(_mm256_min_ps(_mm256_min_ps(tx1, ty1), tz1), _mm256_set1_ps(kSlabFarScale));
    _mm256_store_ps(tNear, tn);
    return _mm256_movemask_ps(_mm256_cmp_ps(tn, _mm256_min_ps(tf, _mm256_set1_ps(tMax)), _CMP_LE_OS));
}

}  // namespace

void closestTriangleAvx2(const BvhNode* nodes, const BoxRay& boxRay, const WatertightRay& wr, TriangleLeafData data,
                         TriangleLeafHit& best) {
    const BoxRay8 r = makeBoxRay8(boxRay);
    ClosestTriangleLeaf<Avx2Tag> leaf{data, wr, best.t, best};
    traverseClosestWith(
        nodes, best.t, [r](const BvhNode& n, float t, float* tNear) { return hits8(r, n.bounds, t, tNear); }, leaf);
    best = leaf.best;
}

bool anyTriangleAvx2(const BvhNode* nodes, const BoxRay& boxRay, const WatertightRay& wr, TriangleLeafData data,
                     float tMax) {
    const BoxRay8 r = makeBoxRay8(boxRay);
    const AnyTriangleLeaf<Avx2Tag> leaf{data, wr, tMax};
    return traverseAnyWith(
        nodes, tMax, [r](const BvhNode& n, float t, float* tNear) { return hits8(r, n.bounds, t, tNear); }, leaf);
}

int slabHits8Avx2(const BoxRay& ray, const float (*bounds)[8], float tMax, float* tNear) {
    alignas(32) float t[8];
    const int m = hits8(makeBoxRay8(ray), bounds, tMax, t);
    for (int k = 0; k < 8; ++k) tNear[k] = t[k];
    return m;
}

#else  // built without AVX2: bvhIsaAvailable(BvhIsa::Avx2) is false, so nothing calls these

void closestTriangleAvx2(const BvhNode*, const BoxRay&, const WatertightRay&, TriangleLeafData, TriangleLeafHit&) {
    std::abort();
}
bool anyTriangleAvx2(const BvhNode*, const BoxRay&, const WatertightRay&, TriangleLeafData, float) { std::abort(); }
int slabHits8Avx2(const BoxRay&, const float (*)[8], float, float*) { std::abort(); }

#endif

}  // namespace shadelab::trace
