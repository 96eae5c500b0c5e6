#include "app/light_markers.h"

#include "scene/scene_load.h"
#include "scene/view.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

namespace shadelab::app {
namespace {

struct SceneSphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};

// The scene's centre and radius; the camera's target and distance when nothing is bounded (planes only).
SceneSphere sceneSphere(const Scene& scene) {
    const Bounds b = sceneBounds(scene);
    if (b.empty()) {
        const float d = glm::length(scene.camera.position - scene.camera.target);
        return {scene.camera.target, std::max(d * 0.5f, 1e-3f)};
    }
    return {0.5f * (b.lo + b.hi), std::max(0.5f * glm::length(b.hi - b.lo), 1e-3f)};
}

glm::vec3 anchorOf(const Light& light, const SceneSphere& sphere) {
    if (light.positional()) return light.position;
    return sphere.center - glm::normalize(light.direction) * (1.2f * sphere.radius);
}

// World point → image pixel; false when behind the eye.
bool project(const ViewSetup& v, const glm::vec3& p, glm::vec2& pixel) {
    const glm::vec4 clip = v.viewProj * glm::vec4(p, 1.0f);
    if (clip.w <= 1e-6f) return false;
    pixel = {(clip.x / clip.w * 0.5f + 0.5f) * float(v.width),
             (1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * float(v.height)};
    return std::isfinite(pixel.x) && std::isfinite(pixel.y);
}

// The circle where the outer cone meets the plane `length` along the spot's axis, in 32 points.
std::vector<glm::vec2> coneRim(const ViewSetup& v, const Light& light, float length) {
    const glm::vec3 axis = glm::normalize(light.direction);
    const glm::vec3 helper = std::fabs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(axis, helper)), w = glm::cross(axis, u);
    const float radius = length * std::tan(std::min(light.outerConeAngle, 1.5f));
    std::vector<glm::vec2> rim;
    for (int k = 0; k < 32; ++k) {
        const float a = 2.0f * 3.14159265f * float(k) / 32.0f;
        glm::vec2 p;
        if (!project(v, light.position + length * axis + radius * (std::cos(a) * u + std::sin(a) * w), p)) return {};
        rim.push_back(p);
    }
    return rim;
}

}  // namespace

std::vector<LightMarker> lightMarkers(const Scene& scene, int width, int height) {
    std::vector<LightMarker> markers;
    if (width <= 0 || height <= 0) return markers;
    const ViewSetup v = makeViewSetup(scene, width, height);
    const SceneSphere sphere = sceneSphere(scene);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        LightMarker m;
        m.light = int(i);
        m.anchor = anchorOf(light, sphere);
        m.visible = project(v, m.anchor, m.pixel);
        if (!m.visible) {
            // Behind the camera (a model's key light often is): point from the image's centre toward it, so
            // its marker waits at the edge on that side.
            const glm::vec3 d = m.anchor - v.eye;
            glm::vec2 dir(glm::dot(d, v.right), -glm::dot(d, v.up));
            if (glm::length(dir) < 1e-6f) dir = glm::vec2(0.0f, -1.0f);
            m.pixel = glm::vec2(float(width), float(height)) * 0.5f + glm::normalize(dir) * float(width + height);
            m.visible = true;
        }
        m.arrowTip = m.pixel;
        if (light.type != LightType::Point) {  // directional and spot lights: an arrow along their light
            glm::vec2 tip;
            const glm::vec3 toward = m.anchor + glm::normalize(light.direction) * (0.35f * sphere.radius);
            if (project(v, toward, tip)) m.arrowTip = tip;
        }
        const glm::vec2 lo(kMarkerInset), hi(float(width) - kMarkerInset, float(height) - kMarkerInset);
        m.shown = glm::clamp(m.pixel, lo, glm::max(lo, hi));
        m.clamped = m.shown != m.pixel;
        if (light.type == LightType::Spot && !m.clamped) m.coneRim = coneRim(v, light, 0.35f * sphere.radius);
        markers.push_back(m);
    }
    return markers;
}

int markerAt(const std::vector<LightMarker>& markers, glm::vec2 pixel, float radius) {
    int best = -1;
    float bestDistance = radius;
    for (const LightMarker& m : markers) {
        if (!m.visible) continue;
        const float d = glm::length(m.shown - pixel);
        if (d <= bestDistance) best = m.light, bestDistance = d;
    }
    return best;
}

namespace {

// The camera ray through the pixel (the renderers' own formula), met with the plane through `through` that
// faces the camera; false when the ray runs parallel to it or meets it behind the eye.
bool underPointer(const ViewSetup& v, int width, int height, glm::vec2 pixel, const glm::vec3& through, glm::vec3& dir,
                  glm::vec3& point) {
    const float aspect = float(width) / float(height);
    const float x = (2.0f * pixel.x / float(width) - 1.0f) * v.tanHalfFovY * aspect;
    const float y = (1.0f - 2.0f * pixel.y / float(height)) * v.tanHalfFovY;
    dir = glm::normalize(v.forward + x * v.right + y * v.up);
    const float along = glm::dot(dir, v.forward);
    if (along <= 1e-4f) return false;
    const float t = glm::dot(through - v.eye, v.forward) / along;
    if (!(t > 0.0f)) return false;
    point = v.eye + t * dir;
    return true;
}

}  // namespace

int aimHandleAt(const Scene& scene, const std::vector<LightMarker>& markers, glm::vec2 pixel, float radius) {
    int best = -1;
    float bestDistance = radius;
    for (const LightMarker& m : markers) {
        if (!m.visible || m.clamped || size_t(m.light) >= scene.lights.size()) continue;
        if (scene.lights[size_t(m.light)].type != LightType::Spot) continue;
        const float d = glm::length(m.arrowTip - pixel);
        if (d <= bestDistance) best = m.light, bestDistance = d;
    }
    return best;
}

Light aimedSpot(const Scene& scene, int width, int height, int index, glm::vec2 pixel) {
    Light light = scene.lights.at(size_t(index));
    if (light.type != LightType::Spot) return light;
    const ViewSetup v = makeViewSetup(scene, width, height);
    const glm::vec3 tip = light.position + glm::normalize(light.direction) * (0.35f * sceneSphere(scene).radius);
    glm::vec3 dir, point;
    if (!underPointer(v, width, height, pixel, tip, dir, point)) return light;
    const glm::vec3 d = point - light.position;
    if (glm::length(d) > 1e-6f) light.direction = glm::normalize(d);
    return light;
}

Light draggedLight(const Scene& scene, int width, int height, int index, glm::vec2 pixel) {
    Light light = scene.lights.at(size_t(index));
    const ViewSetup v = makeViewSetup(scene, width, height);
    const SceneSphere sphere = sceneSphere(scene);
    const glm::vec3 anchor = anchorOf(light, sphere);
    glm::vec3 dir, moved;
    if (!underPointer(v, width, height, pixel, anchor, dir, moved)) return light;  // parallel, or behind: leave it
    if (light.positional()) {  // a spot keeps its direction: dragging moves it, the Lights panel aims it
        light.position = moved;
        return light;
    }
    // A directional light's marker lives on the sphere of radius 1.2 R about the scene's centre: the point
    // of that sphere under the pointer (the nearer one), else the plane point pushed onto the sphere.
    const float R = 1.2f * sphere.radius;
    const glm::vec3 oc = v.eye - sphere.center;
    const float b = glm::dot(oc, dir), c = glm::dot(oc, oc) - R * R, disc = b * b - c;
    glm::vec3 source = sphere.center + glm::normalize(moved - sphere.center) * R;
    if (disc >= 0.0f) {
        // Of the two points under the pointer, the one nearer where the source was: a source on the far
        // side of the sphere stays there instead of jumping to the front.
        float best = 1e30f;
        for (const float tHit : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
            const glm::vec3 p = v.eye + tHit * dir;
            if (tHit > 0.0f && glm::length(p - anchor) < best) source = p, best = glm::length(p - anchor);
        }
    }
    const glm::vec3 d = sphere.center - source;
    if (glm::length(d) > 1e-6f) light.direction = glm::normalize(d);
    return light;
}

}  // namespace shadelab::app
