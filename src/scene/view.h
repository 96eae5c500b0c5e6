// ViewSetup: the camera basis, matrices and clip distances for one image size, derived from the scene.
// Both renderers build primary rays from it (shading::cameraRayDirection), so they agree to the bit.
#pragma once

#include "scene/scene.h"

#include <cmath>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace shadelab {

// tan(fovY / 2) for a vertical field of view in degrees, the same bits in every build: in double, rounded to
// float. glibc's and musl's tanf (the native and the web page's WebAssembly builds) differ in the last bit for
// about one field of view in seven, which would move every primary ray of the page's reference off the native
// tracer's; their double tan rounded to float agrees (checked over 179,000 angles from 0 to 179°).
inline float tanHalfFov(float fovYDegrees) { return float(std::tan(double(glm::radians(fovYDegrees)) * 0.5)); }

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
