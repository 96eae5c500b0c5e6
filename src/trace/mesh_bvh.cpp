// MeshBvh: gathering the scene's triangles, building the BVH, and the two traversals (nearest hit with an
// order-independent tie-break, and any hit for shadow rays). Ordered front-to-back traversal with a
// small fixed stack; no allocation and no virtual calls per ray.
#include "trace/mesh_bvh.h"

#include "trace/bvh_traverse.h"
#include "trace/bvh_traverse_avx2.h"
#include "trace/triangle_leaf.h"
#include "trace/watertight.h"
#include "util/check.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
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
    // One BvhPrim per finite, non-degenerate triangle: its box, its index in its part and the part's index.
    // `source` numbers every triangle, kept or not, in scene order.
    std::vector<BvhPrim> prims;
    size_t total = 0;
    for (const Mesh& m : scene.meshes) total += m.triangleCount();
    prims.reserve(total);
    uint32_t source = 0;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        for (const MeshPart& part : scene.meshes[m].parts) {
            SHADELAB_CHECK(part.geometry != nullptr);
            const MeshGeometry& p = *part.geometry;
            const uint32_t partIndex = uint32_t(partMesh_.size());
            partMesh_.push_back(uint32_t(m));
            geometry_.push_back(part.geometry);
            partFirst_.push_back(source);
            for (size_t t = 0; t < p.triangleCount(); ++t) {
                glm::vec3 v[3];
                for (int k = 0; k < 3; ++k) {
                    const uint32_t idx = p.indices[3 * t + size_t(k)];
                    SHADELAB_CHECK_LT(size_t(idx), p.positions.size());
                    v[k] = p.positions[idx];
                }
                if (!finite(v[0]) || !finite(v[1]) || !finite(v[2])) continue;
                if (isDegenerateTriangle(v[0], v[1], v[2])) continue;
                const glm::vec3 lo = glm::min(glm::min(v[0], v[1]), v[2]), hi = glm::max(glm::max(v[0], v[1]), v[2]);
                prims.push_back(BvhPrim{{lo.x, lo.y, lo.z}, uint32_t(t), {hi.x, hi.y, hi.z}, partIndex});
                bounds_.lo = glm::min(bounds_.lo, lo);
                bounds_.hi = glm::max(bounds_.hi, hi);
            }
            SHADELAB_CHECK_LT(size_t(source) + p.triangleCount(), size_t(UINT32_MAX));
            source += uint32_t(p.triangleCount());
        }
    }
    // Pad every box by far more than a triangle hit's rounding, which scales with the coordinates' magnitude:
    // otherwise a triangle lying in its box's face can round to a hit just before the box's rounded entry and
    // be culled (SphereSet pads spheres the same way).
    if (!prims.empty()) {
        const glm::vec3 m = glm::max(glm::abs(bounds_.lo), glm::abs(bounds_.hi));
        const float pad = 1e-6f * std::max({m.x, m.y, m.z, 1e-30f});
        for (BvhPrim& b : prims)
            for (int a = 0; a < 3; ++a) {
                b.lo[a] -= pad;
                b.hi[a] += pad;
            }
        bounds_.lo -= glm::vec3(pad);
        bounds_.hi += glm::vec3(pad);
    }
    bvh_ = buildBvh(prims, options);

    // Store what the traversal and shading read in leaf order, so a leaf's triangles are contiguous in memory;
    // normals stay in the scene's geometry (interpolatedNormal reads them through the part). The ids first,
    // then the primitive references are freed before the positions are gathered: the peak holds only one.
    const size_t n = prims.size();
    part_.resize(n);
    source_.resize(n);
    for (size_t slot = 0; slot < n; ++slot) {
        part_[slot] = prims[slot].id2;
        source_[slot] = partFirst_[prims[slot].id2] + prims[slot].id;
    }
    std::vector<BvhPrim>().swap(prims);
    positions_.resize(9 * n);
    for (size_t slot = 0; slot < n; ++slot) {
        const MeshGeometry& g = *geometry_[part_[slot]];
        const size_t tri = source_[slot] - partFirst_[part_[slot]];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& v = g.positions[g.indices[3 * tri + size_t(k)]];
            positions_[9 * slot + size_t(3 * k)] = v.x;
            positions_[9 * slot + size_t(3 * k + 1)] = v.y;
            positions_[9 * slot + size_t(3 * k + 2)] = v.z;
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
    const float* v = vertices(slot);
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

bool MeshBvh::closestHit(const Ray& ray, float tMax, MeshHit& out) const {
    return closestHitWith(ray, tMax, isa_, out);
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

bool MeshBvh::anyHit(const Ray& ray, float tMax) const { return anyHit(ray, tMax, isa_); }

bool MeshBvh::anyHit(const Ray& ray, float tMax, BvhIsa isa) const {
    if (bvh_.empty()) return false;
    const TriangleLeafData data{positions_.data(), source_.data()};
    if (isa == BvhIsa::Avx2) return anyTriangleAvx2(bvh_.nodes.data(), ray, data, tMax);
    return traverseAny(bvh_, makeBoxRay(ray), tMax,
                       AnyTriangleLeaf<watertight_detail::BaselineTag>{data, makeWatertightRay(ray), tMax});
}

}  // namespace shadelab::trace
