// The textures a background renderer's image is shown through (ReferenceRenderer, GlobalRenderer): the image
// as RGBA32F in GL row order, like the raster target, and one R8 texel per tile saying which tiles it has
// rendered (the display shows the raster image in the others). UI thread, GL context current.
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

}  // namespace shadelab::app
