// The textures a background renderer's image is shown through (ReferenceRenderer, GlobalRenderer): the image
// as RGBA32F in GL row order, like the raster target, and one R8 texel per tile saying which tiles it has
// rendered (the display shows the raster image in the others), kept by TileMask. UI thread, GL context current.
#pragma once

#include "gl/objects.h"

#include <cstdint>
#include <vector>

namespace shadelab::app {

// A width x height RGBA32F texture, nearest filtering, holding `rgba` (GL row order) or undefined texels.
gl::Texture makeImageTexture(int width, int height, const float* rgba = nullptr);
// An R8 texture with nearest filtering, empty until uploadTileMask.
gl::Texture makeTileTexture();
// The tile mask, tilesX x tilesY bytes, row 0 at the top as the image's rows: 255 = rendered.
void uploadTileMask(const gl::Texture& texture, int tilesX, int tilesY, const uint8_t* mask);
// A w x h block of `rgba` (rows top to bottom) at (x, y) of an image `imageHeight` rows tall (row 0 at the
// top), written into `texture` in GL row order; `scratch` holds the flipped rows.
void uploadRowsFlipped(const gl::Texture& texture, int x, int y, int w, int h, int imageHeight, const float* rgba,
                       std::vector<float>& scratch);

// Which tiles of an image a background renderer has rendered, and the R8 texture that shows it.
class TileMask {
public:
    // An image of width x height in tiles of `tileSize` pixels, none rendered. Keeps the texture when it has one.
    void reset(int width, int height, int tileSize);
    // Marks tile (tx, ty) rendered; true when it was not before.
    bool mark(int tx, int ty);
    // Takes a whole mask (tilesX × tilesY bytes, row 0 at the top, 255 = rendered); one of another size is ignored.
    void assign(const std::vector<uint8_t>& mask);
    // Uploads the mask when it changed since the last upload.
    void upload();

    GLuint texture() const { return texture_.id(); }
    int done() const { return done_; }
    int total() const { return int(state_.size()); }

private:
    int tilesX_ = 0, tilesY_ = 0, done_ = 0;
    std::vector<uint8_t> state_;
    bool dirty_ = false;
    gl::Texture texture_;
};

}  // namespace shadelab::app
