// Camera: a pinhole with a vertical field of view (design.md §1). Aspect comes from the image size.
#pragma once

#include <glm/vec3.hpp>

namespace shadelab {

struct Camera {
    glm::vec3 position{0.0f, 1.5f, 6.0f};  // eye, world units
    glm::vec3 target{0.0f, 0.5f, 0.0f};    // point looked at, world units
    glm::vec3 up{0.0f, 1.0f, 0.0f};        // approximate up; re-orthogonalised
    float fovY = 45.0f;                    // vertical field of view, degrees, (0, 180)
};

}  // namespace shadelab
