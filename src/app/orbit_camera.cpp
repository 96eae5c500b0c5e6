// OrbitCamera conversions and the three mouse motions (rotate, pan, zoom).
#include "app/orbit_camera.h"

#include "scene/scene_limits.h"
#include "scene/view.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace shadelab::app {
namespace {

constexpr float kPi = 3.14159265358979f;

// A fixed orthonormal frame (a, b, up) about the orbit axis; yaw is measured from a toward b.
void axisFrame(const glm::vec3& up, glm::vec3& a, glm::vec3& b) {
    const glm::vec3 ref = std::fabs(up.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    a = glm::normalize(ref - glm::dot(ref, up) * up);
    b = glm::cross(up, a);
}

glm::vec3 safeUp(const glm::vec3& up) {
    const float len = glm::length(up);
    return len > 0.0f ? up / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

OrbitCamera orbitFromCamera(const Camera& camera) {
    OrbitCamera o;
    o.target = camera.target;
    o.up = safeUp(camera.up);
    o.fovY = camera.fovY;
    const glm::vec3 offset = camera.position - camera.target;
    o.distance = std::max(glm::length(offset), 1e-6f);
    const glm::vec3 d = offset / o.distance;
    glm::vec3 a, b;
    axisFrame(o.up, a, b);
    o.pitch = std::clamp(std::asin(std::clamp(glm::dot(d, o.up), -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    o.yaw = std::atan2(glm::dot(d, b), glm::dot(d, a));
    return o;
}

Camera cameraFromOrbit(const OrbitCamera& o) {
    glm::vec3 a, b;
    axisFrame(o.up, a, b);
    const float cp = std::cos(o.pitch);
    const glm::vec3 d = cp * (std::cos(o.yaw) * a + std::sin(o.yaw) * b) + std::sin(o.pitch) * o.up;
    Camera c;
    c.target = o.target;
    c.position = o.target + o.distance * d;
    c.up = o.up;
    c.fovY = o.fovY;
    return c;
}

void orbitRotate(OrbitCamera& o, float deltaYaw, float deltaPitch) {
    o.yaw = std::remainder(o.yaw + deltaYaw, 2.0f * kPi);
    o.pitch = std::clamp(o.pitch + deltaPitch, -kMaxPitch, kMaxPitch);
}

void orbitPan(OrbitCamera& o, float dx, float dy, float viewportHeight) {
    if (!(viewportHeight > 0.0f)) return;
    const Camera c = cameraFromOrbit(o);
    const glm::vec3 forward = glm::normalize(c.target - c.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, o.up));
    const glm::vec3 camUp = glm::cross(right, forward);
    // World units per pixel at the target's depth.
    const float scale = 2.0f * o.distance * tanHalfFov(o.fovY) / viewportHeight;
    o.target += (-dx * right + dy * camUp) * scale;
}

// Held within a scene's coordinate bound: thousands of steps out (a script's zoom) would reach infinity.
void orbitZoom(OrbitCamera& o, float steps) {
    o.distance = std::clamp(o.distance * std::pow(0.85f, steps), 1e-4f, kMaxCoordinate);
}

}  // namespace shadelab::app
