// The denoiser's working memory (image/denoise_kernel.h), in one allocation (denoise_memory.h):
// - the prepared image: per row, one plane of floats per quantity a pass reads (the colour, the guides), the
//   row's planes side by side, so that what a tap needs of a row lies in one contiguous run;
// - per strip of rows that one thread filters, a ring of rows for each pass's output but the last, which the
//   next pass reads while it is still in the cache; and a row for the last pass's output.
// Each row of a plane is padded on both sides by `pad` pixels (at least the widest step) and rounded up to 16
// pixels, so that a tap reads the N pixels beside N others with one load and no bounds check in x. A padding
// pixel looks like a pixel outside the image: its albedo guide is infinite, which no stop lets through (its
// weight is exactly 0), and its colour and variance are 0; so does a pixel whose colour is not finite, which
// lends nothing and keeps its value. Rows start 64-byte aligned. Its functions always inline: every build
// (denoise_builds.h) reads it, and none may lend another a function built for its own CPU. Not for other files.
#pragma once

#include "image/denoise_memory.h"

#include <cstddef>
#include <cstdint>

namespace shadelab::denoise_detail {

// A row's planes in the prepared image, in order. The colour (linear RGB and the variance of its
// luminance) comes first, as in a ring's rows; the guides are read by every tap (the normal, the depth and the
// albedo over σ_a) or only at the centre pixel (the depth's gradient).
enum Plane : int {
    kColour,  // r, g, b, v
    kNx = kColour + 4,
    kNy,
    kNz,
    kDepth,
    kAlbedoR,
    kAlbedoG,
    kAlbedoB,
    kLuminance,  // the first pass's: the luminance's 3x3 B-spline mean, a steadier value to stop at
    kGradX,      // the depth guide's (1/z) gradient along x and y, and σ_z times its steepest
    kGradY,
    kSlope,
    kImagePlanes
};
constexpr int kColourPlanes = 4;

class DenoiseLayout {
public:
    // `iterations` passes, the widest 2^(iterations − 1) pixels; `strips` of rows filtered apart.
    DenoiseLayout(int width, int height, int iterations, int strips)
        : width_(width),
          height_(height),
          iterations_(iterations),
          pad_(roundUp16(1 << (iterations - 1))),
          stride_(pad_ + roundUp16(width) + pad_),
          stripFloats_(size_t(ringRowsBefore(iterations - 1) + 1) * kColourPlanes * size_t(stride_)),
          memory_(size_t(height) * kImagePlanes * size_t(stride_) + size_t(strips) * stripFloats_ + 16) {
        const size_t misalign = (reinterpret_cast<uintptr_t>(memory_.data()) / sizeof(float)) % 16;
        base_ = memory_.data() + (misalign ? 16 - misalign : 0);
    }

    [[gnu::always_inline]] int width() const { return width_; }
    [[gnu::always_inline]] int height() const { return height_; }
    [[gnu::always_inline]] int iterations() const { return iterations_; }
    [[gnu::always_inline]] int pad() const { return pad_; }
    [[gnu::always_inline]] int stride() const { return stride_; }  // from one plane of a row to the next, in floats

    // Pixel (0, y) of a plane of the prepared image.
    [[gnu::always_inline]] float* image(int plane, int y) const {
        return base_ + (size_t(y) * kImagePlanes + size_t(plane)) * size_t(stride_) + size_t(pad_);
    }
    // Pixel (0, y) of the red plane of pass `pass`'s output in strip `strip` (the rest follow, stride apart):
    // a ring for every pass but the last, whose rows are written one at a time into one row.
    [[gnu::always_inline]] float* output(int strip, int pass, int y) const {
        const int row = pass + 1 < iterations_ ? ringRowsBefore(pass) + y % ringRows(pass) : ringRowsBefore(pass);
        return base_ + size_t(height_) * kImagePlanes * size_t(stride_) + size_t(strip) * stripFloats_ +
               size_t(row) * kColourPlanes * size_t(stride_) + size_t(pad_);
    }
    // The rows of pass k's ring: its next pass reads 2^(k + 1) rows either side, and runs 2^(k + 1) + 1 rows
    // behind it (denoise_kernel.h, filterStrip), so a row is overwritten only once every reader is done.
    [[gnu::always_inline]] static int ringRows(int pass) { return (4 << pass) + 2; }

private:
    [[gnu::always_inline]] static int roundUp16(int v) { return (v + 15) / 16 * 16; }
    [[gnu::always_inline]] static int ringRowsBefore(int pass) {
        int rows = 0;
        for (int k = 0; k < pass; ++k) rows += ringRows(k);
        return rows;
    }

    int width_, height_, iterations_, pad_, stride_;
    size_t stripFloats_;
    DenoiseMemory memory_;
    float* base_ = nullptr;
};

}  // namespace shadelab::denoise_detail
