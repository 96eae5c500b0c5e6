// OffscreenOptions: what renderOffscreen (raster/offscreen.h) is asked for, as plain data with no GL, so that
// the render request's conversion (render/render_request.h) fills it without linking the rasterizer.
#pragma once

#include "image/encoding.h"
#include "image/view_transform.h"

#include <cstddef>

namespace shadelab::raster {

struct OffscreenOptions {
    int width = 1280, height = 720;  // output pixels
    int spp = 1;                     // samples per pixel: k² on the grid (i + (a+0.5)/k), scene/sample_grid.h
    Encoding encoding = Encoding::Srgb;
    DisplaySettings display;                   // exposure and view transform of the 8-bit pixels (Standard: today's)
    bool coverage = false;                     // also return coverage ids (of sample a = b = k/2, as the tracer)
    bool keepLinear = false;                   // also return the linear floats the conversion read (RGBA)
    size_t maxTargetBytes = size_t(32) << 20;  // float colour target budget per band: 1920x1080 is one band
};

}  // namespace shadelab::raster
