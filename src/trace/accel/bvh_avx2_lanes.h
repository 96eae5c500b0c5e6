// The AVX2 building blocks of the BVH walks: a ray's box-test and watertight constants, the eight-box test (fused
// or exact), and the leaf tests of four triangles at once. Include it only from files compiled with -mavx2 -mfma
// -ffp-contract=off (bvh_traverse_avx2.cpp, bvh_packet_avx2.cpp; src/trace/CMakeLists.txt). Everything sits in an
// anonymous namespace, so each of those files gets its own copies and no code built for AVX2 can stand in for a
// baseline one at link time; the rest is builtins and intrinsics.
#pragma once

#include "trace/accel/bvh.h"
#include "trace/accel/slab_test.h"
#include "trace/accel/triangle_leaf.h"
#include "trace/accel/watertight.h"
#include "trace/ray.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>

namespace shadelab::trace {
namespace {

// Each including file's own tag (this header's anonymous namespace): the triangle-test templates it instantiates
// are that file's alone.
struct Avx2Tag {};

// Per-ray set-up. It is a third of the instructions of an incoherent ray that visits five nodes (callgrind), so
// it is built straight from the ray into what the walk reads, without branches (which way a ray points is a coin
// toss for incoherent rays) and without the scalar structs: the values are makeBoxRay's and makeWatertightRay's,
// bit for bit (BvhIsa.Avx2RayConstantsMatchTheScalarOnes), and only the cold scalar fallback rebuilds those.

// The ray as (ox, oy, oz, 0) and (dx, dy, dz, 1), from two overlapping 16-byte loads inside the 24-byte Ray.
static_assert(sizeof(Ray) == 24, "the loads below read a Ray as six packed floats");
inline void loadRay(const Ray& ray, __m128& o, __m128& d) {
    const __m128 head = _mm_loadu_ps(&ray.origin.x);  // ox oy oz dx
    const __m128 tail = _mm_loadu_ps(&ray.origin.z);  // oz dx dy dz
    o = _mm_blend_ps(head, _mm_setzero_ps(), 8);
    d = _mm_blend_ps(_mm_permute_ps(tail, _MM_SHUFFLE(0, 3, 2, 1)), _mm_set1_ps(1.0f), 8);
}

// makeBoxRay's reciprocals: 1/d, or ±1e30 where |d| <= 1e-30 (lane 3: 1).
inline __m128 reciprocals(__m128 d) {
    const __m128 signBit = _mm_set1_ps(-0.0f);
    return _mm_blendv_ps(_mm_or_ps(_mm_and_ps(d, signBit), _mm_set1_ps(1e30f)), _mm_div_ps(_mm_set1_ps(1.0f), d),
                         _mm_cmpgt_ps(_mm_andnot_ps(signBit, d), _mm_set1_ps(1e-30f)));
}

// Byte offsets into a node's bounds of each axis's near rows (0-2) and far rows (3-5), by the mask of negative
// reciprocals: slab_test.h's nearIdx/farIdx (lo x y z = rows 0-2, hi = 3-5), times a row's 32 bytes.
struct SlabOffsets {
    size_t off[8][6];
    constexpr SlabOffsets() : off() {
        for (int m = 0; m < 8; ++m)
            for (int a = 0; a < 3; ++a) {
                const int n = (m >> a) & 1;
                off[m][a] = size_t(a + 3 * n) * sizeof(float[8]);
                off[m][3 + a] = size_t(a + 3 * (1 - n)) * sizeof(float[8]);
            }
    }
};
alignas(64) constexpr SlabOffsets kSlabOffsets;

// Lane k of v in all eight lanes.
template <int k>
inline __m256 lane8(__m128 v) {
    return _mm256_broadcastss_ps(k == 0 ? v : _mm_permute_ps(v, _MM_SHUFFLE(k, k, k, k)));
}

// The box test with one fused multiply-subtract per slab: t = bound·invDir − org·invDir. Only the product
// org·invDir is rounded apart, so the per-ray constants are that product nudged outward: up by at least one ulp
// for the near slabs (orgNear >= org·invDir exactly), down for the far ones (orgFar <= it). Then each computed
// near distance lies at or below its exact value (bound − org)·invDir up to the one rounding of the fused
// operation, and each far one at or above it, so the test is at least as conservative as slab_test.h's
// (whose far scale, sized for three roundings, covers the two here: the fused one and invDir's). It sees every
// box that slabHits8 sees up to rounding, and its tNear may differ from slabHits8's in the last bits; the walks
// still find the same hits, which do not depend on visiting order (MeshBvh::closestHit). Where a product
// overflows (a huge origin times a clamped reciprocal) the fused form could meet inf − inf, so such a ray
// takes hitsExact8, slab_test.h's expression operation for operation.
struct BoxRay8 {
    __m256 invDir[3], orgNear[3], orgFar[3];
    __m128 org, inv;    // (x, y, z, 0) and the reciprocals: hitsExact8 broadcasts them itself (rare)
    const size_t* off;  // kSlabOffsets' row for this ray: near rows 0-2, far rows 3-5
    bool fused;         // the products are finite: hitsFused8 applies
};

// From the origin (x, y, z, 0) and makeBoxRay's reciprocals (x, y, z, anything finite).
inline BoxRay8 makeBoxRay8(__m128 o, __m128 inv) {
    BoxRay8 b;
    // o·r, then o·r ± (|o·r|·2^-23 + the least denormal): at least one ulp of o·r outward, so past the exact
    // product, whose rounding moved it at most half an ulp (zero included).
    const __m128 signBit = _mm_set1_ps(-0.0f);
    const __m128 p = _mm_mul_ps(o, inv);
    const __m128 nudge =
        _mm_add_ps(_mm_mul_ps(_mm_andnot_ps(signBit, p), _mm_set1_ps(0x1p-23f)), _mm_set1_ps(0x1p-149f));
    const __m128 hi = _mm_add_ps(p, nudge), lo = _mm_sub_ps(p, nudge);
    const __m128 biggest = _mm_max_ps(_mm_andnot_ps(signBit, hi), _mm_andnot_ps(signBit, lo));
    b.fused = (_mm_movemask_ps(_mm_cmplt_ps(biggest, _mm_set1_ps(INFINITY))) & 7) == 7;
    b.off = kSlabOffsets.off[_mm_movemask_ps(_mm_cmplt_ps(inv, _mm_setzero_ps())) & 7];
    b.org = o;
    b.inv = inv;
    b.invDir[0] = lane8<0>(inv), b.invDir[1] = lane8<1>(inv), b.invDir[2] = lane8<2>(inv);
    b.orgNear[0] = lane8<0>(hi), b.orgNear[1] = lane8<1>(hi), b.orgNear[2] = lane8<2>(hi);
    b.orgFar[0] = lane8<0>(lo), b.orgFar[1] = lane8<1>(lo), b.orgFar[2] = lane8<2>(lo);
    return b;
}

// The watertight test's constants (watertight.h) as the leaf test reads them: broadcast, and the axes
// (kx, ky, kz) whose rows the leaf test loads for the ray's x, y and z.
struct LeafRay4 {
    __m128 ox, oy, oz, Sx, Sy, Sz;
    const int32_t* axes;  // kAxisOrder's (kx, ky, kz, 3) for this ray
};

// Per (kz, d[kz] < 0): the permutation (kx, ky, kz, 3), the shear numerators' (kx, ky, 3, 3) and kz four times.
// z is the axis of largest |d|; x and y follow it cyclically, swapped where d[kz] < 0 (makeWatertightRay).
struct AxisOrder {
    alignas(16) int32_t perm[4];
    alignas(16) int32_t num[4];
    alignas(16) int32_t den[4];
};
constexpr AxisOrder kAxisOrder[6] = {
    {{1, 2, 0, 3}, {1, 2, 3, 3}, {0, 0, 0, 0}}, {{2, 1, 0, 3}, {2, 1, 3, 3}, {0, 0, 0, 0}},
    {{2, 0, 1, 3}, {2, 0, 3, 3}, {1, 1, 1, 1}}, {{0, 2, 1, 3}, {0, 2, 3, 3}, {1, 1, 1, 1}},
    {{0, 1, 2, 3}, {0, 1, 3, 3}, {2, 2, 2, 2}}, {{1, 0, 2, 3}, {1, 0, 3, 3}, {2, 2, 2, 2}},
};

inline LeafRay4 makeLeafRay4(__m128 o, __m128 d) {
    // kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2), from (ax > ay, ax > az, ay > az) in bits 0, 1, 2.
    static constexpr int8_t kKz[8] = {2, 2, 2, 0, 1, 2, 1, 0};
    const __m128 ad = _mm_andnot_ps(_mm_set1_ps(-0.0f), d);
    const int bits = _mm_movemask_ps(
        _mm_cmpgt_ps(_mm_permute_ps(ad, _MM_SHUFFLE(3, 1, 0, 0)), _mm_permute_ps(ad, _MM_SHUFFLE(3, 2, 2, 1))));
    const int kz = kKz[bits & 7];
    const int neg = (_mm_movemask_ps(_mm_cmplt_ps(d, _mm_setzero_ps())) >> kz) & 1;
    const AxisOrder& order = kAxisOrder[2 * kz + neg];
    LeafRay4 r;
    r.axes = order.perm;
    const __m128i perm = _mm_load_si128(reinterpret_cast<const __m128i*>(order.perm));
    // (d[kx], d[ky], 1) / d[kz]: Sx, Sy, Sz; and the origin in (kx, ky, kz) order.
    const __m128 shear = _mm_div_ps(_mm_permutevar_ps(d, _mm_load_si128(reinterpret_cast<const __m128i*>(order.num))),
                                    _mm_permutevar_ps(d, _mm_load_si128(reinterpret_cast<const __m128i*>(order.den))));
    const __m128 permuted = _mm_permutevar_ps(o, perm);
    r.Sx = _mm_permute_ps(shear, _MM_SHUFFLE(0, 0, 0, 0));
    r.Sy = _mm_permute_ps(shear, _MM_SHUFFLE(1, 1, 1, 1));
    r.Sz = _mm_permute_ps(shear, _MM_SHUFFLE(2, 2, 2, 2));
    r.ox = _mm_permute_ps(permuted, _MM_SHUFFLE(0, 0, 0, 0));
    r.oy = _mm_permute_ps(permuted, _MM_SHUFFLE(1, 1, 1, 1));
    r.oz = _mm_permute_ps(permuted, _MM_SHUFFLE(2, 2, 2, 2));
    return r;
}

// The scalar constants back from the vector ones: the fallback leaf loop and the tests read them.
WatertightRay scalarWatertightRay(const LeafRay4& r, const Ray& ray) {
    WatertightRay w;
    w.org[0] = ray.origin.x;
    w.org[1] = ray.origin.y;
    w.org[2] = ray.origin.z;
    w.kx = r.axes[0];
    w.ky = r.axes[1];
    w.kz = r.axes[2];
    w.Sx = _mm_cvtss_f32(r.Sx);
    w.Sy = _mm_cvtss_f32(r.Sy);
    w.Sz = _mm_cvtss_f32(r.Sz);
    w.ox = _mm_cvtss_f32(r.ox);
    w.oy = _mm_cvtss_f32(r.oy);
    w.oz = _mm_cvtss_f32(r.oz);
    return w;
}

inline __m256 boundsRow(const float (*bounds)[8], size_t off) {
    return _mm256_load_ps(reinterpret_cast<const float*>(reinterpret_cast<const char*>(bounds) + off));
}

// Both tests end alike: max(tx0, ty0, tz0, 0) <= min(min(tx1, ty1, tz1) · s, tMax), the same operand order in
// every min and max, so NaN lanes (inverted boxes) miss in both.
inline int slabMask8(__m256 tx0, __m256 ty0, __m256 tz0, __m256 tx1, __m256 ty1, __m256 tz1, float tMax, float* tNear) {
    const __m256 tn = _mm256_max_ps(_mm256_max_ps(tx0, ty0), _mm256_max_ps(tz0, _mm256_setzero_ps()));
    const __m256 tf = _mm256_mul_ps(_mm256_min_ps(_mm256_min_ps(tx1, ty1), tz1), _mm256_set1_ps(kSlabFarScale));
    _mm256_store_ps(tNear, tn);
    return _mm256_movemask_ps(_mm256_cmp_ps(tn, _mm256_min_ps(tf, _mm256_set1_ps(tMax)), _CMP_LE_OS));
}

inline int hitsFused8(const BoxRay8& r, const float (*b)[8], float tMax, float* tNear) {
    const size_t* off = r.off;
    return slabMask8(_mm256_fmsub_ps(boundsRow(b, off[0]), r.invDir[0], r.orgNear[0]),
                     _mm256_fmsub_ps(boundsRow(b, off[1]), r.invDir[1], r.orgNear[1]),
                     _mm256_fmsub_ps(boundsRow(b, off[2]), r.invDir[2], r.orgNear[2]),
                     _mm256_fmsub_ps(boundsRow(b, off[3]), r.invDir[0], r.orgFar[0]),
                     _mm256_fmsub_ps(boundsRow(b, off[4]), r.invDir[1], r.orgFar[1]),
                     _mm256_fmsub_ps(boundsRow(b, off[5]), r.invDir[2], r.orgFar[2]), tMax, tNear);
}

// slabHits4's expression on eight lanes, operation for operation.
inline int hitsExact8(const BoxRay8& r, const float (*b)[8], float tMax, float* tNear) {
    const __m256 org[3] = {lane8<0>(r.org), lane8<1>(r.org), lane8<2>(r.org)};
    auto t = [&](int row, int a) {
        return _mm256_mul_ps(_mm256_sub_ps(boundsRow(b, r.off[row]), org[a]), r.invDir[a]);
    };
    return slabMask8(t(0, 0), t(1, 1), t(2, 2), t(3, 0), t(4, 1), t(5, 2), tMax, tNear);
}

// The watertight test (watertight.h) on up to four triangles of one leaf at once. The leaf's positions are rows
// of a float per triangle (leaf_positions.h): one load per corner and axis, the axes in the ray's order
// (kx, ky, kz), makes a lane per triangle; the lanes past the count read the following floats and are masked
// off by `live` wherever they could matter. Every lane does the
// scalar test's operations in its order (sub, mul, add and div are exactly rounded, and this file is built
// with -ffp-contract=off), so a lane's t and barycentrics are the scalar test's bits. A leaf where any
// triangle's edge function rounds to exactly zero (the scalar test's double recomputation) is handed whole to
// the scalar loop.
struct Hits4 {
    __m128 t, b0, b1, b2;
};

// Bit k set: triangle k of the `count` (1..4) at `v` is hit at 0 < t <= tMax. -1: some lane needs the scalar
// test's double recomputation.
inline int triangles4(const LeafRay4& r, const float* v, uint32_t count, float tMax, Hits4& h) {
    const __m128 live = _mm_castsi128_ps(_mm_cmpgt_epi32(_mm_set1_epi32(int(count)), _mm_setr_epi32(0, 1, 2, 3)));
    const __m128 zero = _mm_setzero_ps();
    // Corner c's row for the ray's axis x, y or z: v + (3c + k·)·count.
    const size_t n = count, ox = size_t(r.axes[0]) * n, oy = size_t(r.axes[1]) * n, oz = size_t(r.axes[2]) * n;
    __m128 k[3][3];  // [corner][x, y, z]
    for (int c = 0; c < 3; ++c) {
        const float* row = v + 3 * size_t(c) * n;
        k[c][0] = _mm_loadu_ps(row + ox);
        k[c][1] = _mm_loadu_ps(row + oy);
        k[c][2] = _mm_loadu_ps(row + oz);
    }
    const __m128 Akx = _mm_sub_ps(k[0][0], r.ox), Aky = _mm_sub_ps(k[0][1], r.oy), Akz = _mm_sub_ps(k[0][2], r.oz);
    const __m128 Bkx = _mm_sub_ps(k[1][0], r.ox), Bky = _mm_sub_ps(k[1][1], r.oy), Bkz = _mm_sub_ps(k[1][2], r.oz);
    const __m128 Ckx = _mm_sub_ps(k[2][0], r.ox), Cky = _mm_sub_ps(k[2][1], r.oy), Ckz = _mm_sub_ps(k[2][2], r.oz);
    const __m128 Ax = _mm_sub_ps(Akx, _mm_mul_ps(r.Sx, Akz)), Ay = _mm_sub_ps(Aky, _mm_mul_ps(r.Sy, Akz));
    const __m128 Bx = _mm_sub_ps(Bkx, _mm_mul_ps(r.Sx, Bkz)), By = _mm_sub_ps(Bky, _mm_mul_ps(r.Sy, Bkz));
    const __m128 Cx = _mm_sub_ps(Ckx, _mm_mul_ps(r.Sx, Ckz)), Cy = _mm_sub_ps(Cky, _mm_mul_ps(r.Sy, Ckz));
    const __m128 U = _mm_sub_ps(_mm_mul_ps(Cx, By), _mm_mul_ps(Cy, Bx));
    const __m128 V = _mm_sub_ps(_mm_mul_ps(Ax, Cy), _mm_mul_ps(Ay, Cx));
    const __m128 W = _mm_sub_ps(_mm_mul_ps(Bx, Ay), _mm_mul_ps(By, Ax));
    const __m128 onEdge = _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(U, zero), _mm_cmpeq_ps(V, zero)), _mm_cmpeq_ps(W, zero));
    if (_mm_movemask_ps(_mm_and_ps(onEdge, live))) return -1;
    const __m128 neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(U, zero), _mm_cmplt_ps(V, zero)), _mm_cmplt_ps(W, zero));
    const __m128 pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(U, zero), _mm_cmpgt_ps(V, zero)), _mm_cmpgt_ps(W, zero));
    // Most triangles of a leaf the ray reaches are missed by the edge test: stop before the division.
    __m128 ok = _mm_andnot_ps(_mm_and_ps(neg, pos), live);
    if (_mm_movemask_ps(ok) == 0) return 0;
    const __m128 det = _mm_add_ps(_mm_add_ps(U, V), W);
    const __m128 T = _mm_add_ps(_mm_add_ps(_mm_mul_ps(U, _mm_mul_ps(r.Sz, Akz)), _mm_mul_ps(V, _mm_mul_ps(r.Sz, Bkz))),
                                _mm_mul_ps(W, _mm_mul_ps(r.Sz, Ckz)));
    const __m128 rcpDet = _mm_div_ps(_mm_set1_ps(1.0f), det);
    h.t = _mm_mul_ps(T, rcpDet);
    h.b0 = _mm_mul_ps(U, rcpDet);
    h.b1 = _mm_mul_ps(V, rcpDet);
    h.b2 = _mm_mul_ps(W, rcpDet);
    // Kept: live, not straddling (signs mixed), det != 0, 0 < t <= tMax (ordered compares: NaN fails).
    ok = _mm_andnot_ps(_mm_cmpeq_ps(det, zero), ok);
    ok = _mm_and_ps(ok, _mm_cmpgt_ps(h.t, zero));
    ok = _mm_and_ps(ok, _mm_cmple_ps(h.t, _mm_set1_ps(tMax)));
    return _mm_movemask_ps(ok);
}

// The scalar loops for a leaf with an edge function of exactly 0: rare, so kept out of the walk's code, with the
// scalar ray constants they need made only here.
__attribute__((noinline, cold)) void closestScalar(const LeafRay4& r, const Ray& ray, TriangleLeafData data, float tMax,
                                                   TriangleLeafHit& best, uint32_t first, uint32_t count) {
    ClosestTriangleLeaf<Avx2Tag> leaf{data, scalarWatertightRay(r, ray), tMax, best};
    leaf(first, count);
    best = leaf.best;
}
__attribute__((noinline, cold)) bool anyScalar(const LeafRay4& r, const Ray& ray, TriangleLeafData data, float tMax,
                                               uint32_t first, uint32_t count) {
    return AnyTriangleLeaf<Avx2Tag>{data, scalarWatertightRay(r, ray), tMax}(first, count);
}

// ClosestTriangleLeaf's answer, four triangles at a time: of the lanes hit, the nearest (lowest scene-order index
// on a tie) is then weighed against the best so far by the scalar leaf's own rule. `tMax` is the ray's bound on
// entry (hits must be nearer), `best` the best so far; returns best.t.
inline float closestInLeaf(const LeafRay4& r, const Ray& ray, TriangleLeafData data, float tMax, TriangleLeafHit& best,
                           uint32_t first, uint32_t count) {
    Hits4 h;
    int m = triangles4(r, data.positions + size_t(first) * 9, count, best.t, h);
    if (m < 0) {
        closestScalar(r, ray, data, tMax, best, first, count);
        return best.t;
    }
    if (m == 0) return best.t;
    alignas(16) float t[4], b0[4], b1[4], b2[4];
    _mm_store_ps(t, h.t);
    int k = __builtin_ctz(unsigned(m));
    for (m &= m - 1; m; m &= m - 1) {
        const int j = __builtin_ctz(unsigned(m));
        if (t[j] < t[k] || (t[j] == t[k] && data.source[first + j] < data.source[first + k])) k = j;
    }
    const uint32_t s = first + uint32_t(k);
    const bool better = best.slot == UINT32_MAX
                            ? t[k] < tMax
                            : (t[k] < best.t || (t[k] == best.t && data.source[s] < data.source[best.slot]));
    if (better) {
        _mm_store_ps(b0, h.b0);
        _mm_store_ps(b1, h.b1);
        _mm_store_ps(b2, h.b2);
        best = TriangleLeafHit{t[k], s, b0[k], b1[k], b2[k]};
    }
    return best.t;
}

inline bool anyInLeaf(const LeafRay4& r, const Ray& ray, TriangleLeafData data, float tMax, uint32_t first,
                      uint32_t count) {
    Hits4 h;
    const int m = triangles4(r, data.positions + size_t(first) * 9, count, tMax, h);
    if (m < 0) return anyScalar(r, ray, data, tMax, first, count);
    return (m & _mm_movemask_ps(_mm_cmplt_ps(h.t, _mm_set1_ps(tMax)))) != 0;
}

struct ClosestTriangleLeaf4 {
    LeafRay4 r;
    const Ray& ray;
    TriangleLeafData data;
    float tMax;            // hits must be nearer than this
    TriangleLeafHit best;  // the best so far

    float operator()(uint32_t first, uint32_t count) { return closestInLeaf(r, ray, data, tMax, best, first, count); }
};

struct AnyTriangleLeaf4 {
    LeafRay4 r;
    const Ray& ray;
    TriangleLeafData data;
    float tMax;

    bool operator()(uint32_t first, uint32_t count) const { return anyInLeaf(r, ray, data, tMax, first, count); }
};

}  // namespace
}  // namespace shadelab::trace

#endif
