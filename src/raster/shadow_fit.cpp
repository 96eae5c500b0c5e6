// Shadow-map fitting: a light's projection fitted to the casters' bounds, the depth-test constants, the
// planes that can block each light. Pure; the depth passes are in shadow_maps.cpp.
#include "raster/shadow_fit.h"

#include "scene/ray_epsilon.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace shadelab::raster {
namespace {

glm::vec3 upFor(const glm::vec3& forward) {
    return std::abs(forward.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

// Signed distance of a point from a plane, and the side of it a light shines from (0: in the plane).
float side(const Plane& p, const glm::vec3& x) { return glm::dot(p.normal, x) - p.offset; }
float lightSide(const Plane& p, const Light& l) {
    return l.positional() ? side(p, l.position) : -glm::dot(p.normal, l.direction);
}

}  // namespace

Bounds casterBounds(const Scene& scene, const std::vector<DrawRange>& ranges) {
    Bounds b;
    for (const Sphere& s : scene.spheres) {
        b.extend(s.center - glm::vec3(s.radius));
        b.extend(s.center + glm::vec3(s.radius));
    }
    for (const DrawRange& r : ranges) {
        if (r.mesh >= scene.meshes.size() || r.part >= scene.meshes[r.mesh].parts.size()) continue;
        b.extend(r.lo);
        b.extend(r.hi);
    }
    return b;
}

// Plane k's own pixels never need the test: their origin lies on the viewer's side, so when the light is on
// the other side N·L <= 0 and the diffuse and specular terms are 0 anyway. So plane k matters only when a
// caster's box reaches its far side, or another plane does (every non-parallel plane crosses it).
int planeMask(const Scene& scene, const Bounds& casters, const Light& l) {
    int mask = 0;
    const int planes = std::min<int>(int(scene.planes.size()), kMaxShadowPlanes);
    for (int k = 0; k < planes; ++k) {
        const Plane& p = scene.planes[size_t(k)];
        const float ls = lightSide(p, l);
        bool matters = ls == 0.0f || !std::isfinite(ls);
        for (int c = 0; c < 8 && !casters.empty() && !matters; ++c) {
            matters = side(p, casters.corner(c)) * ls < 0.0f;
        }
        for (size_t j = 0; j < scene.planes.size() && !matters; ++j) {
            if (int(j) == k) continue;
            const Plane& q = scene.planes[j];
            const bool parallel = glm::length(glm::cross(p.normal, q.normal)) <= 1e-6f;
            // A parallel plane j lies at a constant signed distance from plane k: its point nearest the origin.
            matters = !parallel || side(p, q.offset * q.normal) * ls <= 0.0f;
        }
        if (matters) mask |= 1 << k;
    }
    return mask;
}

glm::vec4 perspectiveDepthTest(float zNear, float zFar) {
    const float span = zFar - zNear;
    return glm::vec4(0.5f + 0.5f * (zFar + zNear) / span, zFar * zNear / span, 0.0f, 0.0f);
}

glm::vec4 orthoDepthTest(float zNear, float zFar, float texelWorld, float depthBiasTexels) {
    return glm::vec4(0.0f, 0.0f, depthBiasTexels * texelWorld / (zFar - zNear), 0.0f);
}

ShadowFit fitShadows(const Scene& scene, const Bounds& box, const RasterSettings& settings) {
    ShadowFit fit;
    ShadowBlock& block = fit.block;
    const int size = std::max(1, settings.shadowMapSize);
    block.info = glm::ivec4(0, settings.pcf ? 1 : 0, size, 0);
    block.bias =
        glm::vec4(settings.depthBias, settings.normalBias, secondaryRayEpsilon(scene, scene.camera.position), 0.0f);
    for (const Plane& p : scene.planes) {
        if (block.info.x == kMaxShadowPlanes) break;
        block.planes[block.info.x++] = glm::vec4(p.normal, p.offset);
    }

    // Fit each light's layers to the casters' bounding box and sphere.
    int& layers = fit.layers;
    const int lights = std::min<int>(int(scene.lights.size()), kMaxShadowedLights);
    if (!box.empty()) {
        const glm::vec3 c = box.centroid();
        const float R = std::max(0.5f * glm::length(box.hi - box.lo), 1e-6f);
        for (int i = 0; i < lights; ++i) {
            const Light& l = scene.lights[size_t(i)];
            glm::ivec4& kind = block.light[i];
            glm::vec4& range = block.range[i];
            kind.y = layers;
            if (l.type == LightType::Directional) {
                // Orthographic box around the casters, seen along the light's direction of travel.
                const glm::vec3 f = glm::normalize(l.direction);
                const glm::mat4 view = glm::lookAt(c - 2.0f * R * f, c, upFor(f));
                glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
                for (int k = 0; k < 8; ++k) {
                    glm::vec3 q = glm::vec3(view * glm::vec4(box.corner(k), 1.0f));
                    lo = glm::min(lo, q);
                    hi = glm::max(hi, q);
                }
                const float extent = std::max(hi.x - lo.x, hi.y - lo.y) * (1.0f + 4.0f / float(size)) + 1e-6f;
                const glm::vec2 mid(0.5f * (lo.x + hi.x), 0.5f * (lo.y + hi.y));
                const float zNear = -hi.z - 0.01f * R, zFar = -lo.z + 0.01f * R;
                block.layerViewProj[layers++] = glm::ortho(mid.x - 0.5f * extent, mid.x + 0.5f * extent,
                                                           mid.y - 0.5f * extent, mid.y + 0.5f * extent, zNear, zFar) *
                                                view;
                kind.x = kShadowOrtho;
                range = glm::vec4(extent / float(size), zNear, zFar, 0.0f);
                block.depth[i] = orthoDepthTest(zNear, zFar, range.x, settings.depthBias);
                continue;
            }
            const float d = glm::length(c - l.position);
            if (d > 1.05f * R) {
                // Outside the casters' bounding sphere: one frustum holds every caster (a spotlight's map).
                const float half = std::asin(std::min(R / d, 1.0f)) * (1.0f + 2.0f / float(size));
                const float zNear = 0.98f * (d - R), zFar = 1.02f * (d + R);
                const glm::vec3 f = (c - l.position) / d;
                block.layerViewProj[layers++] =
                    glm::perspective(2.0f * half, 1.0f, zNear, zFar) * glm::lookAt(l.position, c, upFor(f));
                kind.x = kShadowPerspective;
                range = glm::vec4(2.0f * std::tan(half) / float(size), zNear, zFar, 0.0f);
                block.depth[i] = perspectiveDepthTest(zNear, zFar);
                continue;
            }
            // Inside: a cube of six 90° faces, in the order +X −X +Y −Y +Z −Z. shaders/cube_face.glsl selects
            // the face and its coordinates from these lookAt bases directly, so keep the two in step
            // (shadow_fit_test checks them).
            const float zFar = 1.02f * (d + R), zNear = 1e-3f * zFar;
            const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, zNear, zFar);
            for (int face = 0; face < 6; ++face) {
                glm::vec3 axis(0.0f);
                axis[face / 2] = face % 2 ? -1.0f : 1.0f;
                const glm::vec3 up = face / 2 == 1 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
                block.layerViewProj[layers++] = proj * glm::lookAt(l.position, l.position + axis, up);
            }
            kind.x = kShadowCube;
            range = glm::vec4(2.0f / float(size), zNear, zFar, 0.0f);
            block.depth[i] = perspectiveDepthTest(zNear, zFar);
        }
    }
    for (int i = 0; i < lights; ++i) block.light[i].z = planeMask(scene, box, scene.lights[size_t(i)]);
    return fit;
}

}  // namespace shadelab::raster
