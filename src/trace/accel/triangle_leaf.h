// The leaf tests of MeshBvh's two walks: a leaf's triangles (slots [first, first + count), positions in slot
// order) against one ray, keeping the nearest hit with its order-independent tie-break, or stopping at any hit.
// Templates on a tag type, like watertight.h's test, so the baseline walks (mesh_bvh.cpp) and the AVX2 ones
// (bvh_traverse_avx2.cpp) each inline their own copy into the node walk. The AVX2 walk tests a leaf's triangles
// four at a time and falls back to these loops only for a leaf with an edge function of exactly 0.
#pragma once

#include "trace/accel/leaf_positions.h"
#include "trace/accel/watertight.h"

#include <cstdint>

namespace shadelab::trace {

// What the leaf tests read of a MeshBvh: 9 floats per slot, by leaf (leaf_positions.h), and each slot's
// scene-order triangle index.
struct TriangleLeafData {
    const float* positions;
    const uint32_t* source;
};

// The nearest hit so far: t (the bound the walk prunes with), slot (UINT32_MAX: none yet), barycentrics.
struct TriangleLeafHit {
    float t;
    uint32_t slot;
    float b0, b1, b2;
};

template <typename Tag>
struct ClosestTriangleLeaf {
    TriangleLeafData data;
    WatertightRay wr;
    float tMax;            // hits must be nearer than this (0 < t < tMax)
    TriangleLeafHit best;  // starts as {tMax, UINT32_MAX, ...}

    float operator()(uint32_t first, uint32_t count) {
        const float* rows = data.positions + size_t(first) * 9;
        for (uint32_t j = 0; j < count; ++j) {
            const uint32_t s = first + j;
            float v[9];
            gatherLeafTriangle(rows, count, j, v);
            TriangleHit h;
            if (!intersectTriangleT<Tag>(wr, v, v + 3, v + 6, best.t, h)) continue;
            // Strictly nearer wins; an exact tie goes to the lower scene-order index.
            const bool better = best.slot == UINT32_MAX
                                    ? h.t < tMax
                                    : (h.t < best.t || (h.t == best.t && data.source[s] < data.source[best.slot]));
            if (better) best = TriangleLeafHit{h.t, s, h.b0, h.b1, h.b2};
        }
        return best.t;
    }
};

template <typename Tag>
struct AnyTriangleLeaf {
    TriangleLeafData data;
    WatertightRay wr;
    float tMax;  // hits must be nearer than this

    bool operator()(uint32_t first, uint32_t count) const {
        const float* rows = data.positions + size_t(first) * 9;
        for (uint32_t j = 0; j < count; ++j) {
            float v[9];
            gatherLeafTriangle(rows, count, j, v);
            TriangleHit h;
            if (intersectTriangleT<Tag>(wr, v, v + 3, v + 6, tMax, h) && h.t < tMax) return true;
        }
        return false;
    }
};

}  // namespace shadelab::trace
