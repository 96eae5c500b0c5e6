#include "raster/mesh_textures.h"

#include "gl/gl_api.h"

namespace shadelab::raster {

GLuint MeshTextures::texture(const std::shared_ptr<const Texture>& texture) {
    if (auto it = uploaded_.find(texture.get()); it != uploaded_.end()) return it->second.gl.id();
    Entry e{texture, gl::Texture::create()};
    glBindTexture(GL_TEXTURE_2D, e.gl.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // The codes as they are: GL decodes sRGB (GL_SRGB8_ALPHA8, RGB only) and UNORM8 at texelFetch, before
    // texture_sample.glsl filters, as the tracer decodes through shading/texel_decode.h's tables. llvmpipe's
    // decoding is within kGlTexelDecodeError of those tables (tests/texel_decode_test.cpp).
    const GLint format = texture->srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    for (size_t level = 0; level < texture->levels.size(); ++level) {
        const TextureLevel& l = texture->levels[level];
        glTexImage2D(GL_TEXTURE_2D, GLint(level), format, l.width, l.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     l.texels.data());
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
