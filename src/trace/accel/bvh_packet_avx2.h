// Packets of eight rays walked through MeshBvh's tree together, in AVX2 (bvh_packet_avx2.cpp, compiled alone with
// -mavx2 -mfma); call only where bvhIsaAvailable(BvhIsa::Avx2).
//
// Camera rays of neighbouring pixels, and their shadow rays toward one light, mostly visit the same nodes. A packet
// fetches and orders each node once for all its rays; where the rays share their directions' signs a node's eight
// children are first tested against the packet's frustum in one register, then the children it may enter against
// each ray, so every ray carries exactly the nodes its own walk would enter. Leaves are tested ray by ray with the
// single-ray leaf test, so each ray's answer is closestTriangleAvx2's (anyTriangleAvx2's) bit for bit.
#pragma once

#include "trace/accel/bvh.h"
#include "trace/accel/triangle_leaf.h"
#include "trace/ray.h"

namespace shadelab::trace {

// The same for up to eight rays at once (bit k of `valid`: rays[k], best[k]; the other entries are not read),
// walked through the tree as one packet (coherent rays share its node visits); each ray's answer is
// closestTriangleAvx2's bit for bit.
void closestTriangle8Avx2(const BvhNode* nodes, const Ray* rays, unsigned valid, TriangleLeafData data,
                          TriangleLeafHit* best);
// anyTriangleAvx2 for up to eight rays at once, each with its own tMax: bit k set where ray k is occluded.
unsigned anyTriangle8Avx2(const BvhNode* nodes, const Ray* rays, const float* tMax, unsigned valid,
                          TriangleLeafData data);

}  // namespace shadelab::trace
