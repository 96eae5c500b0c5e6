// A horizontal band of the image: what one draw of a large headless render covers.
#pragma once

namespace shadelab::raster {

// Rows [top, top + rows) counted from the top; rows = 0 is the whole image. Headless renders draw large images
// band by band to bound the float target's memory (bench figures in docs/cli.md); every band samples exactly
// the full image's pixel centres.
struct Band {
    int top = 0;
    int rows = 0;
};

}  // namespace shadelab::raster
