// DrawRange: one uploaded mesh part inside the renderer's shared vertex/index buffers, with its world
// bounds for frustum culling. Shared by the colour passes and the shadow-map passes; holds no GL object.
#pragma once

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace shadelab::raster {

struct DrawRange {
    size_t mesh, part;
    size_t firstIndex, indexCount;
    glm::vec3 lo, hi;  // world-space bounds, for culling
};

// Conservative test: true when the box lies wholly outside one side of the clip volume (far is ignored).
bool outsideClip(const glm::mat4& viewProj, const glm::vec3& lo, const glm::vec3& hi);

}  // namespace shadelab::raster
