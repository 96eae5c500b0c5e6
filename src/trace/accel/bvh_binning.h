// The builder's binning (bvh.cpp): a primitive reference's box as SSE lanes, boxes of four lanes, the binning grid
// of one range and the per-axis bins (Wald 2007, "On fast Construction of SAH-based Bounding Volume
// Hierarchies"). Included by bvh.cpp only; everything is inline.
#pragma once

#include "trace/accel/bvh.h"
#include "trace/accel/simd4.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace shadelab::trace::binning {

inline constexpr int kMaxBins = 32;

inline F4 primLo(const BvhPrim& p) { return keepLanes3(loadu4(p.lo)); }
inline F4 primHi(const BvhPrim& p) { return keepLanes3(loadu4(p.hi)); }
// Twice the box centre: the builder bins and partitions by it; its bounds are the "centroid bounds".
inline F4 primCentre2(const BvhPrim& p) { return primLo(p) + primHi(p); }

struct Box4 {
    F4 lo = splat4(INFINITY), hi = splat4(-INFINITY);
    void extend(F4 l, F4 h) {
        lo = min4(lo, l);
        hi = max4(hi, h);
    }
    void extend(const Box4& b) { extend(b.lo, b.hi); }
    float lane(bool high, int axis) const {
        float v[4];
        store4(v, high ? hi : lo);
        return v[axis];
    }
    // Surface area, 0 for an empty box (the SAH's probability measure): 2 (ex ey + ey ez + ez ex), summed in that
    // order in lane 0 without leaving the register (the sweeps call this for every bin).
    float area() const {
        if ((lessEqualMask(lo, hi) & 7) != 7) return 0.0f;
        const F4 e = hi - lo, p = e * rotate3(e);  // (ex ey, ey ez, ez ex)
        return lane0(splat4(2.0f) * ((p + rotate3(p)) + rotate3(rotate3(p))));
    }
};

// The binning grid of one range: per axis, bins over the doubled centres' extent.
struct Grid {
    F4 lo, scale, lastBin;  // lastBin: bins - 1 in every lane
    float loLane[3], scaleLane[3];
    bool axisOk[3];
    int bins;

    // Bin of a primitive per axis: trunc((c - lo) * scale), clamped to [0, bins - 1] before truncating (the
    // same bins as clamping the truncated integers, for finite boxes).
    void binsOf(const BvhPrim& p, int* out) const {
        truncate4(min4(max4((primCentre2(p) - lo) * scale, splat4(0.0f)), lastBin), out);
    }
    // Whether a primitive's bin on `axis` is at most `bin` (< bins - 1): the same float operations as binsOf
    // on one lane, unclamped (a value below 0 or past the last bin falls on the same side either way).
    bool atMost(const BvhPrim& p, int axis, int bin) const {
        return int(((p.lo[axis] + p.hi[axis]) - loLane[axis]) * scaleLane[axis]) <= bin;
    }
};

// Per axis and bin: the primitives' box and count. Only the first `bins` are set, so a range of a few
// primitives does not pay for initialising all kMaxBins.
struct Bins {
    F4 lo[3][kMaxBins], hi[3][kMaxBins];
    uint32_t count[3][kMaxBins];

    explicit Bins(int bins) {
        // All counts at once (a fixed size, so plain vector stores; a loop to `bins` became a slow `rep stos`
        // for the many small ranges), then the boxes of the bins in use.
        std::memset(count, 0, sizeof count);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < bins; ++b) {
                lo[a][b] = splat4(INFINITY);
                hi[a][b] = splat4(-INFINITY);
            }
    }
    void extend(int a, int b, F4 l, F4 h) {
        lo[a][b] = min4(lo[a][b], l);
        hi[a][b] = max4(hi[a][b], h);
        ++count[a][b];
    }
    void add(const Bins& o, int bins) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < bins; ++b) {
                lo[a][b] = min4(lo[a][b], o.lo[a][b]);
                hi[a][b] = max4(hi[a][b], o.hi[a][b]);
                count[a][b] += o.count[a][b];
            }
    }
};

inline void binPrims(const BvhPrim* prims, uint32_t n, const Grid& g, Bins& out) {
    int b[4];
    for (uint32_t i = 0; i < n; ++i) {
        const BvhPrim& p = prims[i];
        g.binsOf(p, b);
        const F4 lo = primLo(p), hi = primHi(p);
        for (int a = 0; a < 3; ++a) out.extend(a, b[a], lo, hi);
    }
}

}  // namespace shadelab::trace::binning
