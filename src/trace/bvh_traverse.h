// The two walks of the 4-wide BVH every primitive type shares: ordered closest-hit and early-out any-hit.
// Primitive tests come in as leaf callbacks, so triangles (mesh_bvh.cpp) and spheres (sphere_set.cpp) walk
// one code path. Each node's four child boxes are tested at once (slabHits4); the children hit are visited
// nearest entry first, the others wait on a small fixed stack. No allocation, no virtual calls.
#pragma once

#include "trace/bvh.h"
#include "trace/slab_test.h"

#include <cmath>
#include <cstdint>

namespace shadelab::trace {

namespace bvh_detail {

// A node pushes at most three children and the tree is at most kMaxBvhDepth nodes deep.
inline constexpr int kStackSize = 3 * kMaxBvhDepth + 1;

struct Entry {
    uint32_t ref;
    float tEntry;
};

// Starts loading a node that will be visited later (both of its cache lines); leaves are left alone.
inline void prefetchNode(const BvhNode* nodes, uint32_t ref) {
    if (isLeafRef(ref)) return;
    const char* p = reinterpret_cast<const char*>(nodes + ref);
    prefetchLine(p);
    prefetchLine(p + 64);
}

// Index of the lowest set bit of a non-zero 4-bit mask.
inline int lowestBit(int m) {
#if defined(__GNUC__)
    return __builtin_ctz(unsigned(m));
#else
    int k = 0;
    while (!(m & (1 << k))) ++k;
    return k;
#endif
}

// One node step: tests the four child boxes of `node`, pushes the children hit beyond the nearest with
// `push(ref, tEntry)` (farthest first, so they pop nearest first; equal entries pop in child order) and returns
// the nearest child to visit next, or kNoChild when the ray misses all four.
inline constexpr uint32_t kNoChild = kLeafBit;  // the reference of an unused child, never visited

template <typename Push>
inline uint32_t stepNode(const BvhNode& node, const BoxRay4& r, float tMax, Push&& push) {
    F4 tn;
    int m = slabHits4(r, node.bounds, tMax, tn);
    if (m == 0) return kNoChild;
    const int i0 = lowestBit(m);
    m &= m - 1;
    if (m == 0) return node.child[i0];  // the common case: one child hit
    float tNear[4];
    store4(tNear, tn);
    const int i1 = lowestBit(m);
    m &= m - 1;
    if (m == 0) {
        if (tNear[i1] < tNear[i0]) {
            push(node.child[i0], tNear[i0]);
            return node.child[i1];
        }
        push(node.child[i1], tNear[i1]);
        return node.child[i0];
    }
    // Three or four: sort them on the stack, farthest deepest, then take the nearest off the top.
    Entry e[4];
    int n = 0;
    e[n++] = {node.child[i0], tNear[i0]};
    e[n++] = {node.child[i1], tNear[i1]};
    while (m) {
        const int i = lowestBit(m);
        m &= m - 1;
        e[n++] = {node.child[i], tNear[i]};
    }
    // Insertion sort, farthest first; equal distances keep the higher child index deeper.
    for (int k = 1; k < n; ++k) {
        const Entry x = e[k];
        int j = k;
        for (; j > 0 && e[j - 1].tEntry <= x.tEntry; --j) e[j] = e[j - 1];
        e[j] = x;
    }
    for (int k = 0; k < n - 1; ++k) push(e[k].ref, e[k].tEntry);
    return e[n - 1].ref;
}

}  // namespace bvh_detail

// Visits leaves that may hold a hit nearer than `tMax`, nearer children first. `leaf(first, count)` tests the
// primitives at leaf slots [first, first + count) and returns the distance of the nearest hit so far (or the
// bound it was given); subtrees entered beyond it are skipped. The bound is a local here, not shared with the
// callback, so it stays in a register.
template <typename LeafFn>
void traverseClosest(const Bvh& bvh, const BoxRay& br, float tMax, LeafFn&& leaf) {
    using bvh_detail::Entry;
    if (bvh.empty()) return;
    const BvhNode* nodes = bvh.nodes.data();
    const BoxRay4 r = makeBoxRay4(br);
    Entry stack[bvh_detail::kStackSize];
    int sp = 0;
    uint32_t ref = 0;  // the root node
    for (;;) {
        if (!isLeafRef(ref)) {
            ref = bvh_detail::stepNode(nodes[ref], r, tMax, [&](uint32_t c, float t) {
                bvh_detail::prefetchNode(nodes, c);
                stack[sp++] = Entry{c, t};
            });
            if (ref != bvh_detail::kNoChild) continue;
        } else {
            tMax = leaf(leafFirst(ref), leafCount(ref));
        }
        // Pop the next subtree that may still hold a hit no farther than the best so far.
        for (;;) {
            if (sp == 0) return;
            --sp;
            if (stack[sp].tEntry <= tMax) break;
        }
        ref = stack[sp].ref;
    }
}

// True as soon as `leaf(first, count)` reports a hit closer than tMax; nearer children first, so an occluder
// near the origin is found without visiting the far side.
template <typename LeafFn>
bool traverseAny(const Bvh& bvh, const BoxRay& br, float tMax, LeafFn&& leaf) {
    using bvh_detail::Entry;
    if (bvh.empty()) return false;
    const BvhNode* nodes = bvh.nodes.data();
    const BoxRay4 r = makeBoxRay4(br);
    uint32_t stack[bvh_detail::kStackSize];
    int sp = 0;
    uint32_t ref = 0;
    for (;;) {
        if (!isLeafRef(ref)) {
            ref = bvh_detail::stepNode(nodes[ref], r, tMax, [&](uint32_t c, float) {
                bvh_detail::prefetchNode(nodes, c);
                stack[sp++] = c;
            });
            if (ref != bvh_detail::kNoChild) continue;
        } else if (leaf(leafFirst(ref), leafCount(ref))) {
            return true;
        }
        if (sp == 0) return false;
        ref = stack[--sp];
    }
}

}  // namespace shadelab::trace
