// Planar reflection: the frame block of the scene mirrored about a plane, seen from the real
// camera, so a screen-space lookup at the mirror's own pixel is exactly I(reflected ray) for one bounce
// (the classic mirror pass, e.g. Kilgard 1999, "Improving shadows and reflections via the stencil buffer").
// Not the drawing: RasterRenderer runs its passes with this frame into a second float target.
#pragma once

#include "raster/frame_block.h"
#include "scene/scene.h"

#include <glm/mat4x4.hpp>
#include <optional>

namespace shadelab::raster {

// Householder reflection about {x : n·x = offset}, as a 4x4 affine matrix: x' = x − 2(n·x − offset) n.
glm::mat4 mirrorMatrix(const glm::vec3& n, float offset);

// The frame for the mirrored pass: viewProj·M, the eye and camera basis mirrored (so impostor rays are the
// reflected rays), the clip plane on the viewer's side, mirror lookups off (one bounce). Empty when the
// eye lies in the plane (the mirror is seen edge-on and shows nothing).
std::optional<FrameBlock> mirroredFrame(const FrameBlock& frame, const Plane& plane);

// True when the plane gets a reflection pass: reflections on and some channel of kr above 0.
bool isMirror(const Scene& scene, const Plane& plane);

}  // namespace shadelab::raster
