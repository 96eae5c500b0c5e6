// The leaf tests of a packet of eight rays (bvh_packet_avx2.cpp): one triangle against the packet's rays per AVX
// step, for leaves that several of its rays reach together, and the rows of lanes both it and the packet's box
// constants are made from. Include it only from files compiled with -mavx2 -mfma -ffp-contract=off; as
// bvh_avx2_lanes.h, everything sits in an anonymous namespace, so no code built for AVX2 can stand in for a
// baseline one at link time.
#pragma once

#include "trace/accel/bvh_avx2_lanes.h"

#include <cstddef>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>

namespace shadelab::trace {
namespace {

// The rays of `valid` as rows of lanes: ox oy oz dx dy dz, lane k ray k, zeros elsewhere (stored as six vectors:
// an initialiser compiled to a `rep stos`, whose start-up cost showed in the packet's profile).
inline void gatherLanes(const Ray* rays, unsigned valid, float (*lanes)[8]) {
    for (int row = 0; row < 6; ++row) _mm256_store_ps(lanes[row], _mm256_setzero_ps());
    for (unsigned v = valid & 0xFFu; v; v &= v - 1) {
        const int k = __builtin_ctz(v);
        lanes[0][k] = rays[k].origin.x, lanes[1][k] = rays[k].origin.y, lanes[2][k] = rays[k].origin.z;
        lanes[3][k] = rays[k].dir.x, lanes[4][k] = rays[k].dir.y, lanes[5][k] = rays[k].dir.z;
    }
}

// One triangle against the packet's rays, for leaves that several rays reach together: where all the packet's rays
// share the watertight test's axis order (the axis of largest |d| and the sign of that component, so the same
// kx, ky, kz), a triangle's corners are read once, broadcast, and tested against eight rays in one register
// (lane k: ray k), where the per-ray test runs four triangles against one ray. Each lane does the scalar test's
// operations in its order on its own ray's constants (makeWatertightRay's, from the same exactly rounded
// divisions), so a lane's t and barycentrics are that ray's bits, and the triangles are taken in leaf order
// with ClosestTriangleLeaf's rule, so each ray keeps the hit its own walk keeps. A ray that meets an edge
// function of exactly 0 in a leaf leaves the packet's test for that leaf and takes the per-ray one, as a ray alone
// would (the scalar test's double recomputation).
struct PacketLeaf8 {
    const int32_t* axes;  // kAxisOrder's (kx, ky, kz, 3), shared by the packet's rays
    __m256 ox, oy, oz, Sx, Sy, Sz;
};

// False when the rays of `packet` do not share their axis order.
inline bool makePacketLeaf(const Ray* rays, unsigned packet, PacketLeaf8& p) {
    alignas(32) float lanes[6][8];  // ox oy oz dx dy dz of each ray
    gatherLanes(rays, packet, lanes);
    const __m256 signBit = _mm256_set1_ps(-0.0f);
    const __m256 d[3] = {_mm256_load_ps(lanes[3]), _mm256_load_ps(lanes[4]), _mm256_load_ps(lanes[5])};
    const __m256 ax = _mm256_andnot_ps(signBit, d[0]), ay = _mm256_andnot_ps(signBit, d[1]),
                 az = _mm256_andnot_ps(signBit, d[2]);
    // makeWatertightRay's kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2), lane by lane.
    const __m256 xy = _mm256_cmp_ps(ax, ay, _CMP_GT_OQ);
    const unsigned kz0 = unsigned(_mm256_movemask_ps(_mm256_and_ps(xy, _mm256_cmp_ps(ax, az, _CMP_GT_OQ)))) & packet;
    const unsigned kz1 = unsigned(_mm256_movemask_ps(_mm256_andnot_ps(xy, _mm256_cmp_ps(ay, az, _CMP_GT_OQ)))) & packet;
    int kz;
    if (kz0 == packet)
        kz = 0;
    else if (kz1 == packet)
        kz = 1;
    else if ((kz0 | kz1) == 0)
        kz = 2;
    else
        return false;
    const unsigned neg = unsigned(_mm256_movemask_ps(_mm256_cmp_ps(d[kz], _mm256_setzero_ps(), _CMP_LT_OQ))) & packet;
    if (neg != 0 && neg != packet) return false;
    const AxisOrder& order = kAxisOrder[2 * kz + (neg ? 1 : 0)];
    p.axes = order.perm;
    const int kx = order.perm[0], ky = order.perm[1];
    p.Sx = _mm256_div_ps(d[kx], d[kz]);
    p.Sy = _mm256_div_ps(d[ky], d[kz]);
    p.Sz = _mm256_div_ps(_mm256_set1_ps(1.0f), d[kz]);
    p.ox = _mm256_load_ps(lanes[kx]);
    p.oy = _mm256_load_ps(lanes[ky]);
    p.oz = _mm256_load_ps(lanes[kz]);
    return true;
}

// Lane k set (all ones) where bit k of `lanes` is.
inline __m256 laneMask(unsigned lanes) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(lanes)), bit), bit));
}

// Triangle j of the leaf at `rows` (`count` triangles) against the lanes `active`: the lanes that hit it at
// 0 < t <= tMax (their t and scaled barycentrics in h, bit k: lane k), and in `edge` the lanes with an edge
// function of exactly 0, which are not tested further.
struct Hits8 {
    __m256 t, U, V, W, rcpDet;
};
inline unsigned triangle8(const PacketLeaf8& p, const float* rows, size_t count, uint32_t j, unsigned active,
                          __m256 tMax, unsigned& edge, Hits8& h) {
    const size_t ox = size_t(p.axes[0]) * count + j, oy = size_t(p.axes[1]) * count + j,
                 oz = size_t(p.axes[2]) * count + j;
    const float *a = rows, *b = rows + 3 * count, *c = rows + 6 * count;
    const __m256 Akx = _mm256_sub_ps(_mm256_broadcast_ss(a + ox), p.ox);
    const __m256 Aky = _mm256_sub_ps(_mm256_broadcast_ss(a + oy), p.oy);
    const __m256 Akz = _mm256_sub_ps(_mm256_broadcast_ss(a + oz), p.oz);
    const __m256 Bkx = _mm256_sub_ps(_mm256_broadcast_ss(b + ox), p.ox);
    const __m256 Bky = _mm256_sub_ps(_mm256_broadcast_ss(b + oy), p.oy);
    const __m256 Bkz = _mm256_sub_ps(_mm256_broadcast_ss(b + oz), p.oz);
    const __m256 Ckx = _mm256_sub_ps(_mm256_broadcast_ss(c + ox), p.ox);
    const __m256 Cky = _mm256_sub_ps(_mm256_broadcast_ss(c + oy), p.oy);
    const __m256 Ckz = _mm256_sub_ps(_mm256_broadcast_ss(c + oz), p.oz);
    const __m256 Ax = _mm256_sub_ps(Akx, _mm256_mul_ps(p.Sx, Akz)), Ay = _mm256_sub_ps(Aky, _mm256_mul_ps(p.Sy, Akz));
    const __m256 Bx = _mm256_sub_ps(Bkx, _mm256_mul_ps(p.Sx, Bkz)), By = _mm256_sub_ps(Bky, _mm256_mul_ps(p.Sy, Bkz));
    const __m256 Cx = _mm256_sub_ps(Ckx, _mm256_mul_ps(p.Sx, Ckz)), Cy = _mm256_sub_ps(Cky, _mm256_mul_ps(p.Sy, Ckz));
    const __m256 U = _mm256_sub_ps(_mm256_mul_ps(Cx, By), _mm256_mul_ps(Cy, Bx));
    const __m256 V = _mm256_sub_ps(_mm256_mul_ps(Ax, Cy), _mm256_mul_ps(Ay, Cx));
    const __m256 W = _mm256_sub_ps(_mm256_mul_ps(Bx, Ay), _mm256_mul_ps(By, Ax));
    const __m256 zero = _mm256_setzero_ps();
    const unsigned onEdge =
        active & unsigned(_mm256_movemask_ps(
                     _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(U, zero, _CMP_EQ_OQ), _mm256_cmp_ps(V, zero, _CMP_EQ_OQ)),
                                  _mm256_cmp_ps(W, zero, _CMP_EQ_OQ))));
    edge |= onEdge;
    active &= ~onEdge;
    const __m256 neg =
        _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(U, zero, _CMP_LT_OQ), _mm256_cmp_ps(V, zero, _CMP_LT_OQ)),
                     _mm256_cmp_ps(W, zero, _CMP_LT_OQ));
    const __m256 pos =
        _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(U, zero, _CMP_GT_OQ), _mm256_cmp_ps(V, zero, _CMP_GT_OQ)),
                     _mm256_cmp_ps(W, zero, _CMP_GT_OQ));
    active &= ~unsigned(_mm256_movemask_ps(_mm256_and_ps(neg, pos)));
    if (!active) return 0;
    const __m256 det = _mm256_add_ps(_mm256_add_ps(U, V), W);
    const __m256 T = _mm256_add_ps(
        _mm256_add_ps(_mm256_mul_ps(U, _mm256_mul_ps(p.Sz, Akz)), _mm256_mul_ps(V, _mm256_mul_ps(p.Sz, Bkz))),
        _mm256_mul_ps(W, _mm256_mul_ps(p.Sz, Ckz)));
    h.rcpDet = _mm256_div_ps(_mm256_set1_ps(1.0f), det);
    h.t = _mm256_mul_ps(T, h.rcpDet);
    h.U = U, h.V = V, h.W = W;
    // Kept: det != 0, 0 < t <= tMax (ordered compares: NaN fails).
    const __m256 ok =
        _mm256_and_ps(_mm256_andnot_ps(_mm256_cmp_ps(det, zero, _CMP_EQ_OQ), _mm256_cmp_ps(h.t, zero, _CMP_GT_OQ)),
                      _mm256_cmp_ps(h.t, tMax, _CMP_LE_OQ));
    return active & unsigned(_mm256_movemask_ps(ok));
}

// ClosestTriangleLeaf for the rays `lanes` at once: t[k] and best[k] as each ray's own leaf test leaves them
// (t[k] is best[k].t, and while best[k] has no slot it is the ray's bound), except for the lanes returned, which met an
// edge function of exactly 0 and are to be tested alone, from the state they had on entry (restored here).
inline unsigned closestInLeaf8(const PacketLeaf8& p, TriangleLeafData data, float* t, TriangleLeafHit* best,
                               unsigned lanes, uint32_t first, uint32_t count) {
    TriangleLeafHit entry[8];
    __builtin_memcpy(entry, best, sizeof(entry));
    const float* rows = data.positions + size_t(first) * 9;
    // Per lane: the best t, and the scene-order index of the best hit (0 when none yet: then only t < bound
    // counts, and t[k] = bound[k], so the tie rule below never fires).
    __m256 bestT = _mm256_load_ps(t);
    alignas(32) int32_t src[8] = {};
    for (unsigned v = lanes; v; v &= v - 1) {
        const int k = __builtin_ctz(v);
        if (best[k].slot != UINT32_MAX) src[k] = int32_t(data.source[best[k].slot]);
    }
    __m256i bestSrc = _mm256_load_si256(reinterpret_cast<const __m256i*>(src));
    unsigned edge = 0, active = lanes;
    for (uint32_t j = 0; j < count && active; ++j) {
        Hits8 h;
        unsigned hit = triangle8(p, rows, count, j, active, bestT, edge, h);
        active &= ~edge;
        if (!hit) continue;
        // Strictly nearer wins; an exact tie goes to the lower scene-order index.
        const __m256i s = _mm256_set1_epi32(int32_t(data.source[first + j]));
        const __m256 better = _mm256_or_ps(
            _mm256_cmp_ps(h.t, bestT, _CMP_LT_OQ),
            _mm256_and_ps(_mm256_cmp_ps(h.t, bestT, _CMP_EQ_OQ), _mm256_castsi256_ps(_mm256_cmpgt_epi32(bestSrc, s))));
        hit &= unsigned(_mm256_movemask_ps(better));
        if (!hit) continue;
        const __m256 take = laneMask(hit);
        bestT = _mm256_blendv_ps(bestT, h.t, take);
        bestSrc = _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(bestSrc), _mm256_castsi256_ps(s), take));
        alignas(32) float tt[8], b0[8], b1[8], b2[8];
        _mm256_store_ps(tt, h.t);
        _mm256_store_ps(b0, _mm256_mul_ps(h.U, h.rcpDet));
        _mm256_store_ps(b1, _mm256_mul_ps(h.V, h.rcpDet));
        _mm256_store_ps(b2, _mm256_mul_ps(h.W, h.rcpDet));
        for (; hit; hit &= hit - 1) {
            const int k = __builtin_ctz(hit);
            best[k] = TriangleLeafHit{tt[k], first + j, b0[k], b1[k], b2[k]};
        }
    }
    _mm256_store_ps(t, _mm256_blendv_ps(_mm256_load_ps(t), bestT, laneMask(lanes & ~edge)));
    for (unsigned v = edge; v; v &= v - 1) best[__builtin_ctz(v)] = entry[__builtin_ctz(v)];
    return edge;
}

// AnyTriangleLeaf for the rays `lanes` at once: the lanes with a hit nearer than their bound t[k]; in `edge` the
// lanes to test alone (an edge function of exactly 0).
inline unsigned anyInLeaf8(const PacketLeaf8& p, TriangleLeafData data, const float* t, unsigned lanes, uint32_t first,
                           uint32_t count, unsigned& edge) {
    const float* rows = data.positions + size_t(first) * 9;
    const __m256 tMax = _mm256_load_ps(t);
    unsigned occluded = 0, active = lanes;
    for (uint32_t j = 0; j < count && active; ++j) {
        Hits8 h;
        unsigned hit = triangle8(p, rows, count, j, active, tMax, edge, h);
        active &= ~edge;
        if (!hit) continue;
        hit &= unsigned(_mm256_movemask_ps(_mm256_cmp_ps(h.t, tMax, _CMP_LT_OQ)));
        occluded |= hit;
        active &= ~hit;
    }
    return occluded;
}

// The packet's leaf constants, made when a leaf is first reached by enough rays for the packet's test to pay.
struct PacketLeafState {
    PacketLeaf8 leaf;
    int shared = -1;  // -1 not yet known, 0 the rays' axis orders differ, 1 they share one

    bool usable(const Ray* rays, unsigned packet, unsigned lanes) {
        if (__builtin_popcount(lanes) < kPacketLeafMinRays) return false;
        if (shared < 0) shared = makePacketLeaf(rays, packet, leaf) ? 1 : 0;
        return shared == 1;
    }
    static constexpr int kPacketLeafMinRays = 3;
};

}  // namespace
}  // namespace shadelab::trace

#endif
