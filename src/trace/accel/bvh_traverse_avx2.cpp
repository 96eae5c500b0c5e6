// The AVX2 box test and MeshBvh's walks built on it (bvh_traverse_avx2.h). This file alone is compiled with
// -mavx2 (src/trace/CMakeLists.txt). Its own code sits in an anonymous namespace; the walks and leaf tests are
// bvh_traverse.h's and triangle_leaf.h's templates instantiated with lambdas and a tag of this file; it calls
// no other inline function (only builtins and intrinsics), so no code built for AVX2 leaks into the baseline.
#include "trace/accel/bvh_traverse_avx2.h"

#include "trace/accel/bvh_traverse.h"

#include <cstdlib>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace shadelab::trace {

#if defined(__AVX2__)

namespace {

// This file's own tag: the triangle-test templates instantiated here are this file's alone.
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

// ---- Packets: eight rays walked through the tree together ----
//
// Camera rays of neighbouring pixels, and their shadow rays toward one light, mostly visit the same nodes. A
// packet fetches and orders each node once for all its rays and tests a child box against the eight rays in one
// register (lane k: ray k), where the single-ray walk tests a node's eight boxes against one ray. A ray's box
// tests are the single-ray walk's (hitsFused8's fused multiply-subtract with the same nudged constants, on the
// box's lower or upper row as the ray's direction takes them), so a ray enters every node its own walk would;
// its leaves are tested by the single-ray leaf test, and a ray's answer, which does not depend on the order
// leaves are visited in, is its own walk's bit for bit. A ray whose products overflow (hitsExact8's case) leaves
// the packet and walks alone.

// Lane k of each row: ray k's constants. Rays not in the packet have tMax -inf in the walk, so they hit nothing.
struct PacketRay8 {
    __m256 inv[3], orgLo[3], orgHi[3];  // the lower row's constant and the upper row's, per axis
};

// Which of the packet's rays enter child `c` of `node` (bit k: ray k) at tNear <= its far distance and tMax;
// their entry distances in `tn`.
inline unsigned childHits8(const PacketRay8& r, const BvhNode& node, int c, __m256 tMax, __m256& tn) {
    __m256 nearT[3], farT[3];
    for (int a = 0; a < 3; ++a) {
        const __m256 lower = _mm256_fmsub_ps(_mm256_broadcast_ss(&node.bounds[a][c]), r.inv[a], r.orgLo[a]);
        const __m256 upper = _mm256_fmsub_ps(_mm256_broadcast_ss(&node.bounds[3 + a][c]), r.inv[a], r.orgHi[a]);
        nearT[a] = _mm256_min_ps(lower, upper);
        farT[a] = _mm256_max_ps(lower, upper);
    }
    tn = _mm256_max_ps(_mm256_max_ps(nearT[0], nearT[1]), _mm256_max_ps(nearT[2], _mm256_setzero_ps()));
    const __m256 tf =
        _mm256_mul_ps(_mm256_min_ps(_mm256_min_ps(farT[0], farT[1]), farT[2]), _mm256_set1_ps(kSlabFarScale));
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(tn, _mm256_min_ps(tf, tMax), _CMP_LE_OS)));
}

// The smallest of the lanes of v in `lanes` (not empty).
inline float minLane(__m256 v, unsigned lanes) {
    static constexpr uint32_t kBits[8] = {1, 2, 4, 8, 16, 32, 64, 128};
    const __m256i bit = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kBits));
    const __m256 in =
        _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(lanes)), bit), bit));
    __m256 m = _mm256_blendv_ps(_mm256_set1_ps(INFINITY), v, in);
    m = _mm256_min_ps(m, _mm256_permute2f128_ps(m, m, 1));
    m = _mm256_min_ps(m, _mm256_permute_ps(m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = _mm256_min_ps(m, _mm256_permute_ps(m, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm256_cvtss_f32(m);
}

// The largest of the lanes of v in `lanes` (not empty).
inline float maxLane(__m256 v, unsigned lanes) { return -minLane(_mm256_xor_ps(v, _mm256_set1_ps(-0.0f)), lanes); }

// The packet as one frustum, where its rays share the signs of their directions (camera rays of neighbouring
// pixels nearly always do, and shadow rays from them toward one light): then each slab's near and far rows are
// the same for every ray, and a child's box is tested once for all of them, eight children per register as in the
// single-ray walk. Its constants are the extremes of the rays' own: the least and greatest reciprocal, the largest
// near-row product and the least far-row one. Because a fused multiply-subtract rounds monotonically, the
// frustum's near distance fmsub(near, inv at its extreme, largest orgNear) is at most every ray's own, and its far
// distance at least every ray's, with no margin needed: a box some ray's own walk enters passes the frustum test.
struct Frustum8 {
    const size_t* off;  // kSlabOffsets' row for the shared signs: near rows 0-2, far rows 3-5
    __m256 invMin[3], invMax[3], orgNearMax[3], orgFarMin[3];
};

// False when the packet's rays do not share their directions' signs.
inline bool makeFrustum(const PacketRay8& r, unsigned packet, Frustum8& f) {
    int negative = 0;
    for (int a = 0; a < 3; ++a) {
        const unsigned neg =
            unsigned(_mm256_movemask_ps(_mm256_cmp_ps(r.inv[a], _mm256_setzero_ps(), _CMP_LT_OS))) & packet;
        if (neg != 0 && neg != packet) return false;
        if (neg) negative |= 1 << a;
    }
    f.off = kSlabOffsets.off[negative];
    for (int a = 0; a < 3; ++a) {
        const bool neg = (negative >> a) & 1;
        // PacketRay8's rows: the lower row's constant is orgNear where the reciprocal is positive.
        const __m256 orgNear = neg ? r.orgHi[a] : r.orgLo[a], orgFar = neg ? r.orgLo[a] : r.orgHi[a];
        f.invMin[a] = _mm256_set1_ps(minLane(r.inv[a], packet));
        f.invMax[a] = _mm256_set1_ps(maxLane(r.inv[a], packet));
        f.orgNearMax[a] = _mm256_set1_ps(maxLane(orgNear, packet));
        f.orgFarMin[a] = _mm256_set1_ps(minLane(orgFar, packet));
    }
    return true;
}

// The frustum against a node's eight child boxes: bit c set where some ray of the packet may enter child c at or
// before tMax (the largest of the rays' bounds); the frustum's entry distances in tNear. A product bound·inv is
// least at the least reciprocal where the bound is positive and at the greatest where it is negative (the sign
// bit picks: for -0 every choice gives a zero product), and greatest the other way round.
inline int frustumHits8(const Frustum8& f, const BvhNode& node, float tMax, float* tNear) {
    __m256 nearT[3], farT[3];
    for (int a = 0; a < 3; ++a) {
        const __m256 nearRow = boundsRow(node.bounds, f.off[a]), farRow = boundsRow(node.bounds, f.off[3 + a]);
        nearT[a] = _mm256_fmsub_ps(nearRow, _mm256_blendv_ps(f.invMin[a], f.invMax[a], nearRow), f.orgNearMax[a]);
        farT[a] = _mm256_fmsub_ps(farRow, _mm256_blendv_ps(f.invMax[a], f.invMin[a], farRow), f.orgFarMin[a]);
    }
    return slabMask8(nearT[0], nearT[1], nearT[2], farT[0], farT[1], farT[2], tMax, tNear);
}

// Walks the packet from the root: at each node the children some live ray enters are visited nearest first; a
// subtree waits on the stack with the rays that may enter it and is skipped when all of them have found something
// nearer. With a frustum (`frustum` not null) a node's eight children are first tested once for the whole packet,
// and only the children it may enter against each ray; without one each used child is tested against each ray.
// Either way a child carries exactly the rays whose own walks would enter it. `leaf(first, count, lanes)` tests a leaf
// for the rays `lanes` and may shorten `tMax` (closest hits) or clear bits of `live` (rays done); the walk ends with no
// live ray.
template <typename Leaf>
void walkPacket(const BvhNode* nodes, const PacketRay8& r, const Frustum8* frustum, __m256& tMax, unsigned& live,
                Leaf&& leaf) {
    struct Entry {
        uint32_t ref;
        unsigned lanes;
        float tEntry;
    };
    Entry stack[(kBvhWidth - 1) * kMaxBvhDepth + 1];
    int sp = 0;
    uint32_t ref = 0;
    unsigned lanes = live;
    float packetMax = maxLane(tMax, live);  // the frustum's bound: the largest tMax of the live rays
    for (;;) {
        if (!(ref & kLeafBit)) {
            const BvhNode& node = nodes[ref];
            Entry hit[kBvhWidth];
            int n = 0;
            // Insertion by entry distance: nearest first.
            auto insert = [&hit, &n](const Entry& e) {
                int i = n++;
                for (; i > 0 && hit[i - 1].tEntry > e.tEntry; --i) hit[i] = hit[i - 1];
                hit[i] = e;
            };
            if (frustum) {
                alignas(32) float tNear[kBvhWidth];
                for (unsigned m = unsigned(frustumHits8(*frustum, node, packetMax, tNear)); m; m &= m - 1) {
                    const int c = __builtin_ctz(m);
                    __m256 tn;
                    const unsigned entering = lanes & childHits8(r, node, c, tMax, tn);
                    if (entering) insert(Entry{node.child[c], entering, minLane(tn, entering)});
                }
            } else {
                unsigned used = unsigned(_mm256_movemask_ps(
                    _mm256_cmp_ps(_mm256_load_ps(node.bounds[0]), _mm256_load_ps(node.bounds[3]), _CMP_LE_OQ)));
                for (; used; used &= used - 1) {
                    const int c = __builtin_ctz(used);
                    __m256 tn;
                    const unsigned m = childHits8(r, node, c, tMax, tn) & lanes;
                    if (m) insert(Entry{node.child[c], m, minLane(tn, m)});
                }
            }
            if (n > 0) {
                for (int i = n - 1; i > 0; --i) {
                    if (!(hit[i].ref & kLeafBit)) {
                        const char* p = reinterpret_cast<const char*>(nodes + hit[i].ref);
                        for (int line = 0; line < 4; ++line) __builtin_prefetch(p + 64 * line);
                    }
                    stack[sp++] = hit[i];
                }
                ref = hit[0].ref;
                lanes = hit[0].lanes;
                continue;
            }
        } else {
            leaf((ref & ~kLeafBit) >> 4, ref & 15u, lanes);
            if (!live) return;
            if (frustum) packetMax = maxLane(tMax, live);
        }
        // The next subtree that some of its rays may still need: entered no farther than their best so far.
        for (;;) {
            if (sp == 0) return;
            const Entry& e = stack[--sp];
            lanes = e.lanes & live &
                    unsigned(_mm256_movemask_ps(_mm256_cmp_ps(_mm256_set1_ps(e.tEntry), tMax, _CMP_LE_OS)));
            if (lanes) {
                ref = e.ref;
                break;
            }
        }
    }
}

// The packet's lanes: the rays of `valid` that can walk together (bit k), their box-test constants in `r`, all
// eight lanes at once: reciprocals() and makeBoxRay8's nudged products, lane for lane the same operations. The
// rays whose products overflow (hitsExact8's case) are left to the caller.
inline unsigned makePacket(const Ray* rays, unsigned valid, PacketRay8& r) {
    alignas(32) float lanes[6][8] = {};  // ox oy oz dx dy dz of each ray
    for (unsigned v = valid & 0xFFu; v; v &= v - 1) {
        const int k = __builtin_ctz(v);
        lanes[0][k] = rays[k].origin.x, lanes[1][k] = rays[k].origin.y, lanes[2][k] = rays[k].origin.z;
        lanes[3][k] = rays[k].dir.x, lanes[4][k] = rays[k].dir.y, lanes[5][k] = rays[k].dir.z;
    }
    const __m256 signBit = _mm256_set1_ps(-0.0f);
    __m256 finite = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
    for (int a = 0; a < 3; ++a) {
        const __m256 o = _mm256_load_ps(lanes[a]), d = _mm256_load_ps(lanes[3 + a]);
        const __m256 inv = _mm256_blendv_ps(
            _mm256_or_ps(_mm256_and_ps(d, signBit), _mm256_set1_ps(1e30f)), _mm256_div_ps(_mm256_set1_ps(1.0f), d),
            _mm256_cmp_ps(_mm256_andnot_ps(signBit, d), _mm256_set1_ps(1e-30f), _CMP_GT_OS));
        const __m256 p = _mm256_mul_ps(o, inv);
        const __m256 nudge = _mm256_add_ps(_mm256_mul_ps(_mm256_andnot_ps(signBit, p), _mm256_set1_ps(0x1p-23f)),
                                           _mm256_set1_ps(0x1p-149f));
        const __m256 hi = _mm256_add_ps(p, nudge), lo = _mm256_sub_ps(p, nudge);
        const __m256 biggest = _mm256_max_ps(_mm256_andnot_ps(signBit, hi), _mm256_andnot_ps(signBit, lo));
        finite = _mm256_and_ps(finite, _mm256_cmp_ps(biggest, _mm256_set1_ps(INFINITY), _CMP_LT_OS));
        // The lower row is the near slab where the reciprocal is positive (orgNear = hi), the far one where it is
        // negative (orgFar = lo).
        const __m256 negative = _mm256_cmp_ps(inv, _mm256_setzero_ps(), _CMP_LT_OS);
        r.inv[a] = inv;
        r.orgLo[a] = _mm256_blendv_ps(hi, lo, negative);
        r.orgHi[a] = _mm256_blendv_ps(lo, hi, negative);
    }
    return valid & 0xFFu & unsigned(_mm256_movemask_ps(finite));
}

// The watertight constants of the packet's rays, made when a ray first reaches a leaf (most camera rays of a
// model on a background reach none).
struct PacketLeafRays {
    const Ray* rays;
    LeafRay4 leaf[8];
    unsigned made = 0;

    const LeafRay4& operator[](int k) {
        if (!((made >> k) & 1)) {
            __m128 o, d;
            loadRay(rays[k], o, d);
            leaf[k] = makeLeafRay4(o, d);
            made |= 1u << k;
        }
        return leaf[k];
    }
};

// Walks the rays `live` (on entry: the packet) with bounds t[8], -inf in the lanes outside the packet (they enter
// nothing). `leaf(first, count, lanes)` may lower t[k] (closest hits) or clear bits of `live`; the walk reloads
// the bounds after each leaf.
template <typename Leaf>
void walkRays8(const BvhNode* nodes, const PacketRay8& r, float* t, unsigned& live, Leaf&& leaf) {
    __m256 tMax = _mm256_load_ps(t);
    Frustum8 f;
    const Frustum8* frustum = makeFrustum(r, live, f) ? &f : nullptr;
    walkPacket(nodes, r, frustum, tMax, live, [&](uint32_t first, uint32_t count, unsigned lanes) {
        leaf(first, count, lanes);
        tMax = _mm256_load_ps(t);
    });
}

}  // namespace

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

void closestTriangle8Avx2(const BvhNode* nodes, const Ray* rays, unsigned valid, TriangleLeafData data,
                          TriangleLeafHit* best) {
    PacketRay8 r;
    const unsigned packet = makePacket(rays, valid, r);
    for (unsigned alone = valid & 0xFFu & ~packet; alone; alone &= alone - 1) {
        const int k = __builtin_ctz(alone);
        closestTriangleAvx2(nodes, rays[k], data, best[k]);
    }
    if (!packet) return;
    PacketLeafRays leaf{rays, {}, 0};
    alignas(32) float bound[8], t[8];
    for (int k = 0; k < 8; ++k) bound[k] = t[k] = (packet >> k) & 1 ? best[k].t : -INFINITY;
    unsigned live = packet;
    walkRays8(nodes, r, t, live, [&](uint32_t first, uint32_t count, unsigned lanes) {
        for (; lanes; lanes &= lanes - 1) {
            const int k = __builtin_ctz(lanes);
            t[k] = closestInLeaf(leaf[k], rays[k], data, bound[k], best[k], first, count);
        }
    });
}

unsigned anyTriangle8Avx2(const BvhNode* nodes, const Ray* rays, const float* tMax, unsigned valid,
                          TriangleLeafData data) {
    PacketRay8 r;
    const unsigned packet = makePacket(rays, valid, r);
    unsigned occluded = 0;
    for (unsigned alone = valid & 0xFFu & ~packet; alone; alone &= alone - 1) {
        const int k = __builtin_ctz(alone);
        if (anyTriangleAvx2(nodes, rays[k], data, tMax[k])) occluded |= 1u << k;
    }
    if (!packet) return occluded;
    PacketLeafRays leaf{rays, {}, 0};
    alignas(32) float t[8];
    for (int k = 0; k < 8; ++k) t[k] = (packet >> k) & 1 ? tMax[k] : -INFINITY;
    unsigned live = packet;
    walkRays8(nodes, r, t, live, [&](uint32_t first, uint32_t count, unsigned lanes) {
        for (; lanes; lanes &= lanes - 1) {
            const int k = __builtin_ctz(lanes);
            if (anyInLeaf(leaf[k], rays[k], data, t[k], first, count)) {
                occluded |= 1u << k;
                live &= ~(1u << k);
            }
        }
    });
    return occluded;
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
void closestTriangle8Avx2(const BvhNode*, const Ray*, unsigned, TriangleLeafData, TriangleLeafHit*) { std::abort(); }
unsigned anyTriangle8Avx2(const BvhNode*, const Ray*, const float*, unsigned, TriangleLeafData) { std::abort(); }
bool anyTriangleAvx2(const BvhNode*, const Ray&, TriangleLeafData, float) { std::abort(); }
void rayConstantsAvx2(const Ray&, BoxRay&, WatertightRay&) { std::abort(); }
int slabHits8Avx2(const BoxRay&, const float (*)[8], float, float*) { std::abort(); }

#endif

}  // namespace shadelab::trace
