// Comparing two 8-bit images under the gates of design.md §4: silhouette-band masks from coverage ids,
// per-region metrics and a pass/fail verdict with reasons. Heatmaps, summaries and JSON live in
// compare_report.h; reading PNGs and rendering are elsewhere.
#pragma once

#include "image/image.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

// All differences are in 8-bit units (0..255): metrics run on the encoded 8-bit values, the same way
// for both renderers (design.md §2). "Over" always means strictly greater than the limit.
struct CompareGates {
    int threshold = 3;                    // 8-bit units; a pixel is "over" when any channel differs by more
    double maxFractionOver = 0.001;       // fraction of interior pixels allowed over threshold
    int hardMax = 16;                     // 8-bit units; no interior channel may differ by more
    double maxSilhouetteFraction = 0.02;  // coverage mismatches allowed, as a fraction of band pixels
    std::optional<double> maxMean;        // 8-bit units; interior mean absolute difference, unset = no gate
};

// Metrics over one set of pixels. Means run over pixels and compared channels.
struct RegionStats {
    int64_t pixels = 0;         // pixels in the region
    double mean = 0.0;          // 8-bit units, mean |a-b| over pixels and channels
    double rms = 0.0;           // 8-bit units, sqrt of mean (a-b)^2 over pixels and channels
    int max = 0;                // 8-bit units, largest channel difference
    int maxX = -1, maxY = -1;   // first pixel (row-major) reaching max; -1 (JSON null) when max is 0
    int maxChannel = -1;        // 0..3 = R G B A; -1 when max is 0
    int64_t overThreshold = 0;  // pixels with any channel > gates.threshold
    int64_t overHardMax = 0;    // pixels with any channel > gates.hardMax

    double fractionOver() const { return pixels ? double(overThreshold) / double(pixels) : 0.0; }
};

struct CompareResult {
    int width = 0, height = 0;
    int channels = 0;          // channels compared: 3 (RGB) or 4 (RGBA)
    CompareGates gates;        // the gates the verdict was taken under
    bool hasCoverage = false;  // false: every pixel is interior, no silhouette gate

    RegionStats interior;  // pixels outside the silhouette band
    RegionStats band;      // pixels inside the silhouette band
    RegionStats all;       // every pixel

    int64_t coverageMismatches = 0;     // pixels whose coverage ids differ
    int64_t mismatchesOutsideBand = 0;  // of those, outside the band (must be 0)
    std::vector<uint8_t> bandMask;      // width*height, 1 = band; empty without coverage

    bool pass = true;
    std::vector<std::string> reasons;  // one line per failed gate; empty when pass

    double mismatchFractionOfBand() const {
        return band.pixels ? double(coverageMismatches) / double(band.pixels) : 0.0;
    }
};

// Silhouette band (design.md §4): 1 for every pixel whose 3x3 neighbourhood (clamped at the borders)
// holds more than one coverage id in either buffer. Buffers are width*height ids, row 0 at the top,
// 0 = background; the same object must carry the same id in both.
std::vector<uint8_t> silhouetteBand(const std::vector<uint32_t>& coverageA, const std::vector<uint32_t>& coverageB,
                                    int width, int height);

// Compares without coverage (e.g. two PNG files): every pixel is interior and the silhouette gate is
// not applied. RGB against RGBA compares alpha too, reading a missing alpha as 255.
// Throws InputError when the sizes differ ("image sizes differ: 640x480 vs 320x240"), a channel
// count is not 3 or 4, or a gate is out of range (threshold/hardMax outside [0, 255], fractions outside [0, 1]).
CompareResult compareImages(const Image8& a, const Image8& b, const CompareGates& gates = {});

// Compares with coverage from both renderers: band pixels are excluded from the interior gates, and
// coverage may differ only inside the band. Coverage buffers must hold width*height ids (CHECKed).
CompareResult compareImages(const Image8& a, const Image8& b, const std::vector<uint32_t>& coverageA,
                            const std::vector<uint32_t>& coverageB, const CompareGates& gates = {});

// "R", "G", "B", "A", or "-" for anything else.
const char* channelName(int channel);

}  // namespace shadelab
