// renderOffscreen: a whole image from the rasterizer, as `shadelab render` and screenshots need it. Draws in
// bands (bounded RGBA32F target), supersamples on the fixed k×k grid the tracer also uses (spp = k²), and
// converts once with the shared toImage8. Not for interactive frames: the viewer draws its target directly.
#pragma once

#include "image/encode.h"
#include "image/image.h"
#include "raster/offscreen_options.h"
#include "raster/raster_renderer.h"
#include "scene/scene.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

namespace shadelab::raster {

struct OffscreenResult {
    Image8 pixels;                   // RGB
    std::vector<uint32_t> coverage;  // width*height ids when asked, row 0 at the top
    ImageF linear;                   // width x height, when keepLinear: pixels == toImage8(linear, encoding, display)
    uint64_t nonFinite = 0;          // pixels with a NaN or infinite channel (toImage8)
    int bands = 0;
    double drawMs = 0.0;  // GPU time, summed over bands (glFinish after each)
    double readMs = 0.0;  // readback + downsampling + conversion
};

// Sample `index` (0 .. k²-1, row by row) of the k×k grid, as an offset from the pixel centre in pixels (x right,
// y down): the sample renderOffscreen's supersampled image holds at pixel (x·k + a, y·k + b).
glm::vec2 gridSampleOffset(int k, int index);

// Throws SettingError (util/input_error.h) for a sample count off the grid (scene/sample_grid.h), or for a
// size whose supersampled width exceeds the GL maximum texture size.
OffscreenResult renderOffscreen(RasterRenderer& renderer, const Scene& scene, const OffscreenOptions& options);

}  // namespace shadelab::raster
