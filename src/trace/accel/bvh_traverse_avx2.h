// MeshBvh's two walks with an AVX2 box test: a node's eight child boxes in one register per box side.
// Compiled alone with -mavx2 -mfma (bvh_traverse_avx2.cpp); call only where bvhIsaAvailable(BvhIsa::Avx2).
//
// Same hits as the baseline walks, bit for bit. The box test takes one fused multiply-subtract per slab
// (bound·invDir − org·invDir, the product nudged outward so the test stays conservative), so a child's entry
// distance may differ from slab_test.h's in the last bits and a few more boxes may pass; the closest hit does not
// depend on that (ties go to the lower scene index wherever they are found). A leaf's up to four triangles are
// tested in one SSE step that performs the scalar watertight test's operations per lane (watertight.h); a leaf
// where an edge function rounds to exactly 0 goes to triangle_leaf.h's scalar loop, whose double recomputation
// the lanes do not do. The AVX2 file instantiates every template it uses with types of its own, so the linker
// can never hand its AVX2 code to a baseline caller.
#pragma once

#include "trace/accel/bvh.h"
#include "trace/accel/slab_test.h"
#include "trace/accel/triangle_leaf.h"
#include "trace/accel/watertight.h"

#include <cstdint>

namespace shadelab::trace {

// The nearest triangle hit nearer than best.t (updated in place; best.slot stays UINT32_MAX without one), from
// the root nodes[0] of a tree that is not empty. As ClosestTriangleLeaf with tMax = best.t on entry.
void closestTriangleAvx2(const BvhNode* nodes, const Ray& ray, TriangleLeafData data, TriangleLeafHit& best);
// Whether any triangle is hit at 0 < t < tMax.
bool anyTriangleAvx2(const BvhNode* nodes, const Ray& ray, TriangleLeafData data, float tMax);

// The per-ray constants the walks above use, for tests: makeBoxRay's and makeWatertightRay's, bit for bit.
void rayConstantsAvx2(const Ray& ray, BoxRay& box, WatertightRay& wt);

// The AVX2 box test alone, for tests: as slabHits8, conservative, up to rounding (bounds rows 32-byte aligned).
int slabHits8Avx2(const BoxRay& ray, const float (*bounds)[8], float tMax, float* tNear);

}  // namespace shadelab::trace
