// The background renderers' image and tile textures.
#include "app/background_textures.h"

#include <cstring>

namespace shadelab::app {
namespace {

gl::Texture nearestTexture() {
    gl::Texture t = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

}  // namespace

gl::Texture makeImageTexture(int width, int height, const float* rgba) {
    gl::Texture t = nearestTexture();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, rgba);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

gl::Texture makeTileTexture() {
    gl::Texture t = nearestTexture();
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

void uploadTileMask(const gl::Texture& texture, int tilesX, int tilesY, const uint8_t* mask) {
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, tilesX, tilesY, 0, GL_RED, GL_UNSIGNED_BYTE, mask);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void uploadRowsFlipped(const gl::Texture& texture, int x, int y, int w, int h, int imageHeight, const float* rgba,
                       std::vector<float>& scratch) {
    const size_t rowFloats = size_t(w) * 4;
    scratch.resize(rowFloats * size_t(h));
    for (int row = 0; row < h; ++row)
        std::memcpy(&scratch[size_t(h - 1 - row) * rowFloats], rgba + size_t(row) * rowFloats,
                    rowFloats * sizeof(float));
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, x, imageHeight - y - h, w, h, GL_RGBA, GL_FLOAT, scratch.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace shadelab::app
