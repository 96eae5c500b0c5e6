// ImageRect: where the viewer shows its image, in framebuffer pixels with GL's convention (y is the bottom edge).
#pragma once

namespace shadelab::app {

struct ImageRect {
    int x = 0, y = 0;
    int width = 0, height = 0;
};

}  // namespace shadelab::app
