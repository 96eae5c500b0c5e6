// Bvh: a binary bounding-volume hierarchy over boxes, built with binned SAH (MacDonald & Booth 1990 cost,
// Wald 2007 binning) and flattened into 32-byte nodes. It only sees boxes: the traversals live with the
// primitives (mesh_bvh.cpp for triangles, sphere_set.cpp for spheres).
#pragma once

#include "trace/slab_test.h"

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

namespace shadelab::trace {

// One node. Siblings are stored next to each other (left at `first`, right at `first + 1`) and pairs start
// at even indices, so with the 64-byte aligned array one cache line holds both children of a node.
struct alignas(32) BvhNode {
    float bounds[6];  // box: lo x, y, z then hi x, y, z, world units (indexable by slab side, see aabb.h)
    uint32_t first;   // interior: index of the left child; leaf: first primitive in Bvh::order
    uint32_t count;   // leaf: number of primitives (> 0); interior: 0

    bool isLeaf() const { return count != 0; }
    const float* lo() const { return bounds; }
    const float* hi() const { return bounds + 3; }
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes: two siblings per cache line");

// Minimal 64-byte aligned allocator for the node array.
template <class T>
struct CacheLineAllocator {
    using value_type = T;
    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) {}
    T* allocate(size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(64))); }
    void deallocate(T* p, size_t) { ::operator delete(p, std::align_val_t(64)); }
    template <class U>
    bool operator==(const CacheLineAllocator<U>&) const {
        return true;
    }
    template <class U>
    bool operator!=(const CacheLineAllocator<U>&) const {
        return false;
    }
};

struct BvhBuildOptions {
    int bins = 16;               // SAH candidate planes per axis are bins - 1
    int maxLeafSize = 4;         // leaves never hold more primitives than this
    float traversalCost = 1.0f;  // SAH cost of visiting a node, relative to one primitive test
};

// Deepest tree the builder makes; traversal stacks are sized from it.
inline constexpr int kMaxBvhDepth = 64;

struct Bvh {
    std::vector<BvhNode, CacheLineAllocator<BvhNode>> nodes;  // [0] root, [1] padding, then sibling pairs
    std::vector<uint32_t> order;                              // order[k]: the input primitive at leaf slot k
    int depth = 0;                                            // levels below the root, < kMaxBvhDepth

    bool empty() const { return order.empty(); }
};

// Builds over `boxes` (one per primitive, none empty). An empty input gives an empty Bvh.
Bvh buildBvh(const std::vector<Bounds>& boxes, const BvhBuildOptions& options = {});

// SAH cost of a built tree (for tests and tuning): Σ area(node)/area(root) weighted by visit/test cost.
float sahCost(const Bvh& bvh, const BvhBuildOptions& options = {});

}  // namespace shadelab::trace
