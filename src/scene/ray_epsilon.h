// secondaryRayEpsilon: how far secondary-ray origins are offset along the normal (design.md §1, "acne").
// The one definition that the tracer, the raster shadow lookups and the probe share.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

namespace shadelab {

// 1e-4 × the radius of the box around the spheres, the mesh triangles, `eye` and each plane's point
// nearest `eye` (a scene seen from afar gets a larger offset, as its hit points are less precise), and
// never below 1e-6 × the largest coordinate magnitude there, where float spacing sets the floor.
// `eye` is where the rays start: the camera, or a raster environment cube's centre.
float secondaryRayEpsilon(const Scene& scene, const glm::vec3& eye);

}  // namespace shadelab
