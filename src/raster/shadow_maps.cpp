// ShadowMaps: the depth-only passes per layer of what fitShadows (shadow_fit.h) fitted, and the GL storage.
#include "raster/shadow_maps.h"

#include "raster/shadow_fit.h"
#include "raster/triangle_batches.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <glm/matrix.hpp>
#include <stdexcept>
#include <string>

namespace shadelab::raster {

ShadowMaps::ShadowMaps(const gl::ShaderLibrary& shaders, bool buildNow) : shaders_(&shaders) {
    if (buildNow) buildPrograms();
    ubo_ = gl::Buffer::create();
    glBindBuffer(GL_UNIFORM_BUFFER, ubo_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(ShadowBlock), &block_, GL_DYNAMIC_DRAW);  // defined even if unused
    fbo_ = gl::Framebuffer::create();
    allocate(1, 1);
}

void ShadowMaps::buildPrograms() {
    if (meshDepth_.id()) return;
    meshDepth_ = gl::Program::build(*shaders_, "shadow_mesh.vert", "shadow_depth.frag");
    sphereDepth_ = gl::Program::build(*shaders_, "shadow_sphere.vert", "shadow_sphere.frag");
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
    while (glGetError() != GL_NO_ERROR) {}
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
                        GLuint meshVao, GLuint cubeVao, size_t batchTriangles) {
    const ShadowFit fit = fitShadows(scene, casterBounds(scene, ranges), settings);
    block_ = fit.block;
    const int size = block_.info.z, layers = fit.layers;
    layerCount_ = layers;
    allocate(layers > 0 ? size : std::max(size_, 1), std::max(layers, 1));

    glBindBuffer(GL_UNIFORM_BUFFER, ubo_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(ShadowBlock), &block_);
    if (layers == 0) return;
    buildPrograms();

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
    for (int layer = 0; layer < layers; ++layer) drawLayer(scene, ranges, meshVao, cubeVao, layer, batchTriangles);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::checkError("ShadowMaps::render");
}

void ShadowMaps::drawLayer(const Scene& scene, const std::vector<DrawRange>& ranges, GLuint meshVao, GLuint cubeVao,
                           int layer, size_t batchTriangles) const {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, maps_.id(), 0, layer);
    const float farDepth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    const glm::mat4& vp = block_.layerViewProj[layer];

    glDisable(GL_CULL_FACE);
    glUseProgram(meshDepth_.id());
    meshDepth_.set("u_lightViewProj", vp, gl::Program::Uniform::Required);
    glBindVertexArray(meshVao);
    TriangleBatches batches(batchTriangles);
    for (const DrawRange& r : ranges) {
        if (r.mesh >= scene.meshes.size() || r.part >= scene.meshes[r.mesh].parts.size()) continue;
        if (outsideClip(vp, r.lo, r.hi)) continue;  // per part, per layer (cube faces cull most parts)
        batches.draw(r.firstIndex, r.indexCount);
    }

    // Sphere impostors ray-cast from the light: back faces of the bounding cube, as in the colour pass.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CCW);
    glUseProgram(sphereDepth_.id());
    sphereDepth_.set("u_lightViewProj", vp, gl::Program::Uniform::Required);
    const glm::mat4 inverse = glm::inverse(vp);
    sphereDepth_.set("u_lightInverse", inverse, gl::Program::Uniform::Required);
    sphereDepth_.set("u_mapSize", float(size_), gl::Program::Uniform::Required);
    glBindVertexArray(cubeVao);
    for (const Sphere& s : scene.spheres) {
        if (outsideClip(vp, s.center - glm::vec3(s.radius), s.center + glm::vec3(s.radius))) continue;
        sphereDepth_.set("u_center", s.center, gl::Program::Uniform::Required);
        sphereDepth_.set("u_radius", s.radius, gl::Program::Uniform::Required);
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
