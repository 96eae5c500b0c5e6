// compareLinear: one pass over the pixels for the sums and the per-pixel relative differences, then the quantile
// by selection (std::nth_element) on a copy. Relative error over a floored denominator is the per-pixel form of
// the relative MSE renderers are judged by (Rousselle, Knaus & Zwicker 2011, "Adaptive sampling and
// reconstruction using greedy error minimization", which divides by the reference squared plus a small epsilon).
#include "compare/linear_compare.h"

#include "compare/compare_report.h"
#include "util/check.h"
#include "util/input_error.h"

#include "compare/report_verdict.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace shadelab {
namespace {

using compare_detail::Json;

bool sameNonFinite(float a, float b) { return (std::isnan(a) && std::isnan(b)) || (std::isinf(a) && a == b); }

void checkGates(const LinearGates& g) {
    const auto bad = [](double v) { return !(v >= 0.0) || !std::isfinite(v); };
    if (bad(g.floor) || bad(g.threshold) || bad(g.hardMax) || bad(g.maxRelativeRmse) || bad(g.maxFractionOver) ||
        g.maxFractionOver > 1.0)
        throw InputError("", "linear gates out of range (each a finite number from 0, fractions at most 1)");
}

std::string percent(double v) {
    char buf[64];
    if (std::isinf(v)) return "inf";
    std::snprintf(buf, sizeof buf, "%.3g %%", 100.0 * v);
    return buf;
}

Json number(double v) { return std::isfinite(v) ? Json(v) : Json(v > 0 ? "inf" : "nan"); }

}  // namespace

double relativeDifference(const float* a, const float* b, double floor, int* channel) {
    double worst = 0.0;
    if (channel) *channel = -1;
    for (int c = 0; c < 3; ++c) {
        const float x = a[c], y = b[c];
        double d = 0.0;
        if (!std::isfinite(x) || !std::isfinite(y))
            d = sameNonFinite(x, y) ? 0.0 : std::numeric_limits<double>::infinity();
        else
            d = std::fabs(double(x) - double(y)) / (std::max(std::fabs(double(x)), std::fabs(double(y))) + floor);
        if (d > worst) {
            worst = d;
            if (channel) *channel = c;
        }
    }
    return worst;
}

LinearCompareResult compareLinear(const ImageF& a, const ImageF& b, const LinearGates& gates) {
    if (a.width != b.width || a.height != b.height)
        throw InputError("", "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                 " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
    checkGates(gates);
    SHADELAB_CHECK_EQ(a.rgba.size(), size_t(a.width) * size_t(a.height) * 4);
    SHADELAB_CHECK_EQ(b.rgba.size(), a.rgba.size());
    LinearCompareResult r;
    r.width = a.width;
    r.height = a.height;
    r.gates = gates;
    r.pixels = int64_t(a.width) * int64_t(a.height);
    r.relative.resize(size_t(r.pixels));
    double sumSq = 0.0, sumLevel = 0.0;
    int64_t samples = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const float *pa = a.pixel(x, y), *pb = b.pixel(x, y);
            int channel = -1;
            const double rel = relativeDifference(pa, pb, gates.floor, &channel);
            r.relative[size_t(y) * size_t(a.width) + size_t(x)] = float(rel);
            if (std::isinf(rel)) ++r.nonFiniteMismatches;
            if (rel > r.maxRelative) {
                r.maxRelative = rel;
                r.maxX = x;
                r.maxY = y;
                r.maxChannel = channel;
            }
            r.overThreshold += rel > gates.threshold;
            r.overHardMax += rel > gates.hardMax;
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(pa[c]) || !std::isfinite(pb[c])) continue;
                const double d = double(pa[c]) - double(pb[c]),
                             m = 0.5 * (std::fabs(double(pa[c])) + std::fabs(double(pb[c])));
                sumSq += d * d;
                sumLevel += m * m;
                ++samples;
            }
        }
    if (samples > 0) {
        r.rmse = std::sqrt(sumSq / double(samples));
        r.level = std::sqrt(sumLevel / double(samples));
    }
    r.relativeRmse = r.rmse / std::max(gates.floor, r.level);
    if (!(gates.floor > 0.0) && r.level == 0.0)
        r.relativeRmse = r.rmse == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    {
        std::vector<float> sorted = r.relative;
        const double q = 1.0 - gates.maxFractionOver;
        size_t k = size_t(std::ceil(q * double(sorted.size())));
        k = std::min(sorted.size() - 1, k == 0 ? 0 : k - 1);
        std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(k), sorted.end());
        r.percentile = sorted[k];
    }
    char buf[256];
    if (r.fractionOver() > gates.maxFractionOver) {
        std::snprintf(buf, sizeof buf, "%.4f%% of pixels differ by more than %s (relative), allowed %.4f%%",
                      100.0 * r.fractionOver(), percent(gates.threshold).c_str(), 100.0 * gates.maxFractionOver);
        r.reasons.push_back(buf);
    }
    if (r.overHardMax > 0) {
        std::snprintf(buf, sizeof buf,
                      "%lld pixel(s) differ by more than the hard maximum %s; the largest %s at (%d, %d) %c",
                      (long long)r.overHardMax, percent(gates.hardMax).c_str(), percent(r.maxRelative).c_str(), r.maxX,
                      r.maxY, "RGB"[std::max(0, r.maxChannel)]);
        r.reasons.push_back(buf);
    }
    if (r.nonFiniteMismatches > 0) {
        std::snprintf(buf, sizeof buf, "%lld pixel(s) are NaN or infinite in one image and not in the other",
                      (long long)r.nonFiniteMismatches);
        r.reasons.push_back(buf);
    }
    if (!(r.relativeRmse <= gates.maxRelativeRmse)) {
        std::snprintf(buf, sizeof buf, "relative RMSE %s over the gate %s", percent(r.relativeRmse).c_str(),
                      percent(gates.maxRelativeRmse).c_str());
        r.reasons.push_back(buf);
    }
    r.pass = r.reasons.empty();
    return r;
}

Image8 linearHeatmap(const LinearCompareResult& r, int gain) {
    Image8 out;
    out.width = r.width;
    out.height = r.height;
    out.channels = 3;
    out.data.resize(size_t(r.width) * size_t(r.height) * 3);
    const double scale = r.gates.hardMax > 0.0 ? 255.0 * double(gain) / 16.0 / r.gates.hardMax : 255.0 * 1e9;
    for (size_t i = 0; i < r.relative.size(); ++i) {
        const double v = std::min(255.0, double(r.relative[i]) * scale);  // +inf is white
        const uint8_t* rgb = heatRamp(int(std::lround(v)));
        std::copy(rgb, rgb + 3, &out.data[i * 3]);
    }
    return out;
}

std::string linearSummary(const LinearCompareResult& r) {
    char buf[512];
    std::string s;
    std::snprintf(buf, sizeof buf,
                  "compare %dx%d linear RGB (OpenEXR), relative differences |a-b| / (max(|a|,|b|) + %g)\n", r.width,
                  r.height, r.gates.floor);
    s += buf;
    std::snprintf(buf, sizeof buf, "  relative RMSE %s (gate %s; RMSE %.4g, RMS level %.4g)\n",
                  percent(r.relativeRmse).c_str(), percent(r.gates.maxRelativeRmse).c_str(), r.rmse, r.level);
    s += buf;
    std::snprintf(buf, sizeof buf, "  %.1fth percentile %s; over %s: %lld pixels (%.4f%%, allowed %.4f%%)\n",
                  100.0 * (1.0 - r.gates.maxFractionOver), percent(r.percentile).c_str(),
                  percent(r.gates.threshold).c_str(), (long long)r.overThreshold, 100.0 * r.fractionOver(),
                  100.0 * r.gates.maxFractionOver);
    s += buf;
    if (r.maxX >= 0)
        std::snprintf(buf, sizeof buf, "  max %s at (%d, %d) %c (hard maximum %s)\n", percent(r.maxRelative).c_str(),
                      r.maxX, r.maxY, "RGB"[std::max(0, r.maxChannel)], percent(r.gates.hardMax).c_str());
    else
        std::snprintf(buf, sizeof buf, "  max 0 (identical samples)\n");
    s += buf;
    return s + compare_detail::verdictLines(r.pass, r.reasons);
}

std::string linearReportJson(const LinearCompareResult& r, const std::string& imageA, const std::string& imageB) {
    Json j = compare_detail::verdictJson(r.pass, r.reasons, imageA, imageB, r.width, r.height);
    j["units"] = "linear light; relative differences |a-b| / (max(|a|,|b|) + floor)";
    j["gates"] = {{"floor", r.gates.floor},
                  {"threshold", r.gates.threshold},
                  {"max_fraction_over", r.gates.maxFractionOver},
                  {"hard_max", r.gates.hardMax},
                  {"max_relative_rmse", r.gates.maxRelativeRmse}};
    j["pixels"] = r.pixels;
    j["rmse"] = number(r.rmse);
    j["rms_level"] = number(r.level);
    j["relative_rmse"] = number(r.relativeRmse);
    j["percentile"] = {{"quantile", 1.0 - r.gates.maxFractionOver}, {"relative", number(r.percentile)}};
    j["max"] = {{"relative", number(r.maxRelative)},
                {"x", r.maxX >= 0 ? Json(r.maxX) : Json()},
                {"y", r.maxY >= 0 ? Json(r.maxY) : Json()},
                {"channel", r.maxChannel >= 0 ? Json(std::string(1, "RGB"[r.maxChannel])) : Json()}};
    j["over_threshold"] = r.overThreshold;
    j["over_hard_max"] = r.overHardMax;
    j["non_finite_mismatches"] = r.nonFiniteMismatches;
    return j.dump(2) + "\n";
}

}  // namespace shadelab
