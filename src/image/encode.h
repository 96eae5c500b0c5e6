// The one conversion from float images to 8-bit pixels (design.md §2): clamp to [0,1], then the exact
// sRGB curve (default) or no curve ("linear", lecture-style images). Both renderers go through it.
#pragma once

#include "image/encoding.h"
#include "image/image.h"

#include <cstdint>
#include <string>

namespace shadelab {

// Exact IEC 61966-2-1 sRGB transfer function on a linear value in [0, 1].
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

// One channel: clamp, encode, round to nearest 8-bit value. NaN maps to 0.
uint8_t encodeChannel(float linear, Encoding e);

// RGB8 image (alpha dropped) from a float image. A pixel whose RGB holds a NaN or an infinity has no value
// to show: NaN is written as 0 and +inf as 255, and the number of such pixels is added to *nonFinite, which
// every front end passes and reports (nonFiniteMessage), so that no image goes black without a word.
Image8 toImage8(const ImageF& img, Encoding e, uint64_t* nonFinite);

// "N of M pixels (P %) have no finite value (NaN or infinity) and are written black or white": the one
// wording of that report, for the command line's warning, the viewer's status line and Python's warning.
std::string nonFiniteMessage(uint64_t nonFinite, uint64_t pixels);

}  // namespace shadelab
