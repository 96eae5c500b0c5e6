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

// makeBoxRay's and makeWatertightRay's constants, the same bits, without their branches (which way a ray points
// is a coin toss for incoherent rays) and with the divisions in two vector ones: per-ray set-up showed up as a
// tenth of a profile of rays that miss everything.
struct RaySetup {
    BoxRay box;
    WatertightRay wt;
};

RaySetup setUpRay(const Ray& ray) {
    RaySetup s;
    const __m128 d = _mm_setr_ps(ray.dir.x, ray.dir.y, ray.dir.z, 1.0f);
    const __m128 o = _mm_setr_ps(ray.origin.x, ray.origin.y, ray.origin.z, 0.0f);
    const __m128 signBit = _mm_set1_ps(-0.0f);
    const __m128 ad = _mm_andnot_ps(signBit, d);
    // Slabs: 1/d, or ±1e30 where |d| <= 1e-30; the near side by the reciprocal's sign.
    const __m128 inv = _mm_blendv_ps(_mm_or_ps(_mm_and_ps(d, signBit), _mm_set1_ps(1e30f)),
                                     _mm_div_ps(_mm_set1_ps(1.0f), d), _mm_cmpgt_ps(ad, _mm_set1_ps(1e-30f)));
    alignas(16) float invs[4], abs[4], org[4];
    _mm_store_ps(invs, inv);
    _mm_store_ps(abs, ad);
    _mm_store_ps(org, o);
    const int invNeg = _mm_movemask_ps(_mm_cmplt_ps(inv, _mm_setzero_ps()));
    for (int a = 0; a < 3; ++a) {
        const int n = (invNeg >> a) & 1;
        s.box.org[a] = org[a];
        s.box.invDir[a] = invs[a];
        s.box.nearIdx[a] = a + 3 * n;
        s.box.farIdx[a] = a + 3 * (1 - n);
    }
    // Watertight: z is the axis of largest |d| (ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2)), x and y swapped
    // where d[z] < 0.
    static constexpr int8_t kKz[8] = {2, 1, 2, 1, 2, 2, 0, 0};                         // by (ax > ay, ax > az, ay > az)
    static constexpr int8_t kKx[6] = {1, 2, 2, 0, 0, 1}, kKy[6] = {2, 1, 0, 2, 1, 0};  // by (kz, d[kz] < 0)
    const int kz = kKz[(abs[0] > abs[1]) * 4 + (abs[0] > abs[2]) * 2 + (abs[1] > abs[2])];
    const int neg = (_mm_movemask_ps(_mm_cmplt_ps(d, _mm_setzero_ps())) >> kz) & 1;
    const int kx = kKx[2 * kz + neg], ky = kKy[2 * kz + neg];
    // (d[kx], d[ky], 1) / d[kz]: Sx, Sy, Sz; and the origin in (kx, ky, kz) order.
    alignas(16) float shear[4], permuted[4];
    _mm_store_ps(shear, _mm_div_ps(_mm_permutevar_ps(d, _mm_setr_epi32(kx, ky, 3, 3)),
                                   _mm_permutevar_ps(d, _mm_set1_epi32(kz))));
    _mm_store_ps(permuted, _mm_permutevar_ps(o, _mm_setr_epi32(kx, ky, kz, 3)));
    for (int a = 0; a < 3; ++a) s.wt.org[a] = org[a];
    s.wt.kx = kx;
    s.wt.ky = ky;
    s.wt.kz = kz;
    s.wt.Sx = shear[0];
    s.wt.Sy = shear[1];
    s.wt.Sz = shear[2];
    s.wt.ox = permuted[0];
    s.wt.oy = permuted[1];
    s.wt.oz = permuted[2];
    return s;
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
// Offsets are bytes into the node (size_t, so no store of the walk's uint32_t stack entries can alias them).
struct BoxRay8 {
    __m256 org[3], invDir[3], orgNear[3], orgFar[3];
    size_t nearOff[3], farOff[3];
    bool fused;  // the products are finite: hitsFused8 applies
};

BoxRay8 makeBoxRay8(const BoxRay& r) {
    BoxRay8 b;
    // o·r, then o·r ± (|o·r|·2^-23 + the least denormal): at least one ulp of o·r outward, so past the exact
    // product, whose rounding moved it at most half an ulp (zero included).
    const __m128 o = _mm_setr_ps(r.org[0], r.org[1], r.org[2], 0.0f);
    const __m128 inv = _mm_setr_ps(r.invDir[0], r.invDir[1], r.invDir[2], 0.0f);
    const __m128 p = _mm_mul_ps(o, inv);
    const __m128 absP = _mm_andnot_ps(_mm_set1_ps(-0.0f), p);
    const __m128 nudge = _mm_add_ps(_mm_mul_ps(absP, _mm_set1_ps(0x1p-23f)), _mm_set1_ps(0x1p-149f));
    alignas(16) float hi[4], lo[4];
    _mm_store_ps(hi, _mm_add_ps(p, nudge));
    _mm_store_ps(lo, _mm_sub_ps(p, nudge));
    const __m128 finite =
        _mm_and_ps(_mm_cmplt_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_load_ps(hi)), _mm_set1_ps(INFINITY)),
                   _mm_cmplt_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_load_ps(lo)), _mm_set1_ps(INFINITY)));
    b.fused = (_mm_movemask_ps(finite) & 7) == 7;
    for (int a = 0; a < 3; ++a) {
        b.org[a] = _mm256_set1_ps(r.org[a]);
        b.invDir[a] = _mm256_set1_ps(r.invDir[a]);
        b.orgNear[a] = _mm256_set1_ps(hi[a]);
        b.orgFar[a] = _mm256_set1_ps(lo[a]);
        b.nearOff[a] = size_t(r.nearIdx[a]) * sizeof(float[8]);
        b.farOff[a] = size_t(r.farIdx[a]) * sizeof(float[8]);
    }
    return b;
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
    return slabMask8(_mm256_fmsub_ps(boundsRow(b, r.nearOff[0]), r.invDir[0], r.orgNear[0]),
                     _mm256_fmsub_ps(boundsRow(b, r.nearOff[1]), r.invDir[1], r.orgNear[1]),
                     _mm256_fmsub_ps(boundsRow(b, r.nearOff[2]), r.invDir[2], r.orgNear[2]),
                     _mm256_fmsub_ps(boundsRow(b, r.farOff[0]), r.invDir[0], r.orgFar[0]),
                     _mm256_fmsub_ps(boundsRow(b, r.farOff[1]), r.invDir[1], r.orgFar[1]),
                     _mm256_fmsub_ps(boundsRow(b, r.farOff[2]), r.invDir[2], r.orgFar[2]), tMax, tNear);
}

// slabHits4's expression on eight lanes, operation for operation.
inline int hitsExact8(const BoxRay8& r, const float (*b)[8], float tMax, float* tNear) {
    auto t = [&](size_t off, int a) { return _mm256_mul_ps(_mm256_sub_ps(boundsRow(b, off), r.org[a]), r.invDir[a]); };
    return slabMask8(t(r.nearOff[0], 0), t(r.nearOff[1], 1), t(r.nearOff[2], 2), t(r.farOff[0], 0), t(r.farOff[1], 1),
                     t(r.farOff[2], 2), tMax, tNear);
}

// The watertight test (watertight.h) on up to four triangles of one leaf at once. The leaf's positions are
// contiguous (9 floats per slot); masked loads read each corner (never past the leaf), a permute puts its
// components in the ray's order (kx, ky, kz) and a transpose makes a lane per triangle. Every lane does the
// scalar test's operations in its order (sub, mul, add and div are exactly rounded, and this file is built
// with -ffp-contract=off), so a lane's t and barycentrics are the scalar test's bits. A leaf where any
// triangle's edge function rounds to exactly zero (the scalar test's double recomputation) is handed whole to
// the scalar loop.
struct LeafRay4 {
    __m128 ox, oy, oz, Sx, Sy, Sz;
    __m128i perm;  // (kx, ky, kz, 3): moves a corner's permuted components into lanes 0, 1, 2
};

LeafRay4 makeLeafRay4(const WatertightRay& w) {
    LeafRay4 r;
    r.ox = _mm_set1_ps(w.ox);
    r.oy = _mm_set1_ps(w.oy);
    r.oz = _mm_set1_ps(w.oz);
    r.Sx = _mm_set1_ps(w.Sx);
    r.Sy = _mm_set1_ps(w.Sy);
    r.Sz = _mm_set1_ps(w.Sz);
    r.perm = _mm_setr_epi32(w.kx, w.ky, w.kz, 3);
    return r;
}

struct Hits4 {
    __m128 t, b0, b1, b2;
};

// Bit k set: triangle k of the `count` (1..4) at `v` is hit at 0 < t <= tMax. -1: some lane needs the scalar
// test's double recomputation.
inline int triangles4(const LeafRay4& r, const float* v, uint32_t count, float tMax, Hits4& h) {
    const __m128 live = _mm_castsi128_ps(_mm_cmpgt_epi32(_mm_set1_epi32(int(count)), _mm_setr_epi32(0, 1, 2, 3)));
    const __m128 zero = _mm_setzero_ps();
    // Triangle i's corner c as (x, y, z) in the ray's permuted order; lanes past the count repeat the last one.
    const __m128i three = _mm_setr_epi32(-1, -1, -1, 0);
    const float* p[4];
    for (uint32_t i = 0; i < 4; ++i) p[i] = v + 9 * (i < count ? i : count - 1);
    __m128 k[3][3];  // [corner][x, y, z]
    for (int c = 0; c < 3; ++c) {
        __m128 r0 = _mm_permutevar_ps(_mm_maskload_ps(p[0] + 3 * c, three), r.perm);
        __m128 r1 = _mm_permutevar_ps(_mm_maskload_ps(p[1] + 3 * c, three), r.perm);
        __m128 r2 = _mm_permutevar_ps(_mm_maskload_ps(p[2] + 3 * c, three), r.perm);
        __m128 r3 = _mm_permutevar_ps(_mm_maskload_ps(p[3] + 3 * c, three), r.perm);
        const __m128 t0 = _mm_unpacklo_ps(r0, r1), t1 = _mm_unpacklo_ps(r2, r3);
        const __m128 t2 = _mm_unpackhi_ps(r0, r1), t3 = _mm_unpackhi_ps(r2, r3);
        k[c][0] = _mm_movelh_ps(t0, t1);
        k[c][1] = _mm_movehl_ps(t1, t0);
        k[c][2] = _mm_movelh_ps(t2, t3);
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

// The scalar loops for a leaf with an edge function of exactly 0: rare, so kept out of the walk's code.
__attribute__((noinline, cold)) float closestScalar(ClosestTriangleLeaf<Avx2Tag>& leaf, uint32_t first,
                                                    uint32_t count) {
    return leaf(first, count);
}
__attribute__((noinline, cold)) bool anyScalar(const AnyTriangleLeaf<Avx2Tag>& leaf, uint32_t first, uint32_t count) {
    return leaf(first, count);
}

// ClosestTriangleLeaf's answer, four triangles at a time: of the lanes hit, the nearest (lowest scene-order index
// on a tie) is then weighed against the best so far by the scalar leaf's own rule.
struct ClosestTriangleLeaf4 {
    LeafRay4 r;
    ClosestTriangleLeaf<Avx2Tag> scalar;  // the best so far, and the fallback

    float operator()(uint32_t first, uint32_t count) {
        TriangleLeafHit& best = scalar.best;
        Hits4 h;
        int m = triangles4(r, scalar.data.positions + size_t(first) * 9, count, best.t, h);
        if (m < 0) return closestScalar(scalar, first, count);
        if (m == 0) return best.t;
        alignas(16) float t[4], b0[4], b1[4], b2[4];
        _mm_store_ps(t, h.t);
        int k = __builtin_ctz(unsigned(m));
        for (m &= m - 1; m; m &= m - 1) {
            const int j = __builtin_ctz(unsigned(m));
            if (t[j] < t[k] || (t[j] == t[k] && scalar.data.source[first + j] < scalar.data.source[first + k])) k = j;
        }
        const uint32_t s = first + uint32_t(k);
        const bool better =
            best.slot == UINT32_MAX
                ? t[k] < scalar.tMax
                : (t[k] < best.t || (t[k] == best.t && scalar.data.source[s] < scalar.data.source[best.slot]));
        if (better) {
            _mm_store_ps(b0, h.b0);
            _mm_store_ps(b1, h.b1);
            _mm_store_ps(b2, h.b2);
            best = TriangleLeafHit{t[k], s, b0[k], b1[k], b2[k]};
        }
        return best.t;
    }
};

struct AnyTriangleLeaf4 {
    LeafRay4 r;
    AnyTriangleLeaf<Avx2Tag> scalar;

    bool operator()(uint32_t first, uint32_t count) const {
        Hits4 h;
        const int m = triangles4(r, scalar.data.positions + size_t(first) * 9, count, scalar.tMax, h);
        if (m < 0) return anyScalar(scalar, first, count);
        return (m & _mm_movemask_ps(_mm_cmplt_ps(h.t, _mm_set1_ps(scalar.tMax)))) != 0;
    }
};

}  // namespace

void closestTriangleAvx2(const BvhNode* nodes, const Ray& ray, TriangleLeafData data, TriangleLeafHit& best) {
    const RaySetup rs = setUpRay(ray);
    const BoxRay8 r = makeBoxRay8(rs.box);
    ClosestTriangleLeaf4 leaf{makeLeafRay4(rs.wt), ClosestTriangleLeaf<Avx2Tag>{data, rs.wt, best.t, best}};
    if (r.fused)
        traverseClosestWith(
            nodes, best.t, [&r](const BvhNode& n, float t, float* tn) { return hitsFused8(r, n.bounds, t, tn); }, leaf);
    else
        traverseClosestWith(
            nodes, best.t, [&r](const BvhNode& n, float t, float* tn) { return hitsExact8(r, n.bounds, t, tn); }, leaf);
    best = leaf.scalar.best;
}

bool anyTriangleAvx2(const BvhNode* nodes, const Ray& ray, TriangleLeafData data, float tMax) {
    const RaySetup rs = setUpRay(ray);
    const BoxRay8 r = makeBoxRay8(rs.box);
    const AnyTriangleLeaf4 leaf{makeLeafRay4(rs.wt), AnyTriangleLeaf<Avx2Tag>{data, rs.wt, tMax}};
    if (r.fused)
        return traverseAnyWith(
            nodes, tMax, [&r](const BvhNode& n, float t, float* tn) { return hitsFused8(r, n.bounds, t, tn); }, leaf);
    return traverseAnyWith(
        nodes, tMax, [&r](const BvhNode& n, float t, float* tn) { return hitsExact8(r, n.bounds, t, tn); }, leaf);
}

void rayConstantsAvx2(const Ray& ray, BoxRay& box, WatertightRay& wt) {
    const RaySetup rs = setUpRay(ray);
    box = rs.box;
    wt = rs.wt;
}

int slabHits8Avx2(const BoxRay& ray, const float (*bounds)[8], float tMax, float* tNear) {
    alignas(32) float t[8];
    const BoxRay8 r = makeBoxRay8(ray);
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
