// MeshBvh: gathering the scene's triangles, building the BVH, and the two traversals (nearest hit with an
// order-independent tie-break, and any hit for shadow rays). Ordered front-to-back traversal with a
// small fixed stack; no allocation and no virtual calls per ray.
#include "trace/accel/mesh_bvh.h"

#include "trace/accel/bvh_packet_avx2.h"
#include "trace/accel/bvh_traverse.h"
#include "trace/accel/bvh_traverse_avx2.h"
#include "trace/accel/leaf_positions.h"
#include "trace/accel/spatial_splits.h"
#include "trace/accel/triangle_leaf.h"
#include "trace/accel/watertight.h"
#include "util/check.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <thread>
#include <utility>

namespace shadelab::trace {
namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

bool isDegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

MeshBvh::MeshBvh(const Scene& scene, const BvhBuildOptions& options) {
    // The parts in scene order, each with its geometry and the scene-order index (`source`) of its first
    // triangle; `source` numbers every triangle, kept or not.
    uint32_t total = 0;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        for (const MeshPart& part : scene.meshes[m].parts) {
            SHADELAB_CHECK(part.geometry != nullptr);
            partMesh_.push_back(uint32_t(m));
            geometry_.push_back(part.geometry);
            partFirst_.push_back(total);
            SHADELAB_CHECK_LT(size_t(total) + part.geometry->triangleCount(), size_t(UINT32_MAX));
            total += uint32_t(part.geometry->triangleCount());
        }
    }
    const int threads = gatherThreads(options, total);

    // One BvhPrim per finite, non-degenerate triangle, in scene order: its box, its index in its part and the
    // part's index. The test (a cross product in double) runs on `threads` ranges of the scene's triangles;
    // each range then writes its kept triangles at its offset, so the order does not depend on the split.
    std::vector<uint8_t> keep(total);
    std::vector<uint32_t> kept(size_t(threads) + 1, 0);
    forRanges(total, threads, [&](int r, uint32_t begin, uint32_t end) {
        uint32_t count = 0;
        forTriangles(begin, end, [&](uint32_t g, uint32_t, size_t, const glm::vec3* v) {
            keep[g] = finite(v[0]) && finite(v[1]) && finite(v[2]) && !isDegenerateTriangle(v[0], v[1], v[2]);
            count += keep[g];
        });
        kept[size_t(r) + 1] = count;
    });
    for (int r = 0; r < threads; ++r) kept[size_t(r) + 1] += kept[size_t(r)];
    // On huge pages and sized without a zero fill (aligned_allocators.h): the ranges below write every element,
    // each thread's pages first touched by that thread.
    // With spatial splits the builder gets room past the triangles for the budget's extra references: reserved
    // here, so sizing up for the build copies nothing (pages the build never touches stay virtual).
    const size_t triangles = kept[size_t(threads)];
    const bool spatial = options.spatialSplitBudget > 0.0f && triangles <= options.spatialSplitLimit;
    const size_t capacity = spatial
                                ? std::min(triangles + size_t(double(options.spatialSplitBudget) * double(triangles)),
                                           size_t(kMaxBvhPrimitives) - 1)
                                : triangles;
    std::vector<BvhPrim, HugePageAllocator<BvhPrim>> prims;
    prims.reserve(std::max(capacity, triangles));
    prims.resize(triangles);
    std::vector<Bounds> rangeBounds(static_cast<size_t>(threads));
    forRanges(total, threads, [&](int r, uint32_t begin, uint32_t end) {
        BvhPrim* out = prims.data() + kept[size_t(r)];
        Bounds& b = rangeBounds[size_t(r)];
        forTriangles(begin, end, [&](uint32_t g, uint32_t part, size_t t, const glm::vec3* v) {
            if (!keep[g]) return;
            const glm::vec3 lo = glm::min(glm::min(v[0], v[1]), v[2]), hi = glm::max(glm::max(v[0], v[1]), v[2]);
            *out++ = BvhPrim{{lo.x, lo.y, lo.z}, uint32_t(t), {hi.x, hi.y, hi.z}, part};
            b.lo = glm::min(b.lo, lo);
            b.hi = glm::max(b.hi, hi);
        });
    });
    std::vector<uint8_t>().swap(keep);
    for (const Bounds& b : rangeBounds) {
        bounds_.lo = glm::min(bounds_.lo, b.lo);
        bounds_.hi = glm::max(bounds_.hi, b.hi);
    }
    // Every box is padded by far more than a triangle hit's rounding, which scales with the coordinates'
    // magnitude: otherwise a triangle lying in its box's face can round to a hit just before the box's rounded
    // entry and be culled (SphereSet pads spheres the same way).
    const glm::vec3 extent = glm::max(glm::abs(bounds_.lo), glm::abs(bounds_.hi));
    const float pad = prims.empty() ? 0.0f : 1e-6f * std::max({extent.x, extent.y, extent.z, 1e-30f});
    forRanges(uint32_t(prims.size()), threads, [&](int, uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i)
            for (int a = 0; a < 3; ++a) {
                prims[i].lo[a] -= pad;
                prims[i].hi[a] += pad;
            }
    });
    bounds_.lo -= glm::vec3(pad);
    bounds_.hi += glm::vec3(pad);
    BvhBuildOptions leafOptions = options;
    leafOptions.maxLeafSize = std::min(options.maxLeafSize, int(kMaxMeshLeafSize));
    leafOptions.leafTestWidth = kMaxMeshLeafSize;  // the leaf tests take four triangles in one step
    triangles_ = uint32_t(prims.size());
    if (spatial && capacity > triangles) {
        // Long triangles across the axes may become several references (spatial_splits.h); the builder says
        // how many it made.
        const TriangleSplitter splitter(
            [this](const BvhPrim& ref, glm::vec3 c[3]) {
                const MeshGeometry& g = *geometry_[ref.id2];
                for (size_t k = 0; k < 3; ++k) c[k] = g.positions[g.indices[3 * size_t(ref.id) + k]];
            },
            pad);
        prims.resize(capacity);
        bvh_ = buildBvh(prims.data(), triangles, capacity, splitter, leafOptions);
        prims.resize(bvh_.primitives);
    } else {
        bvh_ = buildBvh(prims.data(), prims.size(), leafOptions);
    }

    // Store what the traversal and shading read in leaf order, so a leaf's triangles are contiguous in memory;
    // normals stay in the scene's geometry (interpolatedNormal reads them through the part). The ids first,
    // then the primitive references are freed before the positions are gathered: the peak holds only one.
    const uint32_t n = uint32_t(prims.size());
    part_.resize(n);
    source_.resize(n);
    forRanges(n, threads, [&](int, uint32_t begin, uint32_t end) {
        for (uint32_t slot = begin; slot < end; ++slot) {
            part_[slot] = prims[slot].id2;
            source_[slot] = partFirst_[prims[slot].id2] + prims[slot].id;
        }
    });
    decltype(prims)().swap(prims);
    // Each slot's place in its leaf, from the leaf references, then the positions by leaf (leaf_positions.h).
    lane_.resize(n);
    forRanges(uint32_t(bvh_.nodes.size()), threads, [&](int, uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i)
            for (uint32_t ref : bvh_.nodes[i].child)
                if (isLeafRef(ref))
                    for (uint32_t j = 0; j < leafCount(ref); ++j)
                        lane_[leafFirst(ref) + j] = uint8_t(j << 4 | leafCount(ref));
    });
    // Every slot writes its nine floats below; only the padding is set here (no zero fill of the whole array).
    positions_.resize(9 * size_t(n) + kLeafRowPadding);
    std::fill(positions_.end() - ptrdiff_t(kLeafRowPadding), positions_.end(), 0.0f);
    forRanges(n, threads, [&](int, uint32_t begin, uint32_t end) {
        for (uint32_t slot = begin; slot < end; ++slot) {
            const MeshGeometry& g = *geometry_[part_[slot]];
            const size_t tri = source_[slot] - partFirst_[part_[slot]];
            const uint32_t j = lane_[slot] >> 4, count = lane_[slot] & 15u;
            float* rows = &positions_[9 * size_t(slot - j)];
            for (uint32_t k = 0; k < 3; ++k) {
                const glm::vec3& v = g.positions[g.indices[3 * tri + k]];
                for (uint32_t a = 0; a < 3; ++a) rows[size_t(3 * k + a) * count + j] = v[int(a)];
            }
        }
    });
}

std::array<float, 9> MeshBvh::vertices(uint32_t slot) const {
    const uint32_t j = lane_[slot] >> 4;
    std::array<float, 9> v;
    gatherLeafTriangle(&positions_[9 * size_t(slot - j)], lane_[slot] & 15u, j, v.data());
    return v;
}

int MeshBvh::gatherThreads(const BvhBuildOptions& options, uint32_t triangles) {
    if (triangles < kMinParallelGather) return 1;
    const int t = options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency());
    return std::max(1, std::min(t, 64));
}

template <typename F>
void MeshBvh::forRanges(uint32_t count, int threads, F&& f) {
    auto range = [&](int r) {
        const uint32_t begin = uint32_t(uint64_t(count) * uint64_t(r) / uint64_t(threads));
        const uint32_t end = uint32_t(uint64_t(count) * uint64_t(r + 1) / uint64_t(threads));
        f(r, begin, end);
    };
    std::vector<std::thread> pool;
    for (int r = 1; r < threads; ++r) pool.emplace_back(range, r);
    range(0);
    for (std::thread& t : pool) t.join();
}

template <typename F>
void MeshBvh::forTriangles(uint32_t begin, uint32_t end, F&& f) const {
    if (begin >= end) return;
    // The part holding `begin`: the last whose first source index is <= begin.
    size_t part = size_t(std::upper_bound(partFirst_.begin(), partFirst_.end(), begin) - partFirst_.begin()) - 1;
    for (uint32_t g = begin; g < end; ++part) {
        const MeshGeometry& p = *geometry_[part];
        const uint32_t first = partFirst_[part], last = first + uint32_t(p.triangleCount());
        for (; g < end && g < last; ++g) {
            const size_t t = g - first;
            glm::vec3 v[3];
            for (int k = 0; k < 3; ++k) {
                const uint32_t idx = p.indices[3 * t + size_t(k)];
                SHADELAB_CHECK_LT(size_t(idx), p.positions.size());
                v[k] = p.positions[idx];
            }
            f(g, uint32_t(part), t, v);
        }
    }
}

glm::vec3 MeshBvh::interpolatedNormal(const MeshHit& hit) const {
    const uint32_t part = part_[hit.slot];
    const MeshGeometry& g = *geometry_[part];
    // Without vertex normals, the geometric normal stands in at every corner (flat shading).
    if (g.normals.size() != g.positions.size()) {
        const glm::vec3 f = geometricNormal(hit.slot);
        return hit.b0 * f + hit.b1 * f + hit.b2 * f;
    }
    const size_t tri = source_[hit.slot] - partFirst_[part];
    const glm::vec3& n0 = g.normals[g.indices[3 * tri]];
    const glm::vec3& n1 = g.normals[g.indices[3 * tri + 1]];
    const glm::vec3& n2 = g.normals[g.indices[3 * tri + 2]];
    return hit.b0 * n0 + hit.b1 * n1 + hit.b2 * n2;
}

glm::vec3 MeshBvh::geometricNormal(uint32_t slot) const {
    const std::array<float, 9> v = vertices(slot);
    const glm::vec3 v0(v[0], v[1], v[2]), v1(v[3], v[4], v[5]), v2(v[6], v[7], v[8]);
    return glm::cross(v1 - v0, v2 - v0);
}

bool MeshBvh::matches(const Scene& scene) const {
    size_t k = 0;
    for (size_t m = 0; m < scene.meshes.size(); ++m)
        for (const MeshPart& p : scene.meshes[m].parts) {
            if (k >= geometry_.size() || geometry_[k] != p.geometry || partMesh_[k] != m) return false;
            ++k;
        }
    return k == geometry_.size();
}

std::optional<MeshHit> MeshBvh::closestHit(const Ray& ray, float tMax) const { return closestHit(ray, tMax, isa_); }

std::optional<MeshHit> MeshBvh::closestHit(const Ray& ray, float tMax, BvhIsa isa) const {
    MeshHit hit;
    if (!closestHitWith(ray, tMax, isa, hit)) return std::nullopt;
    return hit;
}

bool MeshBvh::closestHitWith(const Ray& ray, float tMax, BvhIsa isa, MeshHit& out) const {
    if (bvh_.empty()) return false;  // skip the per-ray set-up for scenes without triangles
    const TriangleLeafData data{positions_.data(), source_.data()};
    TriangleLeafHit best{tMax, UINT32_MAX, 0.0f, 0.0f, 0.0f};
    if (isa == BvhIsa::Avx2) {
        closestTriangleAvx2(bvh_.nodes.data(), ray, data, best);
    } else {
        ClosestTriangleLeaf<watertight_detail::BaselineTag> leaf{data, makeWatertightRay(ray), tMax, best};
        traverseClosest(bvh_, makeBoxRay(ray), tMax, leaf);
        best = leaf.best;
    }
    if (best.slot == UINT32_MAX) return false;
    out = MeshHit{best.t, best.slot, best.b0, best.b1, best.b2};
    return true;
}

bool MeshBvh::anyHit(const Ray& ray, float tMax, BvhIsa isa) const {
    if (bvh_.empty()) return false;
    const TriangleLeafData data{positions_.data(), source_.data()};
    if (isa == BvhIsa::Avx2) return anyTriangleAvx2(bvh_.nodes.data(), ray, data, tMax);
    return traverseAny(bvh_, makeBoxRay(ray), tMax,
                       AnyTriangleLeaf<watertight_detail::BaselineTag>{data, makeWatertightRay(ray), tMax});
}

unsigned MeshBvh::closestHit8(const Ray* rays, const float* tMax, unsigned valid, MeshHit* out) const {
    valid &= 0xFFu;
    if (bvh_.empty() || !valid) return 0;
    unsigned found = 0;
    if (isa_ != BvhIsa::Avx2) {
        for (; valid; valid &= valid - 1) {
            const int k = __builtin_ctz(valid);
            if (closestHitWith(rays[k], tMax[k], isa_, out[k])) found |= 1u << k;
        }
        return found;
    }
    TriangleLeafHit best[8];
    for (int k = 0; k < 8; ++k)
        best[k] = TriangleLeafHit{(valid >> k) & 1 ? tMax[k] : 0.0f, UINT32_MAX, 0.0f, 0.0f, 0.0f};
    closestTriangle8Avx2(bvh_.nodes.data(), rays, valid, TriangleLeafData{positions_.data(), source_.data()}, best);
    for (; valid; valid &= valid - 1) {
        const int k = __builtin_ctz(valid);
        if (best[k].slot == UINT32_MAX) continue;
        out[k] = MeshHit{best[k].t, best[k].slot, best[k].b0, best[k].b1, best[k].b2};
        found |= 1u << k;
    }
    return found;
}

unsigned MeshBvh::anyHit8(const Ray* rays, const float* tMax, unsigned valid) const {
    valid &= 0xFFu;
    if (bvh_.empty() || !valid) return 0;
    if (isa_ == BvhIsa::Avx2)
        return anyTriangle8Avx2(bvh_.nodes.data(), rays, tMax, valid,
                                TriangleLeafData{positions_.data(), source_.data()});
    unsigned occluded = 0;
    for (; valid; valid &= valid - 1) {
        const int k = __builtin_ctz(valid);
        if (anyHit(rays[k], tMax[k], isa_)) occluded |= 1u << k;
    }
    return occluded;
}

}  // namespace shadelab::trace
