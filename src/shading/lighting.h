// C++ view of shaders/lighting.glsl: the same text compiled with GLM, so the rasterizer's GLSL and the
// tracer's C++ evaluate one set of equations (design.md §1). No GL and no scene types here.
#pragma once

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab::shading {

using glm::abs;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::floor;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::refract;
using glm::sqrt;
using glm::vec2;
using glm::vec3;
using glm::vec4;

#define SL_FN inline
#include "shaders/lighting.glsl"
#undef SL_FN

}  // namespace shadelab::shading
