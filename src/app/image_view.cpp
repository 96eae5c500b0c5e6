// ImageView: one full-rectangle triangle through shaders/view_image.frag.
#include "app/image_view.h"

#include "compare/compare_report.h"
#include "gl/shader_dialect.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace shadelab::app {

ImageView::ImageView(const gl::ShaderLibrary& shaders) : shaders_(shaders.withDialect(gl::currentContextDialect())) {
    vao_ = gl::VertexArray::create();
    // The heat ramp of the CLI's heatmaps, so the live difference view reads the same way.
    std::vector<uint8_t> ramp(256 * 3);
    for (int v = 0; v < 256; ++v)
        for (int c = 0; c < 3; ++c) ramp[size_t(v * 3 + c)] = heatRamp(v)[c];
    ramp_ = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, ramp_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 256, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    gl::checkError("ImageView setup");
}

gl::Program& ImageView::program(int mode, int srgb, int outline, int filmic) const {
    gl::Program& p = programs_[mode][srgb][outline][filmic];
    if (!p.id())
        p = gl::Program::build(shaders_, "fullscreen.vert", "view_image.frag",
                               "#define VIEW_MODE " + std::to_string(mode) + "\n#define SRGB " + std::to_string(srgb) +
                                   "\n#define OUTLINE " + std::to_string(outline) + "\n#define VIEW_TRANSFORM " +
                                   std::to_string(filmic) + "\n");
    return p;
}

void ImageView::buildAll() {
    for (int mode = 0; mode < 4; ++mode)
        for (int srgb = 0; srgb < 2; ++srgb)
            for (int outline = 0; outline < 2; ++outline)
                for (int filmic = 0; filmic < 2; ++filmic) program(mode, srgb, outline, filmic);
}

void ImageView::draw(const ImageRect& rect, const ImageViewInputs& in) const {
    if (rect.width <= 0 || rect.height <= 0 || !in.raster) return;
    glViewport(rect.x, rect.y, rect.width, rect.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    // Without a reference yet, traced modes fall back to the raster image.
    const bool haveTrace = in.traced != 0 && in.tiles != 0;
    const int mode = !haveTrace                        ? 0
                     : in.mode == ViewMode::Traced     ? 1
                     : in.mode == ViewMode::Split      ? 2
                     : in.mode == ViewMode::Difference ? 3
                                                       : 0;
    const int srgb = in.encoding == Encoding::Srgb ? 1 : 0;
    const int filmic = in.display.transform == ViewTransform::Filmic ? 1 : 0;
    glBindVertexArray(vao_.id());
    if (in.selected == 0 || in.coverage == 0) {
        drawPass(program(mode, srgb, 0, filmic), rect, in);
    } else if (!in.selectedBounds) {
        drawPass(program(mode, srgb, 1, filmic), rect, in);
    } else {
        // The outline costs five coverage look-ups a pixel, as much as the rest of the pass: the image without it,
        // then again with it where the selected object's pixels, two image pixels away at most, can be.
        drawPass(program(mode, srgb, 0, filmic), rect, in);
        const ImageRect box = outlineScissor(rect, in);
        if (box.width > 0 && box.height > 0) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(box.x, box.y, box.width, box.height);
            drawPass(program(mode, srgb, 1, filmic), rect, in);
            glDisable(GL_SCISSOR_TEST);
        }
    }
    glBindVertexArray(0);
    for (int i = 4; i >= 0; --i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glUseProgram(0);
}

void ImageView::drawPass(const gl::Program& program, const ImageRect& rect, const ImageViewInputs& in) const {
    glUseProgram(program.id());
    const GLuint textures[5] = {in.raster, in.traced ? in.traced : in.raster, in.tiles, ramp_.id(), in.coverage};
    const char* samplers[5] = {"t_raster", "t_traced", "t_tiles", "t_ramp", "t_coverage"};
    for (int i = 0; i < 5; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glUniform1i(program.uniform(samplers[i]), i);
    }
    glUniform2f(program.uniform("u_origin"), float(rect.x), float(rect.y));
    glUniform2f(program.uniform("u_scale"), float(in.imageWidth) / float(rect.width),
                float(in.imageHeight) / float(rect.height));
    glUniform1f(program.uniform("u_split"), in.split * float(rect.width));
    glUniform1f(program.uniform("u_gain"), in.gain);
    glUniform1f(program.uniform("u_exposure"), in.display.scale());
    glUniform1f(program.uniform("u_tileSize"), float(in.tileSize));
    glUniform1ui(program.uniform("u_selected"), in.selected);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

ImageRect ImageView::outlineScissor(const ImageRect& rect, const ImageViewInputs& in) {
    // view_image.frag's texel of window pixel p is floor((p + 0.5 - origin) * scale): the window pixels whose texels
    // lie within two of the bounds, with a pixel to spare for the rounding, clipped to the image's rectangle.
    const ImageRect& b = *in.selectedBounds;
    if (b.width <= 0 || b.height <= 0) return ImageRect{};
    const double sx = double(rect.width) / double(in.imageWidth), sy = double(rect.height) / double(in.imageHeight);
    const int x0 = std::max(rect.x, rect.x + int(std::floor((b.x - 2) * sx)) - 1);
    const int y0 = std::max(rect.y, rect.y + int(std::floor((b.y - 2) * sy)) - 1);
    const int x1 = std::min(rect.x + rect.width, rect.x + int(std::ceil((b.x + b.width + 2) * sx)) + 1);
    const int y1 = std::min(rect.y + rect.height, rect.y + int(std::ceil((b.y + b.height + 2) * sy)) + 1);
    return x1 > x0 && y1 > y0 ? ImageRect{x0, y0, x1 - x0, y1 - y0} : ImageRect{};
}

}  // namespace shadelab::app
