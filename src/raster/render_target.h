// RenderTarget: the rasterizer's own framebuffer (design.md §2): RGBA32F linear colour (RGB32F when the alpha
// is not wanted and the GL renders to it), R32UI coverage ids (only when asked for: they cost 4 bytes a pixel)
// and a 32-bit float depth buffer. Never the default framebuffer or an EGL surface.
#pragma once

#include "gl/objects.h"
#include "image/encode.h"
#include "image/image.h"

#include <cstdint>
#include <vector>

namespace shadelab::raster {

class RenderTarget {
public:
    // Reallocates only when the size, the coverage or the alpha choice changes. Needs a current context.
    // withAlpha false: RGB32F colour where the framebuffer is complete with it (desktop Mesa's is; OpenGL ES and
    // WebGL2 render to no three-channel float format, and get RGBA32F), a quarter less memory for an image
    // whose alpha nobody reads. Read back as RGBA, its alpha is 1.
    void resize(int width, int height, bool withCoverage, bool withAlpha = true);
    void bind() const;
    int width() const { return width_; }
    int height() const { return height_; }
    bool hasCoverage() const { return bool(coverage_); }
    GLuint colorTexture() const { return color_.id(); }
    GLuint coverageTexture() const { return coverage_.id(); }  // 0 when made without coverage
    GLuint framebuffer() const { return fbo_.id(); }

    // Read back with row 0 at the top.
    void readColor(ImageF& out) const;
    // Rows [row, row + count) of the target (from the top) into `out`, which must be width x count.
    void readColorRows(int row, int count, ImageF& out) const;
    void readCoverage(std::vector<uint32_t>& out) const;

    // Reads colour a strip of rows at a time and converts each with toImage8 (the one shared conversion),
    // so no full float copy of the image is ever held on the CPU. The target's rows land in `out` from
    // row `top` on, through `display` (image/view_transform.h); `out` must be RGB and as wide as the target. Non-finite
    // pixels are added to *nonFinite.
    void readColor8(Image8& out, int top, Encoding encoding, const DisplaySettings& display, uint64_t* nonFinite) const;

private:
    int width_ = 0, height_ = 0;
    bool withAlpha_ = true;  // as asked: the texture may have alpha anyway (see resize)
    gl::Framebuffer fbo_;
    gl::Texture color_;
    gl::Texture coverage_;
    gl::Renderbuffer depth_;
};

}  // namespace shadelab::raster
