// Ray r(t) = origin + t·dir, the one ray type of the tracer. Plain data; intersection routines live in
// watertight.h (triangles), bvh.h (boxes) and shading/lighting.h (spheres and planes, shared with GLSL).
#pragma once

#include <glm/vec3.hpp>

namespace shadelab::trace {

struct Ray {
    glm::vec3 origin{0.0f};            // world units
    glm::vec3 dir{0.0f, 0.0f, -1.0f};  // unit length: shading::intersectSphere relies on it
};

}  // namespace shadelab::trace
