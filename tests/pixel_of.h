// The pixel of a width x height image of a scene that contains a world point (tests of the viewer's state and
// window).
#pragma once

#include "scene/scene.h"
#include "scene/view.h"

#include <cmath>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab::test {

inline glm::ivec2 pixelOf(const Scene& scene, int width, int height, const glm::vec3& p) {
    const ViewSetup v = makeViewSetup(scene, width, height);
    const glm::vec4 clip = v.viewProj * glm::vec4(p, 1.0f);
    const float x = (clip.x / clip.w * 0.5f + 0.5f) * float(width);
    const float y = (1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * float(height);
    return {int(std::floor(x)), int(std::floor(y))};
}

}  // namespace shadelab::test
