// C++ view of shaders/material_maps.glsl: the metallic-roughness, normal and occlusion mappings compiled
// with GLM over lighting.h, so the tracer maps texels exactly as mesh.frag does. No GL and no scene types.
#pragma once

#include "shading/lighting.h"

#include <glm/common.hpp>
#include <glm/vec4.hpp>

namespace shadelab::shading {

using glm::clamp;
using glm::vec4;

#define SL_FN inline
#include "shaders/material_maps.glsl"
#undef SL_FN

}  // namespace shadelab::shading
