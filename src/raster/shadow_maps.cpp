// ShadowMaps: fitting a light's projection to the casters' bounds, and the depth-only passes per layer.
#include "raster/shadow_maps.h"

#include "scene/bounds.h"
#include "scene/ray_epsilon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <stdexcept>
#include <string>

namespace shadelab::raster {
namespace {

// Bounds of everything that casts: spheres and uploaded mesh parts (planes occlude analytically).
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

glm::vec3 upFor(const glm::vec3& forward) {
    return std::abs(forward.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

// Signed distance of a point from a plane, and the side of it a light shines from (0: in the plane).
float side(const Plane& p, const glm::vec3& x) { return glm::dot(p.normal, x) - p.offset; }
float lightSide(const Plane& p, const Light& l) {
    return l.type == LightType::Point ? side(p, l.position) : -glm::dot(p.normal, l.direction);
}

// Planes that can block light l for some visible receiver (ShadowBlock::light[].z). The tracer's shadow ray
// from origin O is blocked by plane k exactly when O and the light lie strictly on opposite sides of it.
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

}  // namespace

glm::vec4 perspectiveDepthTest(float zNear, float zFar) {
    const float span = zFar - zNear;
    return glm::vec4(0.5f + 0.5f * (zFar + zNear) / span, zFar * zNear / span, 0.0f, 0.0f);
}

glm::vec4 orthoDepthTest(float zNear, float zFar, float texelWorld, float depthBiasTexels) {
    return glm::vec4(0.0f, 0.0f, depthBiasTexels * texelWorld / (zFar - zNear), 0.0f);
}

ShadowMaps::ShadowMaps(const gl::ShaderLibrary& shaders) {
    meshDepth_ = gl::Program::build(shaders, "shadow_mesh.vert", "shadow_depth.frag");
    sphereDepth_ = gl::Program::build(shaders, "shadow_sphere.vert", "shadow_sphere.frag");
    ubo_ = gl::Buffer::create();
    glBindBuffer(GL_UNIFORM_BUFFER, ubo_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(ShadowBlock), &block_, GL_DYNAMIC_DRAW);  // defined even if unused
    fbo_ = gl::Framebuffer::create();
    allocate(1, 1);
}

void ShadowMaps::allocate(int size, int layers) {
    if (size == size_ && layers <= allocatedLayers_) return;
    GLint maxSize = 0, maxLayers = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    const double mib = double(size) * double(size) * 4.0 * double(layers) / (1024.0 * 1024.0);
    const std::string what = "shadow maps of " + std::to_string(size) + "x" + std::to_string(size) + " texels x " +
                             std::to_string(layers) + " layers (" + std::to_string(int(mib + 0.5)) + " MiB)";
    const std::string advice = "; use a smaller shadow-map size (--shadow-map-size, raster.shadowMapSize)";
    if (size > maxSize || layers > maxLayers)
        throw std::runtime_error(what + " exceed this GL's limits (" + std::to_string(maxSize) + " texels, " +
                                 std::to_string(maxLayers) + " layers)" + advice);
    // llvmpipe allocates lazily and a later page fault would kill the process instead of failing here.
    if (mib > double(kMaxShadowMapMiB))
        throw std::runtime_error(what + " exceed the " + std::to_string(kMaxShadowMapMiB) + " MiB budget" + advice);
    while (glGetError() != GL_NO_ERROR) {
    }
    maps_ = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D_ARRAY, maps_.id());
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, size, size, layers, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 nullptr);
    if (glGetError() == GL_OUT_OF_MEMORY) {
        maps_ = gl::Texture();
        size_ = allocatedLayers_ = 0;
        throw std::runtime_error(what + " do not fit in memory" + advice);
    }
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    size_ = size;
    allocatedLayers_ = layers;
}

void ShadowMaps::render(const Scene& scene, const RasterSettings& settings, const std::vector<DrawRange>& ranges,
                        GLuint meshVao, GLuint cubeVao) {
    block_ = ShadowBlock{};
    const int size = std::max(1, settings.shadowMapSize);
    block_.info = glm::ivec4(0, settings.pcf ? 1 : 0, size, 0);
    block_.bias = glm::vec4(settings.depthBias, settings.normalBias, secondaryRayEpsilon(scene, scene.camera.position), 0.0f);
    for (const Plane& p : scene.planes) {
        if (block_.info.x == kMaxShadowPlanes) break;
        block_.planes[block_.info.x++] = glm::vec4(p.normal, p.offset);
    }

    // Fit each light's layers to the casters' bounding box and sphere.
    const Bounds box = casterBounds(scene, ranges);
    int layers = 0;
    const int lights = std::min<int>(int(scene.lights.size()), kMaxShadowedLights);
    if (!box.empty()) {
        const glm::vec3 c = box.centroid();
        const float R = std::max(0.5f * glm::length(box.hi - box.lo), 1e-6f);
        for (int i = 0; i < lights; ++i) {
            const Light& l = scene.lights[size_t(i)];
            glm::ivec4& kind = block_.light[i];
            glm::vec4& range = block_.range[i];
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
                block_.layerViewProj[layers++] = glm::ortho(mid.x - 0.5f * extent, mid.x + 0.5f * extent,
                                                            mid.y - 0.5f * extent, mid.y + 0.5f * extent, zNear, zFar) *
                                                 view;
                kind.x = kShadowOrtho;
                range = glm::vec4(extent / float(size), zNear, zFar, 0.0f);
                block_.depth[i] = orthoDepthTest(zNear, zFar, range.x, settings.depthBias);
                continue;
            }
            const float d = glm::length(c - l.position);
            if (d > 1.05f * R) {
                // Outside the casters' bounding sphere: one frustum holds every caster (a spotlight's map).
                const float half = std::asin(std::min(R / d, 1.0f)) * (1.0f + 2.0f / float(size));
                const float zNear = 0.98f * (d - R), zFar = 1.02f * (d + R);
                const glm::vec3 f = (c - l.position) / d;
                block_.layerViewProj[layers++] =
                    glm::perspective(2.0f * half, 1.0f, zNear, zFar) * glm::lookAt(l.position, c, upFor(f));
                kind.x = kShadowPerspective;
                range = glm::vec4(2.0f * std::tan(half) / float(size), zNear, zFar, 0.0f);
                block_.depth[i] = perspectiveDepthTest(zNear, zFar);
                continue;
            }
            // Inside: a cube of six 90° faces, in the order +X −X +Y −Y +Z −Z. shadow.glsl selects the face and
            // its coordinates from these lookAt bases directly (cubeFaceCoords), so keep the two in step.
            const float zFar = 1.02f * (d + R), zNear = 1e-3f * zFar;
            const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, zNear, zFar);
            for (int face = 0; face < 6; ++face) {
                glm::vec3 axis(0.0f);
                axis[face / 2] = face % 2 ? -1.0f : 1.0f;
                const glm::vec3 up = face / 2 == 1 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
                block_.layerViewProj[layers++] = proj * glm::lookAt(l.position, l.position + axis, up);
            }
            kind.x = kShadowCube;
            range = glm::vec4(2.0f / float(size), zNear, zFar, 0.0f);
            block_.depth[i] = perspectiveDepthTest(zNear, zFar);
        }
    }
    for (int i = 0; i < lights; ++i) block_.light[i].z = planeMask(scene, box, scene.lights[size_t(i)]);
    layerCount_ = layers;
    allocate(layers > 0 ? size : std::max(size_, 1), std::max(layers, 1));

    glBindBuffer(GL_UNIFORM_BUFFER, ubo_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(ShadowBlock), &block_);
    if (layers == 0) return;

    // Depth-only passes: no colour attachment, a trivial fragment shader for meshes, both faces cast.
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    glViewport(0, 0, size_, size_);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    for (int layer = 0; layer < layers; ++layer) drawLayer(scene, ranges, meshVao, cubeVao, layer);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::checkError("ShadowMaps::render");
}

void ShadowMaps::drawLayer(const Scene& scene, const std::vector<DrawRange>& ranges, GLuint meshVao, GLuint cubeVao,
                           int layer) const {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, maps_.id(), 0, layer);
    const float farDepth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    const glm::mat4& vp = block_.layerViewProj[layer];

    glDisable(GL_CULL_FACE);
    glUseProgram(meshDepth_.id());
    glUniformMatrix4fv(meshDepth_.uniform("u_lightViewProj"), 1, GL_FALSE, glm::value_ptr(vp));
    glBindVertexArray(meshVao);
    for (const DrawRange& r : ranges) {
        if (r.mesh >= scene.meshes.size() || r.part >= scene.meshes[r.mesh].parts.size()) continue;
        if (outsideClip(vp, r.lo, r.hi)) continue;  // per part, per layer (cube faces cull most parts)
        glDrawElements(GL_TRIANGLES, GLsizei(r.indexCount), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(r.firstIndex * sizeof(uint32_t)));
    }

    // Sphere impostors ray-cast from the light: back faces of the bounding cube, as in the colour pass.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CCW);
    glUseProgram(sphereDepth_.id());
    glUniformMatrix4fv(sphereDepth_.uniform("u_lightViewProj"), 1, GL_FALSE, glm::value_ptr(vp));
    const glm::mat4 inverse = glm::inverse(vp);
    glUniformMatrix4fv(sphereDepth_.uniform("u_lightInverse"), 1, GL_FALSE, glm::value_ptr(inverse));
    glUniform1f(sphereDepth_.uniform("u_mapSize"), float(size_));
    glBindVertexArray(cubeVao);
    for (const Sphere& s : scene.spheres) {
        if (outsideClip(vp, s.center - glm::vec3(s.radius), s.center + glm::vec3(s.radius))) continue;
        glUniform3fv(sphereDepth_.uniform("u_center"), 1, glm::value_ptr(s.center));
        glUniform1f(sphereDepth_.uniform("u_radius"), s.radius);
        glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
}

void ShadowMaps::setEpsilon(float epsilon) {
    if (block_.bias.z == epsilon) return;
    block_.bias.z = epsilon;
    glBindBuffer(GL_UNIFORM_BUFFER, ubo_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, GLintptr(offsetof(ShadowBlock, bias)), sizeof(block_.bias), &block_.bias);
}

void ShadowMaps::bind(GLuint blockBinding, GLuint textureUnit) const {
    glBindBufferBase(GL_UNIFORM_BUFFER, blockBinding, ubo_.id());
    glActiveTexture(GL_TEXTURE0 + textureUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, maps_.id());
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace shadelab::raster
