// OrbitCamera: the viewer's camera as target + distance + yaw/pitch about an up axis, and the conversions
// to and from the scene's pinhole Camera. Pure maths: no GL, no input handling (app.cpp maps the mouse).
#pragma once

#include "scene/camera.h"

#include <glm/vec3.hpp>

namespace shadelab::app {

struct OrbitCamera {
    glm::vec3 target{0.0f, 0.5f, 0.0f};  // point orbited about, world units
    float distance = 6.0f;               // eye to target, world units, > 0
    float yaw = 0.0f;                    // about `up`, radians
    float pitch = 0.0f;                  // above the plane normal to `up`, radians, within ±kMaxPitch
    glm::vec3 up{0.0f, 1.0f, 0.0f};      // unit orbit axis (the camera's up)
    float fovY = 45.0f;                  // vertical field of view, degrees
};

inline constexpr float kMaxPitch = 1.5533430f;  // 89 degrees: the view never flips over the pole

// Exact for the target, distance and field of view; the eye is reproduced to float rounding.
OrbitCamera orbitFromCamera(const Camera& camera);
Camera cameraFromOrbit(const OrbitCamera& orbit);

// Angles in radians; pitch is clamped to ±kMaxPitch.
void orbitRotate(OrbitCamera& orbit, float deltaYaw, float deltaPitch);
// Moves the target in the view plane by a drag of (dx, dy) pixels (y down) on a viewport `viewportHeight`
// pixels tall, so the point under the cursor follows it at the target's depth.
void orbitPan(OrbitCamera& orbit, float dx, float dy, float viewportHeight);
// Positive steps move closer; each step scales the distance by 0.85, within [1e-4, kMaxCoordinate].
void orbitZoom(OrbitCamera& orbit, float steps);

}  // namespace shadelab::app
