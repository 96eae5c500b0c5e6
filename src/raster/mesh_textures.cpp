#include "raster/mesh_textures.h"

#include "gl/gl_api.h"
#include "shading/texel_decode.h"
#include "util/split_rows.h"

#include <cstdint>
#include <vector>

namespace shadelab::raster {

GLuint MeshTextures::texture(const std::shared_ptr<const Texture>& texture) {
    if (auto it = uploaded_.find(texture.get()); it != uploaded_.end()) return it->second.gl.id();
    Entry e{texture, gl::Texture::create()};
    glBindTexture(GL_TEXTURE_2D, e.gl.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Each code as its half-float linear value (shading/texel_decode.h): texelFetch gives back exactly the
    // floats the tracer decodes. One table lookup per channel; a quarter of RGBA32F's bytes plus the codes.
    const shading::TexelDecodeTable& rgb = texture->srgb ? shading::srgbDecodeTable() : shading::unormDecodeTable();
    const shading::TexelDecodeTable& alpha = shading::unormDecodeTable();
    std::vector<uint16_t>& halves = halves_;
    for (size_t level = 0; level < texture->levels.size(); ++level) {
        const TextureLevel& l = texture->levels[level];
        halves.resize(l.texels.size());
        splitRows(l.height, l.width, 1 << 16, [&](int begin, int end) {
            const size_t row = size_t(l.width) * kTexelBytes;
            for (size_t i = size_t(begin) * row; i < size_t(end) * row; i += 4) {
                halves[i] = rgb.half[l.texels[i]];
                halves[i + 1] = rgb.half[l.texels[i + 1]];
                halves[i + 2] = rgb.half[l.texels[i + 2]];
                halves[i + 3] = alpha.half[l.texels[i + 3]];
            }
        });
        glTexImage2D(GL_TEXTURE_2D, GLint(level), GL_RGBA16F, l.width, l.height, 0, GL_RGBA, GL_HALF_FLOAT,
                     halves.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(texture->levels.size()) - 1);
    // texelFetch ignores filtering; nearest keeps the texture complete whatever the driver checks.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    const GLuint id = e.gl.id();
    uploaded_.emplace(texture.get(), std::move(e));
    gl::checkError("MeshTextures::texture");
    return id;
}

void MeshTextures::prune(const std::set<const Texture*>& keep) {
    for (auto it = uploaded_.begin(); it != uploaded_.end();)
        it = keep.count(it->first) ? std::next(it) : uploaded_.erase(it);
}

}  // namespace shadelab::raster
