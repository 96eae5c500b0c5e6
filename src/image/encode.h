// The one conversion from float images to 8-bit pixels (design.md §2): the display's exposure and view
// transform (view_transform.h; Standard by default), clamp to [0,1], then the exact sRGB curve (default) or no
// curve ("linear", lecture-style images). Every renderer and front end goes through it.
#pragma once

#include "image/encoding.h"
#include "image/image.h"
#include "image/view_transform.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace shadelab {

// Exact IEC 61966-2-1 sRGB transfer function on a linear value in [0, 1].
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

// One linear channel as the display shows it, before the clamp and the encoding: times 2^exposure, then the
// view transform (shaders/view_transform.glsl, the text the viewer's shader runs). Standard at 0 stops
// returns `linear` unchanged.
float displayValue(float linear, const DisplaySettings& display);

// One channel: clamp, encode, round to nearest 8-bit value. NaN maps to 0. The raw linear value, as the probe
// reports it; the three-argument form first applies the display (displayValue).
uint8_t encodeChannel(float linear, Encoding e);
uint8_t encodeChannel(float linear, Encoding e, const DisplaySettings& display);

// One channel as the 8-bit conversion has it just before rounding, in [0, 1]: the display (displayValue), the
// clamp (NaN → 0), then the encoding's curve. encodeChannel(linear, e, display) rounds this value times 255.
float displayEncoded(float linear, Encoding e, const DisplaySettings& display);

// RGB8 image (alpha dropped) from a float image, each channel exactly encodeChannel(v, e, display): every
// caller passes the display it shows (DisplaySettings{} for Standard, today's bytes). A pixel whose RGB holds a NaN or
// an infinity has no value to show: NaN is written as 0 and +inf as 255 (under either transform), and the number of
// such pixels is added to *nonFinite, which every front end passes and reports (nonFiniteMessage), so that no image
// goes black without a word.
Image8 toImage8(const ImageF& img, Encoding e, const DisplaySettings& display, uint64_t* nonFinite);

// The same conversion for a block of rows, into place (one calling thread): `rows` rows of `width` RGBA floats,
// `srcStride` floats apart, become RGB8 rows `dstStride` bytes apart, byte for byte what toImage8 writes for
// them. For renderers that convert each tile as it finishes rather than keep a float image.
void encodeRgbaRows(const float* src, size_t srcStride, uint8_t* dst, size_t dstStride, int width, int rows, Encoding e,
                    const DisplaySettings& display, uint64_t* nonFinite);

// "N of M pixels (P %) have no finite value (NaN or infinity) and are written black or white": the one
// wording of that report, for the command line's warning, the viewer's status line and Python's warning.
std::string nonFiniteMessage(uint64_t nonFinite, uint64_t pixels);

}  // namespace shadelab
