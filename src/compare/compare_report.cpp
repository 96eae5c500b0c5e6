// Heatmap, side-by-side strip, summary text and JSON report for a CompareResult. nlohmann::json stays
// inside this file; the header exposes strings only.
#include "compare/compare_report.h"

#include "util/check.h"
#include "util/input_error.h"

#include "compare/report_verdict.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace shadelab {

namespace {

using compare_detail::Json;

// Inferno-like control points (sRGB bytes) with rising Rec. 709 luminance (0, 20, 51, 91, 176, 255),
// so linear interpolation between them keeps the ramp monotone in brightness.
constexpr int kStops = 6;
constexpr uint8_t kStopRgb[kStops][3] = {{0, 0, 0},      {20, 10, 120},  {120, 20, 160},
                                         {220, 50, 120}, {250, 170, 20}, {255, 255, 255}};

std::array<uint8_t, 256 * 3> makeRamp() {
    std::array<uint8_t, 256 * 3> t{};
    for (int v = 0; v < 256; ++v) {
        const float f = float(v) / 255.0f * float(kStops - 1);
        const int s = std::min(int(f), kStops - 2);
        const float w = f - float(s);
        for (int c = 0; c < 3; ++c) {
            const float x = float(kStopRgb[s][c]) * (1.0f - w) + float(kStopRgb[s + 1][c]) * w;
            t[size_t(v) * 3 + size_t(c)] = uint8_t(std::lround(x));
        }
    }
    return t;
}

constexpr uint8_t kBandFloor = 48;  // sRGB byte: band pixels are at least this grey
constexpr uint8_t kGapGrey = 24;    // sRGB byte: gaps and padding in side-by-side strips

void checkSameSize(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height) {
        throw InputError("", "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                 " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
    }
    SHADELAB_CHECK(a.channels >= 3 && b.channels >= 3);
}

Json regionJson(const RegionStats& s) {
    return {{"pixels", s.pixels},
            {"mean", s.mean},
            {"rms", s.rms},
            {"max", s.max},
            {"max_x", s.max > 0 ? Json(s.maxX) : Json()},  // null: no pixel differs
            {"max_y", s.max > 0 ? Json(s.maxY) : Json()},
            {"max_channel", s.max > 0 ? Json(channelName(s.maxChannel)) : Json()},
            {"over_threshold", s.overThreshold},
            {"fraction_over_threshold", s.fractionOver()},
            {"over_hard_max", s.overHardMax}};
}

std::string regionLine(const char* name, const RegionStats& s, int threshold) {
    char buf[256];
    const int n = std::snprintf(buf, sizeof buf, "  %-9s %9lld px  mean %.3f  rms %.3f  max %3d", name,
                                (long long)s.pixels, s.mean, s.rms, s.max);
    std::string line(buf, size_t(std::max(n, 0)));
    if (s.max > 0)
        line += " at (" + std::to_string(s.maxX) + ", " + std::to_string(s.maxY) + ") " + channelName(s.maxChannel);
    std::snprintf(buf, sizeof buf, "  over %d/255: %.3f%% (%lld px)\n", threshold, 100.0 * s.fractionOver(),
                  (long long)s.overThreshold);
    return line + buf;
}

}  // namespace

const uint8_t* heatRamp(int value) {
    static const std::array<uint8_t, 256 * 3> kRamp = makeRamp();
    return &kRamp[size_t(std::clamp(value, 0, 255)) * 3];
}

Image8 diffHeatmap(const Image8& a, const Image8& b, const std::vector<uint8_t>& bandMask, int gain) {
    checkSameSize(a, b);
    const size_t n = size_t(a.width) * size_t(a.height);
    SHADELAB_CHECK(bandMask.empty() || bandMask.size() == n);
    Image8 out;
    out.width = a.width;
    out.height = a.height;
    out.channels = 3;
    out.data.resize(n * 3);
    const size_t ca = size_t(a.channels), cb = size_t(b.channels);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* pa = &a.data[i * ca];
        const uint8_t* pb = &b.data[i * cb];
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(pa[c]) - int(pb[c])));
        const uint8_t* rgb = heatRamp(d * gain);
        const bool inBand = !bandMask.empty() && bandMask[i];
        for (int c = 0; c < 3; ++c) out.data[i * 3 + size_t(c)] = inBand ? std::max(rgb[c], kBandFloor) : rgb[c];
    }
    return out;
}

Image8 diffHeatmap(const Image8& a, const Image8& b, int gain) { return diffHeatmap(a, b, {}, gain); }

Image8 sideBySide(const std::vector<const Image8*>& images, int gap) {
    Image8 out;
    out.channels = 3;
    for (const Image8* img : images) {
        SHADELAB_CHECK(img != nullptr && img->channels >= 3);
        out.width += img->width;
        out.height = std::max(out.height, img->height);
    }
    if (images.empty()) return out;
    out.width += gap * int(images.size() - 1);
    out.data.assign(size_t(out.width) * size_t(out.height) * 3, kGapGrey);
    int x0 = 0;
    for (const Image8* img : images) {
        for (int y = 0; y < img->height; ++y) {
            uint8_t* dst = &out.data[(size_t(y) * size_t(out.width) + size_t(x0)) * 3];
            for (int x = 0; x < img->width; ++x) std::copy_n(img->pixel(x, y), 3, dst + size_t(x) * 3);
        }
        x0 += img->width + gap;
    }
    return out;
}

std::string compareSummary(const CompareResult& r) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "compare %dx%d %s, differences in 8-bit units (/255)\n", r.width, r.height,
                  r.channels == 4 ? "RGBA" : "RGB");
    std::string s = buf;
    s += regionLine("interior", r.interior, r.gates.threshold);
    if (r.hasCoverage) s += regionLine("band", r.band, r.gates.threshold);
    s += regionLine("all", r.all, r.gates.threshold);
    if (r.hasCoverage) {
        std::snprintf(buf, sizeof buf, "  coverage mismatches %lld (%.3f%% of band; %lld outside the band)\n",
                      (long long)r.coverageMismatches, 100.0 * r.mismatchFractionOfBand(),
                      (long long)r.mismatchesOutsideBand);
        s += buf;
    } else {
        s += "  no coverage: every pixel is interior\n";
    }
    return s + compare_detail::verdictLines(r.pass, r.reasons);
}

std::string compareReportJson(const CompareResult& r, const std::string& imageA, const std::string& imageB) {
    Json j = compare_detail::verdictJson(r.pass, r.reasons, imageA, imageB, r.width, r.height);
    j["channels"] = r.channels;
    j["units"] = "8-bit levels (0-255)";
    j["gates"] = {{"threshold", r.gates.threshold},
                  {"max_fraction_over", r.gates.maxFractionOver},
                  {"hard_max", r.gates.hardMax},
                  {"max_silhouette_fraction", r.gates.maxSilhouetteFraction},
                  {"max_mean", r.gates.maxMean ? Json(*r.gates.maxMean) : Json()}};
    j["regions"] = {{"interior", regionJson(r.interior)}, {"band", regionJson(r.band)}, {"all", regionJson(r.all)}};
    j["coverage"] = {{"present", r.hasCoverage},
                     {"band_pixels", r.band.pixels},
                     {"mismatches", r.coverageMismatches},
                     {"mismatches_outside_band", r.mismatchesOutsideBand},
                     {"mismatch_fraction_of_band", r.mismatchFractionOfBand()}};
    return j.dump(2) + "\n";
}

}  // namespace shadelab
