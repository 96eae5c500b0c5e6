// What a comparison leaves behind (design.md §4 "Report"): the |a-b| heatmap, side-by-side strips, a
// short human summary and the JSON report. No metrics here; the files a failing test writes are compare_evidence.h.
#pragma once

#include "compare/image_compare.h"
#include "image/image.h"

#include <string>
#include <vector>

namespace shadelab {

// RGB heatmap of the per-pixel max R/G/B difference (alpha ignored), times gain, clamped to 255 and mapped through
// a ramp black -> blue -> magenta -> amber -> white whose luminance rises monotonically: no
// difference is black, and at gain 16 the hard limit (16/255) is white. Sizes must match (InputError).
Image8 diffHeatmap(const Image8& a, const Image8& b, int gain = 16);

// The same, with silhouette-band pixels (bandMask from CompareResult, 1 = band; empty = none) lifted to
// at least dark grey, so the band reads as an outline where the images agree.
Image8 diffHeatmap(const Image8& a, const Image8& b, const std::vector<uint8_t>& bandMask, int gain = 16);

// The ramp itself: 0 -> black, 255 -> white. Exposed for tests and legends.
const uint8_t* heatRamp(int value);

// RGB strip of the images left to right, separated by gap pixels of dark grey; shorter images are
// padded below with the same grey. Alpha is dropped. For `--renderer both`: raster | traced | heatmap.
Image8 sideBySide(const std::vector<const Image8*>& images, int gap = 4);

// A few lines: size and coverage, then mean, RMS, max (position, channel) and fraction over the
// threshold per region, coverage mismatches, and the verdict with its reasons.
std::string compareSummary(const CompareResult& r);

// Machine-readable report: gates, per-region metrics, coverage counts, verdict and reasons, with
// snake_case keys and numbers as numbers. imageA/imageB, when given, are recorded as "image_a"/"image_b".
std::string compareReportJson(const CompareResult& r, const std::string& imageA = {}, const std::string& imageB = {});

}  // namespace shadelab
