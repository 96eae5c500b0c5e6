// C++ view of shaders/cube_face.glsl: the shadow lookup's cube-face selection compiled with GLM, so the
// fitted cube layers are tested against the shader's own expression. No GL.
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shadelab::raster::glsl {

using glm::abs;
using glm::vec2;
using glm::vec3;

#define SL_FN inline
#include "shaders/cube_face.glsl"
#undef SL_FN

}  // namespace shadelab::raster::glsl
