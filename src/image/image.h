// ImageF: a linear float RGBA image, the common output of both renderers (design.md §2).
// Row 0 is the top of the image. Image8: 8-bit pixels as they go into and come out of PNG files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadelab {

// The largest image side, in pixels, that shadelab renders, reads or writes: every front end's size limit.
inline constexpr int kMaxImageSide = 16384;

struct ImageF {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // width*height*4 floats, row-major, row 0 at the top

    ImageF() = default;
    ImageF(int w, int h) : width(w), height(h), rgba(size_t(w) * size_t(h) * 4, 0.0f) {}
    float* pixel(int x, int y) { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    const float* pixel(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

struct Image8 {
    int width = 0;
    int height = 0;
    int channels = 0;           // 3 (RGB) or 4 (RGBA)
    std::vector<uint8_t> data;  // width*height*channels bytes, row 0 at the top

    const uint8_t* pixel(int x, int y) const {
        return &data[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels)];
    }
};

}  // namespace shadelab
