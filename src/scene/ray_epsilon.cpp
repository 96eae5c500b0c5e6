// secondaryRayEpsilon over sceneBounds, the eye and the planes' foot points.
#include "scene/ray_epsilon.h"

#include "scene/scene_load.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace shadelab {

float secondaryRayEpsilon(const Scene& scene, const glm::vec3& eye) {
    Bounds box = sceneBounds(scene);
    box.extend(eye);
    for (const Plane& p : scene.planes) box.extend(eye - (glm::dot(p.normal, eye) - p.offset) * p.normal);
    const float radius = 0.5f * glm::length(box.hi - box.lo);
    const glm::vec3 mag = glm::max(glm::abs(box.lo), glm::abs(box.hi));
    const float e = std::max({1e-4f * radius, 1e-6f * std::max({mag.x, mag.y, mag.z}), 1e-7f});
    return std::isfinite(e) ? e : 1e-4f;
}

}  // namespace shadelab
