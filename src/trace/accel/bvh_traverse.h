// The two walks of the 8-wide BVH every primitive type shares: ordered closest-hit and early-out any-hit.
// Primitive tests come in as leaf callbacks, so triangles (mesh_bvh.cpp) and spheres (sphere_set.cpp) walk
// one code path. A node's eight child boxes are tested at once by a box test the caller picks (slabHits8 here,
// on x86-64's baseline SSE2; bvh_traverse_avx2.cpp's AVX2 one); the children hit are visited nearest entry
// first, the others wait on a small fixed stack. No allocation, no virtual calls.
//
// The walks are templates instantiated with the caller's own lambdas, and they call no inline function that is
// not one too (only builtins), so the AVX2 translation unit's copies never stand in for the baseline ones at
// link time (see bvh_traverse_avx2.h).
#pragma once

#include "trace/accel/bvh.h"
#include "trace/accel/slab_test.h"

#include <cmath>
#include <cstdint>

namespace shadelab::trace {

namespace bvh_detail {

// A node pushes at most seven children and the tree is at most kMaxBvhDepth nodes deep.
inline constexpr int kStackSize = (kBvhWidth - 1) * kMaxBvhDepth + 1;

struct Entry {
    uint32_t ref;
    float tEntry;
};

// The reference of an unused child, never visited; also "no child to visit".
inline constexpr uint32_t kNoChild = kLeafBit;

// Orders the children a node's box test hit (`mask`, bit k for child k; `tNear[k]` their entry distances):
// pushes all but the nearest with `push(ref, tEntry)` (farthest first, so they pop nearest first; equal entries
// pop in child order) and returns the nearest, or kNoChild when the mask is empty.
template <typename Push>
inline uint32_t orderChildren(const BvhNode& node, unsigned mask, const float* tNear, Push&& push) {
    static_assert(kBvhWidth == 8, "the masks below hold 8 children");
    if (mask == 0) return kNoChild;
    const int i0 = __builtin_ctz(mask);
    mask &= mask - 1;
    if (mask == 0) return node.child[i0];  // the common case: one child hit
    const int i1 = __builtin_ctz(mask);
    mask &= mask - 1;
    if (mask == 0) {
        // Two: selects, not branches (which of the two is nearer is a coin toss for incoherent rays).
        const bool swap = tNear[i1] < tNear[i0];
        const int nearer = swap ? i1 : i0, farther = swap ? i0 : i1;
        push(node.child[farther], tNear[farther]);
        return node.child[nearer];
    }
    // Three or more: sort them on a key of (entry distance, child index) with a branch-free network of
    // compare-exchanges, then push all but the nearest, farthest first. A hit child's tNear is >= 0 and not NaN
    // (+ 0 makes a -0 +0), so its bits order as the floats do; equal distances keep child order. Sorting beat
    // pushing unsorted, and the network beat the insertion sort it replaced (bench/README.md).
    uint64_t key[kBvhWidth];
    auto keyOf = [&](int i) {
        const float t = tNear[i] + 0.0f;
        uint32_t bits;
        __builtin_memcpy(&bits, &t, 4);
        return (uint64_t(bits) << 32) | uint64_t(i);
    };
    int n = 0;
    key[n++] = keyOf(i0);
    key[n++] = keyOf(i1);
    while (mask) {
        key[n++] = keyOf(__builtin_ctz(mask));
        mask &= mask - 1;
    }
    auto cx = [&key](int a, int b) {
        const uint64_t lo = key[a] < key[b] ? key[a] : key[b], hi = key[a] < key[b] ? key[b] : key[a];
        key[a] = lo;
        key[b] = hi;
    };
    if (n == 3) {
        cx(0, 1), cx(1, 2), cx(0, 1);
    } else if (n == 4) {
        cx(0, 1), cx(2, 3), cx(0, 2), cx(1, 3), cx(1, 2);
    } else {
        for (int k = 1; k < n; ++k) {
            const uint64_t x = key[k];
            int j = k;
            for (; j > 0 && key[j - 1] > x; --j) key[j] = key[j - 1];
            key[j] = x;
        }
    }
    for (int k = n - 1; k > 0; --k) {
        const int i = int(key[k] & 7u);
        push(node.child[i], tNear[i]);
    }
    return node.child[key[0] & 7u];
}

}  // namespace bvh_detail

// Visits leaves that may hold a hit nearer than `tMax`, nearer children first, from the root nodes[0] (of a
// tree that is not empty). `boxes(node, tMax, tNear)`
// tests a node's eight child boxes (returns the hit mask, fills tNear[8]); `leaf(first, count)` tests the
// primitives at leaf slots [first, first + count) and returns the distance of the nearest hit so far (or the
// bound it was given); subtrees entered beyond it are skipped. The bound is a local here, not shared with the
// callback, so it stays in a register. Returns the final bound.
template <typename BoxFn, typename LeafFn>
float traverseClosestWith(const BvhNode* nodes, float tMax, BoxFn&& boxes, LeafFn&& leaf) {
    using bvh_detail::Entry;
    // Starts loading a node that will be visited later (all four cache lines); leaves are left alone.
    auto prefetch = [nodes](uint32_t c) {
        if (c & kLeafBit) return;
        const char* p = reinterpret_cast<const char*>(nodes + c);
        for (int line = 0; line < 4; ++line) __builtin_prefetch(p + 64 * line);
    };
    Entry stack[bvh_detail::kStackSize];
    int sp = 0;
    uint32_t ref = 0;  // the root node
    for (;;) {
        if (!(ref & kLeafBit)) {
            alignas(32) float tNear[kBvhWidth];
            const BvhNode& node = nodes[ref];
            const unsigned mask = unsigned(boxes(node, tMax, tNear));
            ref = bvh_detail::orderChildren(node, mask, tNear, [&](uint32_t c, float t) {
                prefetch(c);
                stack[sp++] = Entry{c, t};
            });
            if (ref != bvh_detail::kNoChild) continue;
        } else {
            tMax = leaf((ref & ~kLeafBit) >> 4, ref & 15u);
        }
        // Pop the next subtree that may still hold a hit no farther than the best so far.
        for (;;) {
            if (sp == 0) return tMax;
            --sp;
            if (stack[sp].tEntry <= tMax) break;
        }
        ref = stack[sp].ref;
    }
}

// True as soon as `leaf(first, count)` reports a hit closer than tMax; nearer children first, so an occluder
// near the origin is found without visiting the far side. `boxes` as for traverseClosestWith.
template <typename BoxFn, typename LeafFn>
bool traverseAnyWith(const BvhNode* nodes, float tMax, BoxFn&& boxes, LeafFn&& leaf) {
    // Starts loading a node that will be visited later (all four cache lines); leaves are left alone.
    auto prefetch = [nodes](uint32_t c) {
        if (c & kLeafBit) return;
        const char* p = reinterpret_cast<const char*>(nodes + c);
        for (int line = 0; line < 4; ++line) __builtin_prefetch(p + 64 * line);
    };
    uint32_t stack[bvh_detail::kStackSize];
    int sp = 0;
    uint32_t ref = 0;
    for (;;) {
        if (!(ref & kLeafBit)) {
            alignas(32) float tNear[kBvhWidth];
            const BvhNode& node = nodes[ref];
            const unsigned mask = unsigned(boxes(node, tMax, tNear));
            ref = bvh_detail::orderChildren(node, mask, tNear, [&](uint32_t c, float) {
                prefetch(c);
                stack[sp++] = c;
            });
            if (ref != bvh_detail::kNoChild) continue;
        } else if (leaf((ref & ~kLeafBit) >> 4, ref & 15u)) {
            return true;
        }
        if (sp == 0) return false;
        ref = stack[--sp];
    }
}

// The baseline (SSE2) walks: slabHits8 as the box test. An empty tree is never entered.
template <typename LeafFn>
float traverseClosest(const Bvh& bvh, const BoxRay& br, float tMax, LeafFn&& leaf) {
    if (bvh.empty()) return tMax;
    const BoxRay4 r = makeBoxRay4(br);
    return traverseClosestWith(
        bvh.nodes.data(), tMax,
        [&](const BvhNode& n, float t, float* tNear) { return slabHits8(r, n.bounds, t, tNear); }, leaf);
}

template <typename LeafFn>
bool traverseAny(const Bvh& bvh, const BoxRay& br, float tMax, LeafFn&& leaf) {
    if (bvh.empty()) return false;
    const BoxRay4 r = makeBoxRay4(br);
    return traverseAnyWith(
        bvh.nodes.data(), tMax,
        [&](const BvhNode& n, float t, float* tNear) { return slabHits8(r, n.bounds, t, tNear); }, leaf);
}

}  // namespace shadelab::trace
