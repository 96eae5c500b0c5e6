// Comparing two linear float images (OpenEXR files, design.md §4 "Linear light") in linear light. 8-bit gates
// (image_compare.h) measure what a display shows; radiance has no fixed scale and runs far above 1, so these
// gates are relative: a difference counts against the value it differs from, with a floor for the darks, where
// a relative measure would otherwise call the noise of near-black pixels huge.
#pragma once

#include "image/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab {

// "Over" means strictly greater. The defaults are the 8-bit gates' in relative terms: 3 sRGB levels are 2.7 % of
// the linear value at white, 3.6 % at 0.5 and 7 % at 0.1 (threshold 5 %); 16 levels are 14 % at white and 19 %
// at 0.5 (hard maximum 25 %, which also admits the darker values 16 levels allow more of).
struct LinearGates {
    double floor = 0.01;             // radiance (1 = display white) added to each denominator
    double threshold = 0.05;         // a pixel is over when its relative difference exceeds this
    double maxFractionOver = 0.001;  // at most this fraction of pixels over threshold: the 99.9th percentile of
                                     // the relative difference is within it
    double hardMax = 0.25;           // no pixel's relative difference above this
    double maxRelativeRmse = 0.01;   // RMS(a − b) / max(floor, RMS((|a| + |b|) / 2)), over pixels and R G B
};

struct LinearCompareResult {
    int width = 0, height = 0;
    LinearGates gates;
    int64_t pixels = 0;
    double rmse = 0.0;                // radiance, over finite pixel pairs and R G B
    double level = 0.0;               // RMS((|a| + |b|) / 2), the same samples
    double relativeRmse = 0.0;        // rmse / max(floor, level)
    double maxRelative = 0.0;         // the largest per-pixel relative difference (+infinity: a non-finite mismatch)
    int maxX = -1, maxY = -1;         // its first pixel (row-major); -1 when 0
    int maxChannel = -1;              // 0..2 = R G B; -1 when 0
    double percentile = 0.0;          // the per-pixel relative difference at the (1 − maxFractionOver) quantile
    int64_t overThreshold = 0;        // pixels with relative difference > threshold
    int64_t overHardMax = 0;          // pixels with relative difference > hardMax
    int64_t nonFiniteMismatches = 0;  // pixels where a channel is NaN or infinite in one image and not the same
                                      // in the other (their relative difference is +infinity)
    std::vector<float> relative;      // width·height per-pixel relative differences, row 0 at the top

    bool pass = true;
    std::vector<std::string> reasons;  // one line per failed gate

    double fractionOver() const { return pixels ? double(overThreshold) / double(pixels) : 0.0; }
};

// The relative difference of one pixel: the largest over R, G, B of |a − b| / (max(|a|, |b|) + floor). Equal
// non-finite values (the same infinity, NaN against NaN) differ by 0; any other non-finite pair by +infinity.
// `channel`, when given, is set to the channel (0..2) of the largest, -1 when all are equal.
double relativeDifference(const float* a, const float* b, double floor, int* channel = nullptr);

// Compares R, G, B (alpha is not compared). Throws InputError when the sizes differ ("image sizes differ: ...")
// or a gate is out of range (negative, NaN; fractions above 1).
LinearCompareResult compareLinear(const ImageF& a, const ImageF& b, const LinearGates& gates = {});

// RGB heatmap of the per-pixel relative difference through heatRamp (compare_report.h): black where equal, white
// at hardMax when gain is 16 (the same gain as the 8-bit heatmap, where 16/255 is white).
Image8 linearHeatmap(const LinearCompareResult& r, int gain = 16);

// A few lines: size, the metrics against their gates, the verdict with its reasons.
std::string linearSummary(const LinearCompareResult& r);

// Machine-readable report, snake_case keys, numbers as numbers (a non-finite maximum is the string "inf").
std::string linearReportJson(const LinearCompareResult& r, const std::string& imageA = {},
                             const std::string& imageB = {});

}  // namespace shadelab
