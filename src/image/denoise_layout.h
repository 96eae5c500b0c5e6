// The denoiser's working memory (image/denoise_kernel.h): one plane of floats per quantity a pass reads, all
// in one allocation, each row padded on both sides by `pad` pixels (at least the widest step) and rounded up
// to 16 pixels, so that a tap reads the N pixels beside N others with one load and no bounds check in x. A
// padding pixel looks like a pixel outside the image: its albedo guide is infinite, which no stop lets
// through (its weight is exactly 0), and its colour and variance are 0; so does a pixel whose colour is not
// finite, which lends nothing and keeps its value. Rows start 64-byte aligned, so the steps from 16 pixels on
// load whole cache lines. Not for other files.
#pragma once

#include "image/denoise_memory.h"

#include <cstddef>
#include <cstdint>

namespace shadelab::denoise_detail {

// The planes, in the order they lie in memory. The colour ping-pongs between two sets of four (c / (1 + L) per
// channel and the variance of its luminance); the guides are read by every tap (the normal, the depth and the
// albedo over σ_a) or only at the centre pixel (σ_z times the depth slope).
enum Plane : int {
    kColourA,  // r, g, b, v
    kColourB = kColourA + 4,
    kNx = kColourB + 4,
    kNy,
    kNz,
    kDepth,
    kAlbedoR,
    kAlbedoG,
    kAlbedoB,
    kSlope,
    kPlaneCount
};

class DenoiseLayout {
public:
    DenoiseLayout(int width, int height, int widestStep)
        : width_(width),
          height_(height),
          pad_(roundUp16(widestStep)),
          stride_(pad_ + roundUp16(width) + pad_),
          planeSize_(size_t(height) * size_t(stride_)),
          // Not zeroed: every float is written before it is read (denoise_kernel.h, prepareRow).
          memory_(planeSize_ * kPlaneCount + 16) {
        const size_t misalign = (reinterpret_cast<uintptr_t>(memory_.data()) / sizeof(float)) % 16;
        base_ = memory_.data() + (misalign ? 16 - misalign : 0);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    int pad() const { return pad_; }
    int stride() const { return stride_; }
    // Pixel (0, y) of a plane; pixels -pad .. stride - pad - 1 of the row are there.
    float* row(int plane, int y) { return base_ + size_t(plane) * planeSize_ + size_t(y) * size_t(stride_) + pad_; }
    const float* row(int plane, int y) const {
        return base_ + size_t(plane) * planeSize_ + size_t(y) * size_t(stride_) + pad_;
    }

private:
    static int roundUp16(int v) { return (v + 15) / 16 * 16; }

    int width_, height_, pad_, stride_;
    size_t planeSize_;
    DenoiseMemory memory_;
    float* base_ = nullptr;
};

}  // namespace shadelab::denoise_detail
