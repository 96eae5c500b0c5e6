// Structural checks of a built BVH for the tests (bvh_test.cpp, bvh_build_test.cpp): every primitive in exactly
// one leaf inside its box, children inside their parents, unused slots empty, the depth as reported. Test-only;
// not part of the library.
#pragma once

#include "scene/bounds.h"
#include "trace/accel/bvh.h"
#include "trace/accel/bvh_test_util.h"
#include "trace/accel/mesh_bvh.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace shadelab::trace::test {

inline Bounds box(glm::vec3 lo, glm::vec3 hi) { return Bounds{lo, hi}; }

inline Bounds childBox(const BvhNode& n, int k) {
    return box({n.bounds[0][k], n.bounds[1][k], n.bounds[2][k]}, {n.bounds[3][k], n.bounds[4][k], n.bounds[5][k]});
}

inline bool contains(const Bounds& outer, const Bounds& b) {
    for (int a = 0; a < 3; ++a)
        if (b.lo[a] < outer.lo[a] || b.hi[a] > outer.hi[a]) return false;
    return true;
}

inline bool overlaps(const Bounds& a, const Bounds& b) {
    for (int axis = 0; axis < 3; ++axis)
        if (a.hi[axis] < b.lo[axis] || b.hi[axis] < a.lo[axis]) return false;
    return true;
}

// Every primitive in exactly one leaf, leaves of 1..maxLeaf primitives inside their boxes, interior children's
// boxes inside their parent's box for them, unused children inverted and empty, every node reached once, and
// at most depth + 1 levels. `order[k]` is the primitive (index into boxes) at leaf slot k. With `references`,
// a primitive may sit in several leaves (spatial splits), each leaf's box need only overlap its box, and
// `leafBoxOf`, when given, receives each slot's leaf box.
inline ::testing::AssertionResult bvhIsValid(const Bvh& bvh, const std::vector<Bounds>& boxes, int maxLeaf,
                                             const std::vector<uint32_t>& order, bool references = false,
                                             std::vector<Bounds>* leafBoxOf = nullptr) {
    if (boxes.empty())
        return bvh.empty() ? ::testing::AssertionSuccess() : ::testing::AssertionFailure() << "not empty";
    if ((references ? order.size() < boxes.size() : order.size() != boxes.size()) || bvh.primitives != order.size())
        return ::testing::AssertionFailure() << "order has " << order.size();
    if (leafBoxOf) leafBoxOf->assign(order.size(), Bounds{});
    std::vector<int> seen(boxes.size(), 0);
    std::vector<int> reached(bvh.nodes.size(), 0);
    int levels = 0;
    struct Item {
        uint32_t node;
        Bounds box;
        int level;
    };
    std::vector<Item> stack{{0u, bvh.bounds, 1}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        if (it.node >= bvh.nodes.size() || reached[it.node]++)
            return ::testing::AssertionFailure() << "node " << it.node << " out of range or reached twice";
        levels = std::max(levels, it.level);
        const BvhNode& n = bvh.nodes[it.node];
        int used = 0;
        for (int k = 0; k < kBvhWidth; ++k) {
            const uint32_t ref = n.child[k];
            if (!n.used(k)) {
                if (ref != kLeafBit) return ::testing::AssertionFailure() << "unused child " << k << " has a reference";
                continue;
            }
            ++used;
            const Bounds b = childBox(n, k);
            if (!contains(it.box, b))
                return ::testing::AssertionFailure() << "node " << it.node << " child " << k << " outside its parent";
            if (!isLeafRef(ref)) {
                stack.push_back({ref, b, it.level + 1});
                continue;
            }
            const uint32_t first = leafFirst(ref), count = leafCount(ref);
            if (count == 0 || count > uint32_t(maxLeaf))
                return ::testing::AssertionFailure() << "leaf in node " << it.node << " holds " << count;
            if (size_t(first) + count > order.size()) return ::testing::AssertionFailure() << "leaf range";
            for (uint32_t s = first; s < first + count; ++s) {
                const uint32_t p = order[s];
                if (p >= boxes.size() || (seen[p]++ && !references))
                    return ::testing::AssertionFailure() << "primitive " << p << " twice";
                if (!(references ? overlaps(b, boxes[p]) : contains(b, boxes[p])))
                    return ::testing::AssertionFailure() << "leaf in node " << it.node << " misses box " << p;
                if (leafBoxOf) (*leafBoxOf)[s] = b;
            }
        }
        if (used == 0) return ::testing::AssertionFailure() << "node " << it.node << " has no children";
    }
    for (size_t i = 0; i < reached.size(); ++i)
        if (!reached[i]) return ::testing::AssertionFailure() << "node " << i << " unreachable";
    for (size_t p = 0; p < seen.size(); ++p)
        if (seen[p] == 0) return ::testing::AssertionFailure() << "primitive " << p << " in no leaf";
    if (levels > bvh.depth + 1 || bvh.depth >= kMaxBvhDepth)
        return ::testing::AssertionFailure() << levels << " levels vs reported depth " << bvh.depth;
    return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult bvhIsValid(const Bvh& bvh, const std::vector<Bounds>& boxes, int maxLeaf) {
    return bvhIsValid(bvh, boxes, maxLeaf, bvh.order);
}

inline std::vector<Bounds> boxesOf(const std::vector<SceneTri>& tris) {
    std::vector<Bounds> boxes(tris.size());
    for (size_t i = 0; i < tris.size(); ++i)
        for (int k = 0; k < 3; ++k) boxes[i].extend(glm::make_vec3(tris[i].v + 3 * k));
    return boxes;
}

// A piece of triangle `tri` (index into sceneTriangles()) and its box.
struct TrianglePiece {
    uint32_t tri;
    Bounds box;
};

// Whether the pieces cover their triangles: every point of a barycentric grid over each triangle lies, within
// `tolerance` world units, in the box of one of its pieces, and every triangle has a piece.
inline ::testing::AssertionResult piecesCover(const std::vector<SceneTri>& tris,
                                              const std::vector<TrianglePiece>& pieces, float tolerance) {
    std::vector<std::vector<Bounds>> of(tris.size());
    for (const TrianglePiece& p : pieces) {
        if (p.tri >= tris.size()) return ::testing::AssertionFailure() << "piece of triangle " << p.tri;
        of[p.tri].push_back(p.box);
    }
    constexpr int kGrid = 8;
    for (size_t t = 0; t < tris.size(); ++t) {
        const glm::vec3 a = glm::make_vec3(tris[t].v), b = glm::make_vec3(tris[t].v + 3),
                        c = glm::make_vec3(tris[t].v + 6);
        for (int i = 0; i <= kGrid; ++i)
            for (int j = 0; i + j <= kGrid; ++j) {
                const float u = float(i) / kGrid, v = float(j) / kGrid;
                const glm::vec3 q = (1.0f - u - v) * a + u * b + v * c;
                bool inside = false;
                for (const Bounds& box : of[t]) {
                    const Bounds grownBox{box.lo - glm::vec3(tolerance), box.hi + glm::vec3(tolerance)};
                    inside = inside || contains(grownBox, Bounds{q, q});
                }
                if (!inside)
                    return ::testing::AssertionFailure() << "triangle " << t << " (source " << tris[t].source
                                                         << ") is not covered at (" << u << ", " << v << ")";
            }
    }
    return ::testing::AssertionSuccess();
}

// A MeshBvh's structure over sceneTriangles() (which lists the kept triangles by source): every triangle in at
// least one leaf, each leaf holding one of its triangles overlapping that triangle's box, and the leaves holding
// a triangle together covering it (spatial splits may give it several).
inline ::testing::AssertionResult meshBvhIsValid(const MeshBvh& bvh, const std::vector<SceneTri>& tris, int maxLeaf) {
    if (bvh.triangleCount() != tris.size())
        return ::testing::AssertionFailure() << bvh.triangleCount() << " triangles kept, not " << tris.size();
    std::vector<uint32_t> order(bvh.slotCount());
    for (uint32_t s = 0; s < order.size(); ++s) {
        const auto it = std::lower_bound(tris.begin(), tris.end(), bvh.sourceTriangle(s),
                                         [](const SceneTri& t, uint32_t src) { return t.source < src; });
        order[s] = it != tris.end() && it->source == bvh.sourceTriangle(s) ? uint32_t(it - tris.begin()) : UINT32_MAX;
    }
    std::vector<Bounds> leafBoxes;
    const ::testing::AssertionResult structure = bvhIsValid(bvh.bvh(), boxesOf(tris), maxLeaf, order, true, &leafBoxes);
    if (!structure) return structure;
    std::vector<TrianglePiece> pieces;
    for (uint32_t s = 0; s < order.size(); ++s) pieces.push_back({order[s], leafBoxes[s]});
    return piecesCover(tris, pieces, 1e-5f * std::max(1.0f, glm::length(bvh.bounds().hi - bvh.bounds().lo)));
}

}  // namespace shadelab::trace::test
