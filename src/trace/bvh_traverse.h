// The two BVH walks every primitive type shares: ordered closest-hit and early-out any-hit. Primitive tests
// come in as leaf callbacks, so triangles (mesh_bvh.cpp) and spheres (sphere_set.cpp) walk one code path.
#pragma once

#include "trace/bvh.h"
#include "trace/slab_test.h"

#include <cmath>
#include <cstdint>
#include <utility>

namespace shadelab::trace {

// Visits leaves that may hold a hit nearer than `tMax`, nearer child first. `leaf(first, count)` tests the
// primitives at Bvh::order slots [first, first + count) and returns the distance of the nearest hit so far
// (or the bound it was given); subtrees entered beyond it are skipped. The bound is a local here, not shared
// with the callback, so it stays in a register.
template <typename LeafFn>
void traverseClosest(const Bvh& bvh, const BoxRay& br, float tMax, LeafFn&& leaf) {
    if (bvh.empty()) return;
    const BvhNode* nodes = bvh.nodes.data();
    if (slabEntry(br, nodes[0].bounds, tMax) == INFINITY) return;
    struct Entry {
        uint32_t node;
        float tEntry;
    } stack[kMaxBvhDepth];
    int sp = 0;
    uint32_t ni = 0;
    for (;;) {
        const BvhNode& node = nodes[ni];
        if (node.isLeaf()) {
            tMax = leaf(node.first, node.count);
        } else {
            const BvhNode& c0 = nodes[node.first];
            const BvhNode& c1 = nodes[node.first + 1];
            float t0 = slabEntry(br, c0.bounds, tMax);
            float t1 = slabEntry(br, c1.bounds, tMax);
            uint32_t nearNode = node.first, farNode = node.first + 1;
            if (t1 < t0) {
                std::swap(t0, t1);
                std::swap(nearNode, farNode);
            }
            if (t0 != INFINITY) {
                if (t1 != INFINITY) stack[sp++] = {farNode, t1};
                ni = nearNode;
                continue;
            }
        }
        // Pop the next subtree that may still hold a hit no farther than the best so far.
        for (;;) {
            if (sp == 0) return;
            --sp;
            if (stack[sp].tEntry <= tMax) break;
        }
        ni = stack[sp].node;
    }
}

// True as soon as `leaf(first, count)` reports a hit closer than tMax; nearer child first, so an occluder
// near the origin is found without visiting the far side.
template <typename LeafFn>
bool traverseAny(const Bvh& bvh, const BoxRay& br, float tMax, LeafFn&& leaf) {
    if (bvh.empty()) return false;
    const BvhNode* nodes = bvh.nodes.data();
    if (slabEntry(br, nodes[0].bounds, tMax) == INFINITY) return false;
    uint32_t stack[kMaxBvhDepth];
    int sp = 0;
    uint32_t ni = 0;
    for (;;) {
        const BvhNode& node = nodes[ni];
        if (node.isLeaf()) {
            if (leaf(node.first, node.count)) return true;
        } else {
            const BvhNode& c0 = nodes[node.first];
            const BvhNode& c1 = nodes[node.first + 1];
            const float t0 = slabEntry(br, c0.bounds, tMax);
            const float t1 = slabEntry(br, c1.bounds, tMax);
            if (t0 != INFINITY && t1 != INFINITY) {
                ni = t0 <= t1 ? node.first : node.first + 1;
                stack[sp++] = t0 <= t1 ? node.first + 1 : node.first;
                continue;
            }
            if (t0 != INFINITY || t1 != INFINITY) {
                ni = t0 != INFINITY ? node.first : node.first + 1;
                continue;
            }
        }
        if (sp == 0) return false;
        ni = stack[--sp];
    }
}

}  // namespace shadelab::trace
