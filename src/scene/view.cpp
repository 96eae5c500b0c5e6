// ViewSetup from a Camera: orthonormal basis, look-at view, infinite-far perspective, scene-fitted near.
#include "scene/view.h"

#include "scene/scene_load.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace shadelab {

ViewSetup makeViewSetup(const Scene& scene, int width, int height) {
    const Camera& c = scene.camera;
    ViewSetup v;
    v.width = width;
    v.height = height;
    v.eye = c.position;
    v.forward = glm::normalize(c.target - c.position);
    v.right = glm::normalize(glm::cross(v.forward, c.up));
    v.up = glm::cross(v.right, v.forward);
    v.tanHalfFovY = tanHalfFov(c.fovY);

    // Near plane: half the distance to the nearest bounded geometry, but never so small that depth
    // precision collapses. Planes are unbounded and ride on the infinite far plane.
    Bounds b = sceneBounds(scene);
    float zNear = 0.01f;
    if (!b.empty()) {
        glm::vec3 centre = 0.5f * (b.lo + b.hi);
        float radius = 0.5f * glm::length(b.hi - b.lo);
        float dist = glm::length(centre - c.position);
        zNear = std::max({0.5f * (dist - radius), 1e-4f * (dist + radius), 1e-5f});
    }
    v.zNear = zNear;
    v.view = glm::lookAt(c.position, c.target, c.up);
    v.proj = glm::infinitePerspective(glm::radians(c.fovY), float(width) / float(height), zNear);
    v.viewProj = v.proj * v.view;
    return v;
}

}  // namespace shadelab
