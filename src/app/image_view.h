// ImageView: draws the rendered image into a rectangle of the window (raster, reference, wipe or
// difference), with the display's exposure and view transform and the sRGB curve in shaders/view_image.frag,
// and the selected object's outline. Display only: captures read the renderers' float images, never the window.
// GL only (no window, no ImGui), so the web page shows its raster image through it too.
#pragma once

#include "app/image_rect.h"
#include "app/viewer_state.h"
#include "gl/program.h"

#include <cstdint>
#include <optional>

namespace shadelab::app {

struct ImageViewInputs {
    GLuint raster = 0;                    // RGBA32F texture
    int imageWidth = 0, imageHeight = 0;  // its size (the traced texture has the same)
    GLuint traced = 0;                    // RGBA32F texture, or 0
    GLuint tiles = 0;                     // R8 tile-state texture, or 0
    int tileSize = 32;
    ViewMode mode = ViewMode::Raster;
    Encoding encoding = Encoding::Srgb;
    DisplaySettings display;  // exposure and view transform of every mode but Difference
    float split = 0.5f;
    float gain = 16.0f;
    GLuint coverage = 0;    // R32UI coverage ids of the raster image, or 0
    uint32_t selected = 0;  // coverage id outlined in the image (scene/coverage.h); 0: none
    // The image pixels (GL row order, x and y the lower-left corner) where the selected object's coverage ids can
    // lie (RasterRenderer::objectRect), or unset: anywhere. The outline's look-ups run only around them.
    std::optional<ImageRect> selectedBounds;
};

class ImageView {
public:
    // Keeps a copy of `shaders` in the current context's dialect (GLSL 3.30 or ES 3.00); each program is built at its
    // first draw (a browser compiles them one by one, and a page that only shows the raster image needs one of the 32).
    explicit ImageView(const gl::ShaderLibrary& shaders);
    // Builds every program now (throws InputError on a shader error): the viewer's hot reload wants a broken
    // shader reported when it reloads, not at the next draw.
    void buildAll();
    // Draws into the bound draw framebuffer (the window's) at `rect`; sets the state it needs.
    void draw(const ImageRect& rect, const ImageViewInputs& in) const;

private:
    gl::Program& program(int mode, int srgb, int outline, int filmic) const;
    // One full-rectangle triangle through `program` with the inputs' textures and uniforms.
    void drawPass(const gl::Program& program, const ImageRect& rect, const ImageViewInputs& in) const;
    // The window pixels where the outline can show: around in.selectedBounds, inside `rect`; empty if none.
    static ImageRect outlineScissor(const ImageRect& rect, const ImageViewInputs& in);

    gl::ShaderLibrary shaders_;
    mutable gl::Program programs_[4][2][2][2];  // [mode][sRGB][selection outline][filmic], built when first used
    gl::VertexArray vao_;
    gl::Texture ramp_;
};

}  // namespace shadelab::app
