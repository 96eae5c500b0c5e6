// Bvh: an 8-wide bounding-volume hierarchy over boxes. It only sees boxes: the traversals live in
// bvh_traverse.h (and bvh_traverse_avx2.h) and call back into the primitives (mesh_bvh.cpp for triangles,
// sphere_set.cpp for spheres).
//
// Design (goals: fast traversal of incoherent rays, fast builds of millions of triangles):
// - Layout. A node holds the boxes of its (up to) eight children as structure-of-arrays floats, one row of 8
//   per box side (lo x, lo y, lo z, hi x, hi y, hi z). One AVX register holds one side of all eight boxes, so
//   on CPUs with AVX2 and FMA a ray tests all eight with 6 fused multiply-subtracts and a few min/max
//   (bvh_traverse_avx2.h); x86-64's baseline SSE2 does it in two halves of four with 6 subtractions and 6
//   multiplications (slab_test.h). Which one runs is chosen once per process (bvh_isa.h); both find the same hits. A
//   node is 256 bytes, four cache lines, aligned. Unused children have an inverted box (+inf, -inf) that every ray
//   misses, so traversal needs no child count. Eight children rather than four: fewer levels, so fewer nodes per ray
//   (7.5 instead of 11 on the incoherent-ray benchmark), each tested in one AVX2 step.
// - Child references are 32 bits: an interior child is a node index; a leaf is kLeafBit | first << 4 | count,
//   a range of at most 15 primitives in leaf order. So a tree holds fewer than 2^27 primitives.
// - Build. Binned SAH (MacDonald & Booth 1990 cost; Wald 2007 binning, 16 bins: bvh_binning.h) on primitive
//   references that carry their own box (BvhPrim, 32 bytes), so binning and partitioning read memory
//   sequentially. A node is
//   made by splitting its range in two by SAH, then splitting the child of largest area again, until it has
//   eight children or every child is a leaf (the usual binary-to-wide collapse, done while building). Slots
//   left free stay free (splitting leaves into them was measured: no faster, and a slower build).
//   A range the caller's leaf test takes in one step (leafTestWidth: four triangles for MeshBvh) is a leaf
//   without a split search, since the SAH's one-test-per-primitive count would split it into leaves that cost
//   the same test each (on the 4.2 M-triangle grid: 27 % fewer nodes, a 17 % faster build, faster rays).
//   Below kMedianDepth binary splits the object median takes over, which bounds the depth for any input.
// - Spatial splits (Stich, Friedrich & Dietrich 2009, SBVH). Given a BvhReferenceSplitter (MeshBvh's
//   triangles: spatial_splits.h) and room for more references than it was handed, the builder may also split
//   space: where the best object split's two children overlap by more than kSpatialSplitAlpha of the root's
//   area, it bins the range across planes on the same axis, each reference adding the box of its part in
//   every bin it crosses, and takes the plane if it costs less by SAH and the range has room for the
//   references it cuts in two. Each range carries spare room past its end (Embree's "extended ranges"): a
//   split hands it to the two sides by their sizes, moving the right side up to make the left side's share,
//   but only to sides where it or their parent found enough overlap (elsewhere it stays with the right side,
//   unmoved). Afterwards the leaves are packed to the front in order, closing the gaps. So a triangle may fill
//   several slots, and one pass both splits and builds (a separate top-down pass before the build took 6 times
//   the build itself at 4 M triangles; now about 1.0 times on the grid of spheres, no split taken).
// - Parallel build. The top of the tree is built on the calling thread, with the binning of large ranges
//   split across threads; subtrees below a size threshold are queued, and the workers build them into their
//   own node arrays as they are queued (the calling thread joins them when the top is done), then they are
//   appended in queue order. The result does not depend on the thread count or
//   on scheduling: the same input gives the same nodes and the same leaf order.
// - Memory. The builder's only scratch is the BvhPrim array the caller hands in (it becomes the leaf order);
//   nodes are about n / 10 x 256 bytes with four-triangle leaf tests (about 26 bytes per primitive; on
//   2CylinderEngine's spatial-split references leaves average 3.1 triangles and nodes 4.3 children, on the
//   sphere grid 3.4 and 3.8). The worker threads' subtree arrays are
//   reserved up front and their pages handed back (malloc_trim) as they are copied into the final array, so
//   the build's peak holds the nodes about once.
#pragma once

#include "scene/bounds.h"
#include "trace/accel/aligned_allocators.h"

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

namespace shadelab::trace {

// A child reference: an interior node index, or a leaf (kLeafBit set) with its first primitive and count.
inline constexpr uint32_t kLeafBit = 0x80000000u;
inline constexpr uint32_t kMaxLeafCount = 15;
inline constexpr uint32_t kMaxBvhPrimitives = 1u << 27;
inline bool isLeafRef(uint32_t ref) { return (ref & kLeafBit) != 0; }
inline uint32_t leafFirst(uint32_t ref) { return (ref & ~kLeafBit) >> 4; }
inline uint32_t leafCount(uint32_t ref) { return ref & 15u; }
inline uint32_t makeLeafRef(uint32_t first, uint32_t count) { return kLeafBit | first << 4 | count; }

// Children per node.
inline constexpr int kBvhWidth = 8;

// One node: eight child boxes, side-major (bounds[side][child], side 0-2 lo x y z, 3-5 hi x y z, world units,
// indexable by slab side as slab_test.h's nearIdx/farIdx), and eight child references. An unused child has
// lo = +inf, hi = -inf and reference kLeafBit (an empty leaf). Each row of 8 floats is 32-byte aligned: one
// AVX register, or two SSE registers (children 0-3 and 4-7).
struct alignas(64) BvhNode {
    float bounds[6][kBvhWidth];
    uint32_t child[kBvhWidth];
    uint32_t pad[8];  // to 256 bytes: four whole cache lines

    bool used(int k) const { return !(bounds[0][k] > bounds[3][k]); }
};
static_assert(sizeof(BvhNode) == 256, "BvhNode must stay four cache lines");

struct BvhBuildOptions {
    int bins = 16;               // SAH candidate planes per axis are bins - 1 (at most 32 bins)
    int maxLeafSize = 4;         // leaves never hold more primitives than this (at most kMaxLeafCount)
    float traversalCost = 1.0f;  // SAH cost of visiting a node, relative to one primitive test
    // Primitives the caller's leaf test takes in one step (MeshBvh: four triangles per SIMD test). A range of at
    // most this many (and at most maxLeafSize) becomes a leaf without a split search: splitting it could not save
    // a leaf test, only add a node. 1: every range of two or more is weighed by the SAH.
    int leafTestWidth = 1;
    int threads = 0;  // build threads; 0: std::thread::hardware_concurrency(). Small inputs use one.
    // MeshBvh only: extra references spatial splits may make, as a fraction of the triangles (spatial_splits.h);
    // 0 turns them off.
    float spatialSplitBudget = 1.0f;
    // MeshBvh only: the most triangles spatial splits run on (kMaxSpatialSplitTriangles, mesh_bvh.h); larger
    // scenes get the plain build. Benchmarks raise it to time the pass on large scenes.
    size_t spatialSplitLimit = 500000;
};

// Deepest tree the builder makes, in binary splits (an 8-wide level is one to seven of them); traversal
// stacks are sized from it.
inline constexpr int kMaxBvhDepth = 64;

// A primitive as the builder sees it: its box and two words the builder carries along untouched (for
// example the primitive's index). 32 bytes, so the builder moves whole cache-line halves.
struct BvhPrim {
    float lo[3];
    uint32_t id;
    float hi[3];
    uint32_t id2;
};
static_assert(sizeof(BvhPrim) == 32, "BvhPrim must stay 32 bytes");

struct Bvh {
    std::vector<BvhNode, HugePageAllocator<BvhNode>> nodes;  // [0] is the root; empty when no primitives
    std::vector<uint32_t> order;  // buildBvh(boxes) only: order[k] is the input primitive at leaf slot k
    Bounds bounds;                // of every primitive
    uint32_t primitives = 0;      // references in the leaves (with spatial splits, more than were handed in)
    int depth = 0;                // binary splits below the root on the deepest path, < kMaxBvhDepth

    bool empty() const { return primitives == 0; }
};

// Cuts a reference in two at a plane, for spatial splits (see the design above). Both calls see references
// the builder was given or made with split(); `planes` are positions across `axis`, increasing.
class BvhReferenceSplitter {
public:
    virtual ~BvhReferenceSplitter() = default;
    // Extends boxes[k], for k in [first, last] (at most 32 apart), by a box of the part of `ref` between
    // planes[k] and planes[k + 1] (the first and last parts are bounded by the reference's box instead), where
    // it has one. For the SAH only: the box may be larger than the part, never smaller.
    virtual void binParts(const BvhPrim& ref, int axis, const float* planes, int first, int last,
                          Bounds* boxes) const = 0;
    // The parts of `ref` below and above `pos` across `axis`, with the same ids; returns which exist (bit 0:
    // below, bit 1: above). 0 (a reference that seems to reach neither side, by rounding) keeps it whole.
    virtual int split(const BvhPrim& ref, int axis, float pos, BvhPrim& below, BvhPrim& above) const = 0;
};

// Spatial splits are weighed where the best object split's children overlap by more than this fraction of the
// root's surface area (SBVH's alpha): below it, overlap costs rays too little to pay for the references.
inline constexpr float kSpatialSplitAlpha = 1e-5f;

// Builds over `prims` (boxes not empty, fewer than kMaxBvhPrimitives) and reorders them into leaf order:
// afterwards prims[k] is the primitive at leaf slot k. An empty input gives an empty Bvh.
Bvh buildBvh(std::vector<BvhPrim>& prims, const BvhBuildOptions& options = {});
// The same on an array of `count` references that the caller owns (reordered in place).
Bvh buildBvh(BvhPrim* prims, size_t count, const BvhBuildOptions& options = {});
// With spatial splits: `prims` has room for `capacity` references (at least `count`, fewer than
// kMaxBvhPrimitives), the first `count` set. Afterwards prims[0, Bvh::primitives) are the references in leaf
// order, split ones included; the rest of the room is left undefined.
Bvh buildBvh(BvhPrim* prims, size_t count, size_t capacity, const BvhReferenceSplitter& splitter,
             const BvhBuildOptions& options = {});
// The same over plain boxes (one per primitive); fills Bvh::order.
Bvh buildBvh(const std::vector<Bounds>& boxes, const BvhBuildOptions& options = {});

// SAH cost of a built tree (for tests and tuning): Σ area(child box)/area(root) weighted by visit/test cost.
float sahCost(const Bvh& bvh, const BvhBuildOptions& options = {});

}  // namespace shadelab::trace
