// Spatial splits for a triangle BVH (Stich, Friedrich & Dietrich 2009, "Spatial Splits in Bounding Volume
// Hierarchies"). A long triangle lying across the axes has a box far larger than itself, which overlaps its
// neighbours' boxes, so rays near it visit many leaves. SBVH lets a node split space instead of objects where
// that costs less by SAH: every triangle straddling the plane becomes two references, each with the box of its
// part on one side. The builder (bvh.h) decides where; this file bins a triangle's parts (from its corners and edge
// crossings) and cuts it at the chosen plane (by clipping).
//
// A reference carries its triangle's ids unchanged, so the tree's slots name the same triangles, some more than
// once. The parts of a triangle cover it: each part's box is its clipped polygon's box grown by `pad` (the
// caller's rounding margin, which every reference's box already has), within the box of the reference it was
// cut from, so a rounding error in clipping never drops a sliver. On 2CylinderEngine (110 K triangles) spatial
// splits take our walk on incoherent rays from about 0.88x to about 1.07x Embree's (bench/README.md).
#pragma once

#include "trace/accel/bvh.h"

#include <functional>
#include <glm/vec3.hpp>
#include <utility>

namespace shadelab::trace {

// The three corners of the triangle a reference stands for.
using TriangleCorners = std::function<void(const BvhPrim& ref, glm::vec3 corners[3])>;

// Triangle references for the builder: parts binned from corners and edge crossings, cuts clipped exactly.
class TriangleSplitter final : public BvhReferenceSplitter {
public:
    TriangleSplitter(TriangleCorners corners, float pad) : corners_(std::move(corners)), pad_(pad) {}

    void binParts(const BvhPrim& ref, int axis, const float* planes, int first, int last, Bounds* boxes) const override;
    int split(const BvhPrim& ref, int axis, float pos, BvhPrim& below, BvhPrim& above) const override;

private:
    TriangleCorners corners_;
    float pad_;
};

}  // namespace shadelab::trace
