// The builder's spatial splits (bvh.h's design; bvh.cpp): the best spatial plane of a range, cutting the
// references that straddle the chosen one, moving a range up to make room, and packing the leaves at the end.
// Included by bvh.cpp only; everything is inline.
#pragma once

#include "trace/accel/bvh.h"
#include "trace/accel/bvh_binning.h"
#include "util/check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace shadelab::trace::spatial {

struct Plane {
    int bin = -1;  // -1: none; else the plane between bins `bin` and `bin + 1`
    float pos = 0.0f;
    float cost = INFINITY;  // SAH, in units of one primitive test
};

inline F4 lanesOf(const glm::vec3& v) { return set4(v.x, v.y, v.z, 0.0f); }

// The best spatial plane across `axis` (SBVH) for the `n` references at `prims` with box `box`: `bins` planes
// evenly over the box, each reference binned into every bin it crosses with the box of its part there
// (BvhReferenceSplitter::binParts), counted where it enters and where it leaves. Only planes that leave both
// sides with fewer references than the range, and cut no more references than `room`, are weighed.
inline Plane bestPlane(const BvhPrim* prims, uint32_t n, const binning::Box4& box, int axis, int bins, uint32_t room,
                       float traversalCost, const BvhReferenceSplitter& splitter) {
    using binning::Box4;
    using binning::kMaxBins;
    Plane best;
    const float lo = box.lane(false, axis), extent = box.lane(true, axis) - lo;
    const float scale = float(bins) / extent;
    if (!(extent > 0.0f) || !std::isfinite(scale)) return best;
    float planes[kMaxBins + 1];
    for (int k = 0; k <= bins; ++k) planes[k] = lo + extent * float(k) / float(bins);
    auto binOf = [&](float x) { return std::min(std::max(int((x - lo) * scale), 0), bins - 1); };
    // References within one bin by their boxes as lanes; the parts of the others in scalar boxes (binParts
    // writes them as floats, and a vector load of floats just stored would stall), joined after.
    Box4 boxes[kMaxBins];
    Bounds parts[kMaxBins];
    uint32_t entering[kMaxBins] = {}, leaving[kMaxBins] = {};
    for (uint32_t i = 0; i < n; ++i) {
        const BvhPrim& p = prims[i];
        const int first = binOf(p.lo[axis]), last = binOf(p.hi[axis]);
        ++entering[first];
        ++leaving[last];
        if (first == last)
            boxes[first].extend(binning::primLo(p), binning::primHi(p));
        else
            splitter.binParts(p, axis, planes, first, last, parts);
    }
    for (int k = 0; k < bins; ++k)
        if (!parts[k].empty()) boxes[k].extend(lanesOf(parts[k].lo), lanesOf(parts[k].hi));
    const float parentArea = box.area();
    float rightArea[kMaxBins];
    uint32_t rightCount[kMaxBins];
    Box4 acc;
    uint32_t cnt = 0;
    for (int b = bins - 1; b > 0; --b) {
        acc.extend(boxes[b]);
        cnt += leaving[b];
        rightArea[b] = acc.area();
        rightCount[b] = cnt;
    }
    acc = Box4();
    cnt = 0;
    for (int b = 0; b < bins - 1; ++b) {
        acc.extend(boxes[b]);
        cnt += entering[b];
        const uint32_t right = rightCount[b + 1];
        // Every reference enters at or left of b or leaves right of it, so cnt + right >= n.
        if (cnt == 0 || right == 0 || cnt >= n || right >= n || cnt + right - n > room) continue;
        const float cost = traversalCost + (acc.area() * float(cnt) + rightArea[b + 1] * float(right)) / parentArea;
        if (cost < best.cost) best = Plane{b, planes[b + 1], cost};
    }
    return best;
}

// Cuts the references in [begin, end) that straddle `pos` across `axis`, each into its part below (in its place)
// and above (appended after `end`, while there is room before `room`); returns the new end.
inline uint32_t cutStraddlers(BvhPrim* prims, uint32_t begin, uint32_t end, uint32_t room, int axis, float pos,
                              const BvhReferenceSplitter& splitter) {
    uint32_t out = end;
    for (uint32_t i = begin; i < end; ++i) {
        BvhPrim& p = prims[i];
        if (!(p.lo[axis] < pos && p.hi[axis] > pos)) continue;
        BvhPrim below, above;
        const int sides = splitter.split(p, axis, pos, below, above);
        if (sides == 3 && out < room) {
            p = below;
            prims[out++] = above;
        } else if (sides == 1) {
            p = below;
        } else if (sides == 2) {
            p = above;
        }
        // Both parts and no room left (the binning's count of straddlers can differ from the cut's by rounding),
        // or neither: the reference stays whole.
    }
    return out;
}

// Moves the range [begin, end) up by `by` places. The order within a range changes no node (the splits depend on
// the set of references), so only the references the shift uncovers move: from the front to past the end.
inline void shiftUp(BvhPrim* prims, uint32_t begin, uint32_t end, uint32_t by) {
    const uint32_t moved = std::min(by, end - begin);
    std::memcpy(static_cast<void*>(prims + end + by - moved), prims + begin, size_t(moved) * sizeof(BvhPrim));
}

// Moves the leaves' references to the front of the array in order, closing the gaps the ranges' unused room left,
// and renumbers the leaves; returns how many references there are. Every node's children must be in the order of
// their ranges: then a depth-first walk in slot order meets the leaves in array order, and each moves down at most.
template <class Nodes>
uint32_t packLeaves(Nodes& nodes, BvhPrim* prims) {
    struct Visit {
        uint32_t node;
        int slot;
    };
    Visit stack[kMaxBvhDepth + 1];
    int top = 0;
    stack[0] = Visit{0, 0};
    uint32_t packed = 0;
    while (top >= 0) {
        Visit& v = stack[top];
        if (v.slot == kBvhWidth) {
            --top;
            continue;
        }
        uint32_t& ref = nodes[v.node].child[v.slot++];
        if (!isLeafRef(ref)) {
            SHADELAB_CHECK_LT(top, kMaxBvhDepth);
            stack[++top] = Visit{ref, 0};
            continue;
        }
        const uint32_t first = leafFirst(ref), count = leafCount(ref);
        if (count == 0) continue;
        SHADELAB_CHECK_LE(packed, first);
        if (packed != first) std::memmove(static_cast<void*>(prims + packed), prims + first, count * sizeof(BvhPrim));
        ref = makeLeafRef(packed, count);
        packed += count;
    }
    return packed;
}

}  // namespace shadelab::trace::spatial
