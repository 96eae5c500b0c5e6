// ViewSetup: the camera basis, matrices and clip distances for one image size, derived from the scene.
// Both renderers build primary rays from it (shading::cameraRayDirection), so they agree to the bit.
#pragma once

#include "scene/scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace shadelab {

struct ViewSetup {
    int width = 0, height = 0;  // pixels
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};  // orthonormal
    float tanHalfFovY = 0.4142f;
    float zNear = 0.01f;  // raster near plane, world units; the far plane is at infinity
    glm::mat4 view{1.0f}, proj{1.0f}, viewProj{1.0f};
};

ViewSetup makeViewSetup(const Scene& scene, int width, int height);

}  // namespace shadelab
