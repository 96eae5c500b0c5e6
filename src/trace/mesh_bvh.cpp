// MeshBvh: gathering the scene's triangles, building the BVH, and the two traversals (nearest hit with an
// order-independent tie-break, and any hit for shadow rays). Ordered front-to-back traversal with a
// small fixed stack; no allocation and no virtual calls per ray.
#include "trace/mesh_bvh.h"

#include "trace/bvh_traverse.h"
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
    // Gather the finite triangles in scene order; `source` numbers every triangle, kept or not.
    std::vector<Bounds> boxes;
    std::vector<uint32_t> tmpPart, tmpSource;
    std::vector<float> tmpPos, tmpNrm;
    uint32_t source = 0, partIndex = 0;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        for (const MeshPart& part : scene.meshes[m].parts) {
            SHADELAB_CHECK(part.geometry != nullptr);
            const MeshGeometry& p = *part.geometry;
            partMesh_.push_back(uint32_t(m));
            geometry_.push_back(part.geometry);
            const bool hasNormals = p.normals.size() == p.positions.size();
            for (size_t t = 0; t < p.triangleCount(); ++t, ++source) {
                uint32_t idx[3];
                glm::vec3 v[3];
                for (int k = 0; k < 3; ++k) {
                    idx[k] = p.indices[3 * t + size_t(k)];
                    SHADELAB_CHECK_LT(size_t(idx[k]), p.positions.size());
                    v[k] = p.positions[idx[k]];
                }
                if (!finite(v[0]) || !finite(v[1]) || !finite(v[2])) continue;
                if (isDegenerateTriangle(v[0], v[1], v[2])) continue;
                Bounds box;
                for (const glm::vec3& q : v) box.extend(q);
                boxes.push_back(box);
                bounds_.extend(box);
                tmpPart.push_back(partIndex);
                tmpSource.push_back(source);
                // Without vertex normals, the geometric normal stands in (flat shading).
                const glm::vec3 flat = glm::cross(v[1] - v[0], v[2] - v[0]);
                for (int k = 0; k < 3; ++k) {
                    tmpPos.insert(tmpPos.end(), {v[k].x, v[k].y, v[k].z});
                    const glm::vec3 n = hasNormals ? p.normals[idx[k]] : flat;
                    tmpNrm.insert(tmpNrm.end(), {n.x, n.y, n.z});
                }
            }
            ++partIndex;
        }
    }
    // Pad every box by far more than a triangle hit's rounding, which scales with the coordinates' magnitude:
    // otherwise a triangle lying in its box's face can round to a hit just before the box's rounded entry and
    // be culled (SphereSet pads spheres the same way).
    if (!boxes.empty()) {
        const glm::vec3 m = glm::max(glm::abs(bounds_.lo), glm::abs(bounds_.hi));
        const glm::vec3 pad(1e-6f * std::max({m.x, m.y, m.z, 1e-30f}));
        for (Bounds& b : boxes) {
            b.lo -= pad;
            b.hi += pad;
        }
        bounds_.lo -= pad;
        bounds_.hi += pad;
    }
    bvh_ = buildBvh(boxes, options);

    // Store the per-triangle data in BVH order, so a leaf's triangles are contiguous in memory.
    const size_t n = boxes.size();
    positions_.resize(9 * n);
    normals_.resize(9 * n);
    part_.resize(n);
    source_.resize(n);
    for (size_t slot = 0; slot < n; ++slot) {
        const uint32_t src = bvh_.order[slot];
        std::copy_n(&tmpPos[9 * size_t(src)], 9, &positions_[9 * slot]);
        std::copy_n(&tmpNrm[9 * size_t(src)], 9, &normals_[9 * slot]);
        part_[slot] = tmpPart[src];
        source_[slot] = tmpSource[src];
    }
}

glm::vec3 MeshBvh::interpolatedNormal(const MeshHit& hit) const {
    const float* n = &normals_[size_t(hit.slot) * 9];
    return hit.b0 * glm::vec3(n[0], n[1], n[2]) + hit.b1 * glm::vec3(n[3], n[4], n[5]) +
           hit.b2 * glm::vec3(n[6], n[7], n[8]);
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

std::optional<MeshHit> MeshBvh::closestHit(const Ray& ray, float tMax) const {
    if (bvh_.empty()) return std::nullopt;  // skip the per-ray set-up for scenes without triangles
    const WatertightRay wr = makeWatertightRay(ray);
    MeshHit best{tMax, UINT32_MAX, 0.0f, 0.0f, 0.0f};
    traverseClosest(bvh_, makeBoxRay(ray), tMax, [&](uint32_t first, uint32_t count) {
        for (uint32_t s = first, end = first + count; s < end; ++s) {
            const float* v = &positions_[size_t(s) * 9];
            const std::optional<TriangleHit> h = intersectTriangle(wr, v, v + 3, v + 6, best.t);
            if (!h) continue;
            // Strictly nearer wins; an exact tie goes to the lower scene-order index.
            const bool better = best.slot == UINT32_MAX
                                    ? h->t < tMax
                                    : (h->t < best.t || (h->t == best.t && source_[s] < source_[best.slot]));
            if (better) best = MeshHit{h->t, s, h->b0, h->b1, h->b2};
        }
        return best.t;
    });
    return best.slot == UINT32_MAX ? std::nullopt : std::optional<MeshHit>(best);
}

bool MeshBvh::anyHit(const Ray& ray, float tMax) const {
    if (bvh_.empty()) return false;
    const WatertightRay wr = makeWatertightRay(ray);
    return traverseAny(bvh_, makeBoxRay(ray), tMax, [&](uint32_t first, uint32_t count) {
        for (uint32_t s = first, end = first + count; s < end; ++s) {
            const float* v = &positions_[size_t(s) * 9];
            const std::optional<TriangleHit> h = intersectTriangle(wr, v, v + 3, v + 6, tMax);
            if (h && h->t < tMax) return true;
        }
        return false;
    });
}

}  // namespace shadelab::trace
