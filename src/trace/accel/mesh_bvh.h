// MeshBvh: every triangle of a scene's meshes in one 8-wide SAH BVH (bvh.h), built over spatial-split references
// (spatial_splits.h: a long triangle across the axes fills several slots, each slot the same triangle), the
// vertex positions stored in leaf order next to which part and triangle each is (45 bytes per slot; vertex normals are
// read from the scene's shared geometry, which it keeps alive). A leaf's positions are 9 rows, one per corner and axis,
// of one float per triangle (leaf_positions.h), so the AVX2 leaf test loads each row as a register without shuffling.
// Geometry only and immutable once built, so TraceScene versions that differ only in materials, lights or camera share
// one (see trace_scene.h).
#pragma once

#include "scene/scene.h"
#include "trace/accel/bvh.h"
#include "trace/accel/bvh_isa.h"
#include "trace/accel/bvh_traverse_avx2.h"
#include "trace/ray.h"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace shadelab::trace {

struct MeshHit {
    float t;           // ray parameter, > 0
    uint32_t slot;     // the triangle's position in BVH order (MeshBvh accessors take it)
    float b0, b1, b2;  // barycentric weights of the triangle's vertices 0, 1, 2
};

// True for a triangle with exactly zero area (collinear or repeated corners, cross product computed in
// double). GL rasterizes no fragment for one, so the tracer leaves it out too: the watertight test would
// otherwise report hits at rounding-noise distances for rays in its plane.
bool isDegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// A leaf holds at most this many triangles: the AVX2 leaf test takes them in one 4-wide step.
inline constexpr int kMaxMeshLeafSize = 4;

// Spatial splits (bvh.h, spatial_splits.h) run on scenes of up to this many triangles. Above it, scanned or
// tessellated meshes are the ones made of small, well-shaped triangles that splits help least, while the room
// for extra references and the overlap tests still cost time (the 4.2 M-triangle grid of spheres: 1.0 to 1.25
// times the plain build, no split taken; trace_bench --spatial times both at any size).
inline constexpr size_t kMaxSpatialSplitTriangles = 500000;
static_assert(BvhBuildOptions{}.spatialSplitLimit == kMaxSpatialSplitTriangles, "the option's default is this limit");

class MeshBvh {
public:
    // Triangles with a non-finite vertex are left out (they cannot be hit); indices must be in range.
    // options.maxLeafSize is capped at kMaxMeshLeafSize.
    explicit MeshBvh(const Scene& scene, const BvhBuildOptions& options = {});

    // The nearest hit with 0 < t < tMax. Exactly equal distances go to the lower sourceTriangle(), so
    // the answer does not depend on traversal order (brute force over the scene gives the same hit).
    // The walks use defaultBvhIsa(); the overloads taking an isa (available: bvhIsaAvailable) give the same
    // answers bit for bit, and exist for tests and benchmarks.
    std::optional<MeshHit> closestHit(const Ray& ray, float tMax) const;
    std::optional<MeshHit> closestHit(const Ray& ray, float tMax, BvhIsa isa) const;
    // The same into `out` (left alone without a hit): the per-ray path TraceScene takes, with no optional to
    // build and copy at each level. Inline, like anyHit below, so a ray reaches the AVX2 walk in one call.
    bool closestHit(const Ray& ray, float tMax, MeshHit& out) const {
        if (isa_ != BvhIsa::Avx2 || bvh_.empty()) return closestHitWith(ray, tMax, isa_, out);
        TriangleLeafHit best{tMax, UINT32_MAX, 0.0f, 0.0f, 0.0f};
        closestTriangleAvx2(bvh_.nodes.data(), ray, TriangleLeafData{positions_.data(), source_.data()}, best);
        if (best.slot == UINT32_MAX) return false;
        out = MeshHit{best.t, best.slot, best.b0, best.b1, best.b2};
        return true;
    }
    // Whether any triangle is hit at 0 < t < tMax (shadow rays): stops at the first one found.
    bool anyHit(const Ray& ray, float tMax) const {
        if (isa_ != BvhIsa::Avx2 || bvh_.empty()) return anyHit(ray, tMax, isa_);
        return anyTriangleAvx2(bvh_.nodes.data(), ray, TriangleLeafData{positions_.data(), source_.data()}, tMax);
    }
    bool anyHit(const Ray& ray, float tMax, BvhIsa isa) const;

    // closestHit(rays[k], tMax[k], out[k]) for up to eight rays at once (bit k of `valid`); returns the rays hit
    // (bit k). With the AVX2 walks the rays go through the tree as one packet (closestTriangle8Avx2): camera
    // rays of neighbouring pixels, and their shadow rays, share most node visits. Each answer is the single-ray
    // walk's bit for bit; the baseline walks take the rays one by one.
    unsigned closestHit8(const Ray* rays, const float* tMax, unsigned valid, MeshHit* out) const;
    // anyHit(rays[k], tMax[k]) for up to eight rays at once: bit k set where ray k is occluded.
    unsigned anyHit8(const Ray* rays, const float* tMax, unsigned valid) const;

    // Triangles kept (finite, not degenerate), and slots: a triangle cut by spatial splits fills several.
    size_t triangleCount() const { return triangles_; }
    size_t slotCount() const { return part_.size(); }
    // Vertex positions of a slot as 9 floats (v0, v1, v2), world units.
    std::array<float, 9> vertices(uint32_t slot) const;
    // b0·n0 + b1·n1 + b2·n2 from the glTF vertex normals, not renormalised (shadeLight does that).
    glm::vec3 interpolatedNormal(const MeshHit& hit) const;
    // cross(v1 − v0, v2 − v0): points out of the counter-clockwise (front) side; not unit length.
    glm::vec3 geometricNormal(uint32_t slot) const;
    // Index into the scene's flattened list of mesh parts (mesh by mesh, part by part).
    uint32_t part(uint32_t slot) const { return part_[slot]; }
    // Index of the triangle in scene order: mesh by mesh, part by part, triangle by triangle.
    uint32_t sourceTriangle(uint32_t slot) const { return source_[slot]; }

    // Mesh index (into Scene::meshes) of each flattened part.
    const std::vector<uint32_t>& partMesh() const { return partMesh_; }
    Bounds bounds() const { return bounds_; }
    const Bvh& bvh() const { return bvh_; }
    // Whether `scene`'s mesh parts hold, in order, the very geometry this was built from (by identity:
    // MeshGeometry is immutable, so the same pointer means the same triangles). O(parts).
    bool matches(const Scene& scene) const;

private:
    bool closestHitWith(const Ray& ray, float tMax, BvhIsa isa, MeshHit& out) const;

    // The constructor's gathering runs on options.threads threads from this many triangles (one below it).
    static constexpr uint32_t kMinParallelGather = 100000;
    static int gatherThreads(const BvhBuildOptions& options, uint32_t triangles);
    // f(range, begin, end) for `threads` consecutive ranges of [0, count), on as many threads.
    template <typename F>
    static void forRanges(uint32_t count, int threads, F&& f);
    // f(source, part, triangle in part, corners) for the scene-order triangles [begin, end).
    template <typename F>
    void forTriangles(uint32_t begin, uint32_t end, F&& f) const;

    BvhIsa isa_ = defaultBvhIsa();  // read once, not per ray
    uint32_t triangles_ = 0;
    Bvh bvh_;
    std::vector<float, HugePageAllocator<float>> positions_;  // 9 per slot, by leaf (leaf_positions.h), + padding
    // Per slot, each written whole once sized (no zero fill) by the build's threads, on huge pages from 2 MiB
    // (aligned_allocators.h): a hit reads them at a random slot.
    std::vector<uint8_t, HugePageAllocator<uint8_t>> lane_;      // its index in its leaf << 4 | the leaf's count
    std::vector<uint32_t, HugePageAllocator<uint32_t>> part_;    // its part
    std::vector<uint32_t, HugePageAllocator<uint32_t>> source_;  // its scene-order triangle
    std::vector<uint32_t> partMesh_;                             // per flattened part
    std::vector<uint32_t> partFirst_;                            // per flattened part: its first source index
    std::vector<std::shared_ptr<const MeshGeometry>> geometry_;  // per flattened part, for matches()
    Bounds bounds_;
};

}  // namespace shadelab::trace
