// ImageView: one full-rectangle triangle through shaders/view_image.frag.
#include "app/image_view.h"

#include "compare/compare_report.h"
#include "gl/shader_dialect.h"

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
    const bool outline = in.selected != 0 && in.coverage != 0;
    const bool filmic = in.display.transform == ViewTransform::Filmic;
    const gl::Program& program =
        this->program(mode, in.encoding == Encoding::Srgb ? 1 : 0, outline ? 1 : 0, filmic ? 1 : 0);
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
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    for (int i = 4; i >= 0; --i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glUseProgram(0);
}

}  // namespace shadelab::app
