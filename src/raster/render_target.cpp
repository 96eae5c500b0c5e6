// RenderTarget allocation and readback.
#include "raster/render_target.h"

#include "gl/shader_dialect.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace shadelab::raster {
namespace {

gl::Texture makeTexture(GLint internalFormat, GLenum format, GLenum type, int w, int h) {
    gl::Texture t = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, w, h, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

// glReadPixels returns the bottom row first; image files start at the top.
template <typename T>
void flipRows(T* data, int width, int height, int channels) {
    size_t row = size_t(width) * size_t(channels);
    std::vector<T> tmp(row);
    for (int y = 0; y < height / 2; ++y) {
        T* a = data + size_t(y) * row;
        T* b = data + size_t(height - 1 - y) * row;
        std::memcpy(tmp.data(), a, row * sizeof(T));
        std::memcpy(a, b, row * sizeof(T));
        std::memcpy(b, tmp.data(), row * sizeof(T));
    }
}

// Whether glReadPixels may read the bound R32UI buffer as GL_RED_INTEGER. Desktop GL converts to any format;
// OpenGL ES 3.0 (§4.3.1) and WebGL2 take only GL_RGBA_INTEGER for an unsigned integer buffer, or the one
// pair the implementation names for it.
bool readsRedInteger() {
    if (gl::currentContextDialect() == gl::ShaderDialect::Glsl330) return true;
    GLint format = 0, type = 0;
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &type);
    return format == GL_RED_INTEGER && type == GL_UNSIGNED_INT;
}

}  // namespace

void RenderTarget::resize(int width, int height, bool withCoverage, bool withAlpha) {
    if (width == width_ && height == height_ && fbo_ && withCoverage == hasCoverage() && withAlpha == withAlpha_)
        return;
    width_ = width;
    height_ = height;
    withAlpha_ = withAlpha;
    coverage_ = withCoverage ? makeTexture(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, width, height) : gl::Texture();
    depth_ = gl::Renderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);

    fbo_ = gl::Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    if (coverage_) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, coverage_.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GLenum(coverage_ ? GL_COLOR_ATTACHMENT1 : GL_NONE)};
    glDrawBuffers(2, buffers);
    const auto attachColor = [&](GLint internalFormat, GLenum format) {
        color_ = makeTexture(internalFormat, format, GL_FLOAT, width, height);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);
        return glCheckFramebufferStatus(GL_FRAMEBUFFER);
    };
    GLenum status = GL_FRAMEBUFFER_UNSUPPORTED;
    if (!withAlpha && gl::currentContextDialect() == gl::ShaderDialect::Glsl330) {
        status = attachColor(GL_RGB32F, GL_RGB);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            while (glGetError() != GL_NO_ERROR) {}  // a GL that refuses the format may say so; RGBA32F follows
    }
    if (status != GL_FRAMEBUFFER_COMPLETE) status = attachColor(GL_RGBA32F, GL_RGBA);
    // OpenGL ES 3.0 renders into RGBA32F only with EXT_color_buffer_float (WebGL2: the extension of that name).
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("raster framebuffer incomplete (status 0x" + std::to_string(status) + ") at " +
                                 std::to_string(width) + "x" + std::to_string(height) +
                                 "; an OpenGL ES context needs EXT_color_buffer_float");
    gl::checkError("RenderTarget::resize");
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
}

void RenderTarget::readColor(ImageF& out) const {
    out = ImageF(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, out.rgba.data());
    gl::checkError("RenderTarget::readColor");
    flipRows(out.rgba.data(), width_, height_, 4);
}

void RenderTarget::readColorRows(int row, int count, ImageF& out) const {
    if (out.width != width_ || out.height != count || row < 0 || row + count > height_)
        throw std::logic_error("RenderTarget::readColorRows: destination does not fit");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, height_ - row - count, width_, count, GL_RGBA, GL_FLOAT, out.rgba.data());
    flipRows(out.rgba.data(), width_, count, 4);
    gl::checkError("RenderTarget::readColorRows");
}

void RenderTarget::readCoverage(std::vector<uint32_t>& out) const {
    if (!coverage_) throw std::logic_error("RenderTarget::readCoverage: target was made without coverage");
    out.assign(size_t(width_) * size_t(height_), 0u);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    if (readsRedInteger()) {
        glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT, out.data());
    } else {
        std::vector<uint32_t> rgba(out.size() * 4);
        glReadPixels(0, 0, width_, height_, GL_RGBA_INTEGER, GL_UNSIGNED_INT, rgba.data());
        for (size_t i = 0; i < out.size(); ++i) out[i] = rgba[4 * i];
    }
    gl::checkError("RenderTarget::readCoverage");
    flipRows(out.data(), width_, height_, 1);
}

void RenderTarget::readColor8(Image8& out, int top, Encoding encoding, const DisplaySettings& display,
                              uint64_t* nonFinite) const {
    constexpr int kStripRows = 64;
    if (out.width != width_ || out.channels != 3 || top < 0 || top + height_ > out.height)
        throw std::logic_error("RenderTarget::readColor8: destination does not fit the target");
    ImageF strip;
    for (int row = 0; row < height_; row += kStripRows) {
        int rows = std::min(kStripRows, height_ - row);
        if (strip.height != rows) strip = ImageF(width_, rows);
        readColorRows(row, rows, strip);
        Image8 converted = toImage8(strip, encoding, display, nonFinite);
        std::memcpy(&out.data[size_t(top + row) * size_t(width_) * 3], converted.data.data(), converted.data.size());
    }
    gl::checkError("RenderTarget::readColor8");
}

}  // namespace shadelab::raster
