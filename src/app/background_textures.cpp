// The background renderers' image and tile textures.
#include "app/background_textures.h"

#include "util/check.h"

#include <algorithm>
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

void TileMask::reset(int width, int height, int tileSize) {
    tilesX_ = (width + tileSize - 1) / tileSize;
    tilesY_ = (height + tileSize - 1) / tileSize;
    state_.assign(size_t(tilesX_) * size_t(tilesY_), 0);
    done_ = 0;
    dirty_ = true;
    if (!texture_) texture_ = makeTileTexture();
}

bool TileMask::mark(int tx, int ty) {
    SHADELAB_DCHECK(tx >= 0 && tx < tilesX_ && ty >= 0 && ty < tilesY_);
    uint8_t& state = state_[size_t(ty) * size_t(tilesX_) + size_t(tx)];
    const bool fresh = state == 0;
    if (fresh) ++done_;
    state = 255;
    dirty_ = true;
    return fresh;
}

void TileMask::assign(const std::vector<uint8_t>& mask) {
    if (mask.size() != state_.size()) return;
    state_ = mask;
    done_ = int(std::count(state_.begin(), state_.end(), uint8_t(255)));
    dirty_ = true;
}

void TileMask::upload() {
    if (!dirty_ || !texture_) return;
    uploadTileMask(texture_, tilesX_, tilesY_, state_.data());
    dirty_ = false;
}

}  // namespace shadelab::app
