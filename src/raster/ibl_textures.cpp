// IblTextures: three float textures without mips or filtering (texelFetch only).
#include "raster/ibl_textures.h"

#include "gl/gl_api.h"
#include "shading/dfg_lut.h"
#include "shading/sheen_lut.h"

namespace shadelab::raster {
namespace {

void upload(gl::Texture& t, GLenum internal, GLenum format, int w, int h, const float* data) {
    if (!t) t = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, format, GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace

void IblTextures::prepare(const std::shared_ptr<const shading::PrefilteredEnvironment>& map, bool needDfg,
                          bool needSheen) {
    if (needDfg && !dfg_) {
        const shading::DfgLut& lut = shading::dfgLut();
        upload(dfg_, GL_RG32F, GL_RG, lut.size, lut.size, lut.ab.data());
    }
    if (needSheen && !sheen_) {
        const shading::SheenLut& lut = shading::sheenLut();
        upload(sheen_, GL_R32F, GL_RED, lut.size, lut.size, lut.e.data());
    }
    if (map && map != uploaded_) {
        upload(atlas_, GL_RGB32F, GL_RGB, map->atlasWidth, map->atlasHeight, map->atlas.data());
        uploaded_ = map;
        ++generation_;
    }
    gl::checkError("IblTextures::prepare");
}

void IblTextures::bind(unsigned cubeUnit, unsigned dfgUnit, unsigned sheenUnit) const {
    glActiveTexture(GL_TEXTURE0 + cubeUnit);
    glBindTexture(GL_TEXTURE_2D, atlas_ ? atlas_.id() : 0);
    glActiveTexture(GL_TEXTURE0 + dfgUnit);
    glBindTexture(GL_TEXTURE_2D, dfg_ ? dfg_.id() : 0);
    glActiveTexture(GL_TEXTURE0 + sheenUnit);
    glBindTexture(GL_TEXTURE_2D, sheen_ ? sheen_.id() : 0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace shadelab::raster
