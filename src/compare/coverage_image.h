// Coverage ids (design.md §4) as an ordinary 8-bit RGB image, so that a renderer's coverage can travel in a PNG
// file beside its picture (`shadelab render --coverage`, the web page) and come back for `shadelab compare`.
// Pixel = id in 24 bits: R the low byte, G the middle, B the high; alpha, when present, must be 255. The ids of
// a scene are small, so the picture is nearly black: it is meant for tools, not for eyes.
#pragma once

#include "image/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab {

// The largest id a coverage image holds.
inline constexpr uint32_t kMaxCoverageImageId = (1u << 24) - 1;

// width x height ids, row 0 at the top, as RGB. Throws std::invalid_argument when the sizes disagree or an id is
// over kMaxCoverageImageId (a scene of more than 16 million objects).
Image8 coverageToImage(const std::vector<uint32_t>& ids, int width, int height);

// The ids back. Throws InputError naming `path` when a pixel is not one (alpha not 255).
std::vector<uint32_t> coverageFromImage(const Image8& image, const std::string& path);

}  // namespace shadelab
