// Environment cubes: face frames and the cube textures they render into.
#include "raster/environment_cubes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

namespace shadelab::raster {
namespace {

// Camera basis per face so that window pixel (x, y) of the face's render is texel (s, t) of that cube face
// (OpenGL 4.6 core, table 8.19: e.g. +X has sc = −rz, tc = −ry).
struct FaceBasis {
    glm::vec3 forward, right, up;
};
constexpr FaceBasis kFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
};

}  // namespace

FrameBlock cubeFaceFrame(const FrameBlock& frame, const glm::vec3& centre, float zNear, int face, int size) {
    const FaceBasis& b = kFaces[face];
    FrameBlock f = frame;
    f.viewProj =
        glm::infinitePerspective(glm::radians(90.0f), 1.0f, zNear) * glm::lookAt(centre, centre + b.forward, b.up);
    f.eye = glm::vec4(centre, 1.0f);
    f.forward = glm::vec4(b.forward, 0.0f);
    f.right = glm::vec4(b.right, 0.0f);
    f.up = glm::vec4(b.up, 0.0f);
    f.viewport = glm::vec4(float(size), float(size), 1.0f, 0.0f);  // tan(45°) = 1, one band
    f.clipPlane = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    f.flags.w &= ~kPassMirrors;
    return f;
}

void EnvironmentCubes::resize(int count, int size) {
    if (size != size_) cubes_.clear();
    const size_t before = cubes_.size();
    const bool newDepth = count > 0 && (!depth_ || size != depthSize_);
    size_ = size;
    while (int(cubes_.size()) < count) {
        gl::Texture t = gl::Texture::create();
        glBindTexture(GL_TEXTURE_CUBE_MAP, t.id());
        for (int face = 0; face < 6; ++face)
            glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA16F, size, size, 0, GL_RGBA, GL_FLOAT,
                         nullptr);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        cubes_.push_back(std::move(t));
    }
    if (!fbo_) fbo_ = gl::Framebuffer::create();
    if (newDepth) {
        depth_ = gl::Renderbuffer::create();
        glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        depthSize_ = size;
    }
    // Completeness is checked here, once per new texture or depth buffer, not per face drawn: under WebGL the
    // check is a round trip to the GPU process, up to six of them a frame while a material is dragged. Every
    // face of a cube has the same format and size, so face 0 of each new cube (or of the first, for a new
    // depth buffer) stands for all six.
    for (size_t cube = newDepth ? 0 : before; cube < cubes_.size(); ++cube) {
        attachFace(int(cube), 0);
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("environment cube framebuffer incomplete (status 0x" + std::to_string(status) +
                                     ")");
        if (newDepth) break;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::checkError("EnvironmentCubes::resize");
}

void EnvironmentCubes::attachFace(int cube, int face) const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face),
                           cubes_[size_t(cube)].id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_NONE};
    glDrawBuffers(2, buffers);
}

void EnvironmentCubes::bindFace(int cube, int face) const {
    attachFace(cube, face);
    glViewport(0, 0, size_, size_);
}

}  // namespace shadelab::raster
