// SphereSet: BVH over padded sphere boxes and its traversals. The padding keeps the box test
// conservative, so culling never changes which sphere intersectSphere reports.
#include "trace/sphere_set.h"

#include "shading/lighting.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadelab::trace {

SphereSet::SphereSet(const std::vector<Sphere>& spheres) {
    std::vector<Aabb> boxes;
    boxes.reserve(spheres.size());
    for (const Sphere& s : spheres) {
        // Pad by a little more than intersectSphere's rounding, relative to the radius and to the
        // magnitude of the coordinates, so grazing hits are never culled.
        const float m = std::max({std::fabs(s.center.x), std::fabs(s.center.y), std::fabs(s.center.z)});
        const float r = s.radius * (1.0f + 1e-4f) + 1e-6f * m;
        Aabb b;
        b.lo = s.center - glm::vec3(r);
        b.hi = s.center + glm::vec3(r);
        boxes.push_back(b);
        bounds_.extend(b);
    }
    BvhBuildOptions options;
    options.maxLeafSize = 2;
    bvh_ = buildBvh(boxes, options);
    for (uint32_t slot : bvh_.order) {
        spheres_.emplace_back(spheres[slot].center, spheres[slot].radius);
        index_.push_back(slot);
    }
}

std::optional<SphereHit> SphereSet::closestHit(const Ray& ray, float tMin, float tMax) const {
    if (bvh_.empty()) return std::nullopt;
    const BvhNode* nodes = bvh_.nodes.data();
    const BoxRay br = makeBoxRay(ray);
    if (slabEntry(br, nodes[0].lo(), nodes[0].hi(), tMax) == INFINITY) return std::nullopt;

    SphereHit best{tMax, UINT32_MAX};
    struct Entry {
        uint32_t node;
        float tEntry;
    } stack[kMaxBvhDepth];
    int sp = 0;
    uint32_t ni = 0;
    for (;;) {
        const BvhNode& node = nodes[ni];
        if (node.isLeaf()) {
            for (uint32_t s = node.first, end = node.first + node.count; s < end; ++s) {
                const glm::vec4& c = spheres_[s];
                const float t = shading::intersectSphere(ray.origin, ray.dir, glm::vec3(c), c.w, tMin);
                if (!(t > tMin)) continue;  // -1 is a miss
                if (t < best.t || (t == best.t && best.index != UINT32_MAX && index_[s] < best.index))
                    best = SphereHit{t, index_[s]};
            }
        } else {
            const BvhNode& c0 = nodes[node.first];
            const BvhNode& c1 = nodes[node.first + 1];
            float t0 = slabEntry(br, c0.lo(), c0.hi(), best.t);
            float t1 = slabEntry(br, c1.lo(), c1.hi(), best.t);
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
        for (;;) {
            if (sp == 0) return best.index == UINT32_MAX ? std::nullopt : std::optional<SphereHit>(best);
            --sp;
            if (stack[sp].tEntry <= best.t) break;
        }
        ni = stack[sp].node;
    }
}

bool SphereSet::anyHit(const Ray& ray, float tMin, float tMax) const {
    if (bvh_.empty()) return false;
    const BvhNode* nodes = bvh_.nodes.data();
    const BoxRay br = makeBoxRay(ray);
    uint32_t stack[kMaxBvhDepth];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const BvhNode& node = nodes[stack[--sp]];
        if (slabEntry(br, node.lo(), node.hi(), tMax) == INFINITY) continue;
        if (node.isLeaf()) {
            for (uint32_t s = node.first, end = node.first + node.count; s < end; ++s) {
                const glm::vec4& c = spheres_[s];
                const float t = shading::intersectSphere(ray.origin, ray.dir, glm::vec3(c), c.w, tMin);
                if (t > tMin && t < tMax) return true;
            }
        } else {
            stack[sp++] = node.first + 1;
            stack[sp++] = node.first;
        }
    }
    return false;
}

}  // namespace shadelab::trace
