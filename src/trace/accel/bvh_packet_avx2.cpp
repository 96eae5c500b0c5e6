// Packets of eight rays walked through MeshBvh's tree together (bvh_packet_avx2.h). This file is compiled with
// -mavx2 -mfma (src/trace/CMakeLists.txt); its code sits in an anonymous namespace and uses bvh_avx2_lanes.h's
// tests and bvh_packet_leaf_avx2.h's packet leaf tests, which have internal linkage, so no code built for AVX2
// leaks into the baseline.
#include "trace/accel/bvh_packet_avx2.h"

#include "trace/accel/bvh_avx2_lanes.h"
#include "trace/accel/bvh_packet_leaf_avx2.h"
#include "trace/accel/bvh_traverse_avx2.h"

#include <cstdlib>

namespace shadelab::trace {

#if defined(__AVX2__)

namespace {

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
    alignas(32) float lanes[6][8];  // ox oy oz dx dy dz of each ray
    gatherLanes(rays, valid, lanes);
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
    unsigned made = 0;
    LeafRay4 leaf[8];  // lane k valid where bit k of `made` is: left uninitialised, not zeroed per packet

    explicit PacketLeafRays(const Ray* r) : rays(r) {}

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

void closestTriangle8Avx2(const BvhNode* nodes, const Ray* rays, unsigned valid, TriangleLeafData data,
                          TriangleLeafHit* best) {
    PacketRay8 r;
    const unsigned packet = makePacket(rays, valid, r);
    for (unsigned alone = valid & 0xFFu & ~packet; alone; alone &= alone - 1) {
        const int k = __builtin_ctz(alone);
        closestTriangleAvx2(nodes, rays[k], data, best[k]);
    }
    if (!packet) return;
    PacketLeafRays leaf(rays);
    alignas(32) float bound[8], t[8];
    for (int k = 0; k < 8; ++k) bound[k] = t[k] = (packet >> k) & 1 ? best[k].t : -INFINITY;
    unsigned live = packet;
    PacketLeafState together;
    walkRays8(nodes, r, t, live, [&](uint32_t first, uint32_t count, unsigned lanes) {
        if (together.usable(rays, packet, lanes))
            lanes = closestInLeaf8(together.leaf, data, t, best, lanes, first, count);
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
    PacketLeafRays leaf(rays);
    alignas(32) float t[8];
    for (int k = 0; k < 8; ++k) t[k] = (packet >> k) & 1 ? tMax[k] : -INFINITY;
    unsigned live = packet;
    PacketLeafState together;
    walkRays8(nodes, r, t, live, [&](uint32_t first, uint32_t count, unsigned lanes) {
        if (together.usable(rays, packet, lanes)) {
            unsigned edge = 0;
            const unsigned hit = anyInLeaf8(together.leaf, data, t, lanes, first, count, edge);
            occluded |= hit;
            live &= ~hit;
            lanes = edge;
        }
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

#else  // built without AVX2: bvhIsaAvailable(BvhIsa::Avx2) is false, so nothing calls these

void closestTriangle8Avx2(const BvhNode*, const Ray*, unsigned, TriangleLeafData, TriangleLeafHit*) { std::abort(); }
unsigned anyTriangle8Avx2(const BvhNode*, const Ray*, const float*, unsigned, TriangleLeafData) { std::abort(); }

#endif

}  // namespace shadelab::trace
