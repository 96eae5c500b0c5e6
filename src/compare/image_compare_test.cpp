// Tests for the image comparison (design.md §4): exact metrics on hand-made differences, the strict
// "over" rule, every gate with a negative control, silhouette bands against brute force, and the report.
#include "compare/image_compare.h"

#include "compare/compare_evidence.h"
#include "compare/compare_report.h"
#include "image/png.h"
#include "util/input_error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

std::string outStem(const std::string& name) {
    fs::path dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "compare";
    fs::create_directories(dir);
    return (dir / name).string();
}

Image8 solid(int w, int h, int channels = 3, uint8_t v = 100) {
    Image8 img;
    img.width = w;
    img.height = h;
    img.channels = channels;
    img.data.assign(size_t(w) * size_t(h) * size_t(channels), v);
    return img;
}

uint8_t& at(Image8& img, int x, int y, int c) {
    return img.data[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels) + size_t(c)];
}

Image8 noise(int w, int h, uint32_t seed) {
    Image8 img = solid(w, h);
    std::mt19937 rng(seed);
    for (uint8_t& v : img.data) v = uint8_t(rng() & 0xFF);
    return img;
}

// A failing test leaves both images, the heatmap and the report behind, and says where.
void keepEvidenceOnFailure(const std::string& name, const Image8& a, const Image8& b, const CompareResult& r) {
    if (!::testing::Test::HasFailure()) return;
    for (const std::string& p : writeCompareEvidence(outStem(name), a, b, r)) {
        std::printf("evidence: %s\n", p.c_str());
    }
    std::printf("%s", compareSummary(r).c_str());
}

// Band by definition: the clamped 3x3 window holds two different ids in either buffer.
std::vector<uint8_t> bruteForceBand(const std::vector<uint32_t>& ca, const std::vector<uint32_t>& cb, int w, int h) {
    std::vector<uint8_t> band(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (const auto* cov : {&ca, &cb}) {
                const uint32_t centre = (*cov)[size_t(y) * size_t(w) + size_t(x)];
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
                        const uint32_t id = (*cov)[size_t(yy) * size_t(w) + size_t(xx)];
                        if (id != centre) band[size_t(y) * size_t(w) + size_t(x)] = 1;
                    }
            }
    return band;
}

// Coverage with a vertical edge: id 1 left of x = edge, 0 from there on.
std::vector<uint32_t> edgeCoverage(int w, int h, int edge) {
    std::vector<uint32_t> cov(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) cov[size_t(y) * size_t(w) + size_t(x)] = x < edge ? 1u : 0u;
    return cov;
}

}  // namespace

TEST(Compare, IdenticalImagesPassWithZeros) {
    const Image8 a = noise(64, 48, 1);
    const CompareResult r = compareImages(a, a);
    EXPECT_TRUE(r.pass);
    EXPECT_TRUE(r.reasons.empty());
    EXPECT_EQ(r.interior.pixels, 64 * 48);
    EXPECT_EQ(r.band.pixels, 0);
    for (const RegionStats* s : {&r.interior, &r.all}) {
        EXPECT_EQ(s->mean, 0.0);
        EXPECT_EQ(s->rms, 0.0);
        EXPECT_EQ(s->max, 0);
        EXPECT_EQ(s->maxX, -1);
        EXPECT_EQ(s->maxChannel, -1);
        EXPECT_EQ(s->overThreshold, 0);
    }
}

TEST(Compare, SinglePixelDifferencesGiveExactMetrics) {
    const Image8 a = solid(10, 10);
    Image8 b = a;
    at(b, 3, 7, 1) += 5;  // G +5 at (3, 7)
    at(b, 8, 2, 2) -= 2;  // B -2 at (8, 2): earlier in row-major order but smaller
    at(b, 9, 9, 0) += 5;  // ties with (3, 7) but later: the first one is reported
    const CompareResult r = compareImages(a, b);
    EXPECT_DOUBLE_EQ(r.all.mean, 12.0 / 300.0);
    EXPECT_DOUBLE_EQ(r.all.rms, std::sqrt(54.0 / 300.0));
    EXPECT_EQ(r.all.max, 5);
    EXPECT_EQ(r.all.maxX, 3);
    EXPECT_EQ(r.all.maxY, 7);
    EXPECT_STREQ(channelName(r.all.maxChannel), "G");
    EXPECT_EQ(r.all.overThreshold, 2);
    EXPECT_DOUBLE_EQ(r.all.fractionOver(), 0.02);
    // 2% of pixels over 3/255 breaks the 0.1% gate.
    ASSERT_FALSE(r.pass);
    ASSERT_EQ(r.reasons.size(), 1u);
    EXPECT_EQ(r.reasons[0], "interior: 2.00% of pixels over 3/255 (limit 0.10%; 2 of 100 pixels)");
    keepEvidenceOnFailure("single_pixel", a, b, r);
}

TEST(Compare, OverMeansStrictlyGreaterThanThreshold) {
    const Image8 a = solid(100, 100);
    Image8 atLimit = a, overLimit = a;
    at(atLimit, 5, 5, 0) += 3;
    at(overLimit, 5, 5, 0) += 4;
    EXPECT_EQ(compareImages(a, atLimit).all.overThreshold, 0);
    EXPECT_EQ(compareImages(a, overLimit).all.overThreshold, 1);
}

TEST(Compare, FractionGateWithNegativeControl) {
    const Image8 a = solid(100, 100);  // 10 000 interior pixels: the 0.1% limit is 10 pixels
    for (int n : {9, 10, 11}) {
        Image8 b = a;
        for (int i = 0; i < n; ++i) at(b, i * 7, i * 3, i % 3) += 10;
        const CompareResult r = compareImages(a, b);
        EXPECT_EQ(r.interior.overThreshold, n);
        EXPECT_EQ(r.pass, n <= 10) << n << " pixels over: " << compareSummary(r);
        keepEvidenceOnFailure("fraction_" + std::to_string(n), a, b, r);
    }
}

TEST(Compare, HardMaxGateWithNegativeControl) {
    const Image8 a = solid(100, 100);
    Image8 b16 = a, b17 = a;
    at(b16, 12, 7, 1) += 16;
    at(b17, 12, 7, 1) += 17;
    EXPECT_TRUE(compareImages(a, b16).pass);
    const CompareResult r = compareImages(a, b17);
    ASSERT_FALSE(r.pass);
    ASSERT_EQ(r.reasons.size(), 1u);
    EXPECT_EQ(r.reasons[0], "interior: max 17/255 at (12, 7) channel G (limit 16/255; 1 pixels over)");
    EXPECT_EQ(r.interior.overHardMax, 1);
}

TEST(Compare, OptionalMeanGate) {
    const Image8 a = solid(10, 10);
    Image8 b = a;
    for (int x = 0; x < 10; ++x) at(b, x, 0, 0) += 3;  // 30 levels over 300 samples: mean 0.1
    CompareGates g;
    g.maxFractionOver = 1.0;
    EXPECT_TRUE(compareImages(a, b, g).pass);
    g.maxMean = 0.1;
    EXPECT_TRUE(compareImages(a, b, g).pass);
    g.maxMean = 0.09;
    const CompareResult r = compareImages(a, b, g);
    ASSERT_FALSE(r.pass);
    EXPECT_EQ(r.reasons[0], "interior: mean 0.100/255 (limit 0.090/255)");
}

TEST(Compare, RgbAgainstRgbaReadsMissingAlphaAsOpaque) {
    const Image8 rgb = solid(4, 4, 3);
    Image8 rgba = solid(4, 4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) at(rgba, x, y, 3) = 255;
    EXPECT_EQ(compareImages(rgb, rgba).all.max, 0);
    at(rgba, 2, 1, 3) = 250;
    const CompareResult r = compareImages(rgba, rgb);
    EXPECT_EQ(r.channels, 4);
    EXPECT_EQ(r.all.max, 5);
    EXPECT_STREQ(channelName(r.all.maxChannel), "A");
}

TEST(Compare, MismatchedSizesAreAnInputError) {
    const Image8 a = solid(4, 3), b = solid(2, 2);
    try {
        compareImages(a, b);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "image sizes differ: 4x3 vs 2x2");
    }
    EXPECT_THROW(diffHeatmap(a, b), InputError);
    CompareGates g;
    g.threshold = 300;
    EXPECT_THROW(compareImages(a, a, g), InputError);
    // A coverage buffer of the wrong size is a programmer error: CHECK names both sizes.
    EXPECT_DEATH(silhouetteBand(std::vector<uint32_t>(3), std::vector<uint32_t>(4), 2, 2), "CHECK failed.*3 vs 4");
}

TEST(SilhouetteBand, HandMadeSixBySix) {
    // A 3x3 block of id 1 in both; B also shows id 2 in the bottom-right corner.
    const int w = 6, h = 6;
    std::vector<uint32_t> ca(w * h, 0);
    for (int y = 1; y <= 3; ++y)
        for (int x = 1; x <= 3; ++x) ca[size_t(y * w + x)] = 1;
    std::vector<uint32_t> cb = ca;
    cb[size_t(5 * w + 5)] = 2;
    const char* expected[h] = {"11111.", "11111.", "11.11.", "11111.", "111111", "....11"};
    const std::vector<uint8_t> band = silhouetteBand(ca, cb, w, h);
    for (int y = 0; y < h; ++y) {
        std::string row;
        for (int x = 0; x < w; ++x) row += band[size_t(y * w + x)] ? '1' : '.';
        EXPECT_EQ(row, expected[y]) << "row " << y;
    }
}

TEST(SilhouetteBand, DiscAndRandomIdsMatchBruteForce) {
    const int w = 32, h = 32;
    std::vector<uint32_t> disc(w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) disc[size_t(y * w + x)] = (x - 16) * (x - 16) + (y - 15) * (y - 15) <= 100;
    const std::vector<uint8_t> band = silhouetteBand(disc, disc, w, h);
    EXPECT_EQ(band, bruteForceBand(disc, disc, w, h));
    EXPECT_EQ(band[size_t(15 * w + 16)], 0);  // disc centre is interior
    EXPECT_EQ(band[0], 0);                    // far corner is interior
    EXPECT_EQ(band[size_t(15 * w + 26)], 1);  // rim (x = 16 + 10) is band
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        const int tw = 1 + int(rng() % 9), th = 1 + int(rng() % 9);
        std::vector<uint32_t> a(size_t(tw * th)), b(size_t(tw * th));
        for (auto& v : a) v = rng() % 5 == 0 ? 1u : 0u;
        for (auto& v : b) v = rng() % 7 == 0 ? 2u : 0u;
        EXPECT_EQ(silhouetteBand(a, b, tw, th), bruteForceBand(a, b, tw, th)) << tw << "x" << th;
    }
}

TEST(Compare, DifferencesInsideTheBandDoNotCountForInteriorGates) {
    const int w = 64, h = 100;
    const std::vector<uint32_t> cov = edgeCoverage(w, h, 32);
    const Image8 a = solid(w, h);
    Image8 b = a;
    for (int y = 0; y < h; ++y) at(b, 31, y, 0) = at(b, 32, y, 2) = 200;  // aliasing along the edge
    const CompareResult r = compareImages(a, b, cov, cov);
    EXPECT_TRUE(r.pass) << compareSummary(r);
    EXPECT_EQ(r.band.pixels, 2 * h);
    EXPECT_EQ(r.interior.max, 0);
    EXPECT_EQ(r.band.max, 100);
    EXPECT_EQ(r.all.max, 100);
    EXPECT_EQ(r.all.overThreshold, 2 * h);
    keepEvidenceOnFailure("band_differences", a, b, r);
}

TEST(Compare, CoverageMismatchInsideBandWithinTwoPercentWithNegativeControl) {
    const int w = 64, h = 100;
    const Image8 img = solid(w, h);
    const std::vector<uint32_t> ca = edgeCoverage(w, h, 32);
    // B's edge moves right by one pixel on isolated rows. Band: columns 31-32 on every row, plus
    // column 33 on the moved rows and their neighbours.
    for (const std::vector<int>& rows : {std::vector<int>{10, 50}, std::vector<int>{10, 30, 50, 70, 90}}) {
        std::vector<uint32_t> cb = ca;
        for (int y : rows) cb[size_t(y * w + 32)] = 1;
        const CompareResult r = compareImages(img, img, ca, cb);
        const int64_t moved = int64_t(rows.size());
        EXPECT_EQ(r.band.pixels, 2 * h + 3 * moved);
        EXPECT_EQ(r.coverageMismatches, moved);
        EXPECT_EQ(r.mismatchesOutsideBand, 0);
        // 2 of 206 band pixels (0.97%) pass; 5 of 215 (2.33%) fail.
        EXPECT_EQ(r.pass, moved == 2) << compareSummary(r);
        if (!r.pass) {
            ASSERT_EQ(r.reasons.size(), 1u);
            EXPECT_EQ(r.reasons[0],
                      "coverage differs at 2.33% of silhouette band pixels (limit 2.00%; 5 of 215 pixels)");
        }
    }
}

TEST(Compare, CoverageMismatchOutsideBandFails) {
    const int w = 16, h = 16;
    const Image8 img = solid(w, h);
    std::vector<uint32_t> ca(w * h, 0);
    for (int y = 4; y < 9; ++y)
        for (int x = 4; x < 9; ++x) ca[size_t(y * w + x)] = 1;
    std::vector<uint32_t> cb = ca;
    for (auto& v : cb) v = v == 1 ? 3u : v;  // same shape, wrong object: the 3x3 inside is not band
    const CompareResult r = compareImages(img, img, ca, cb);
    EXPECT_EQ(r.coverageMismatches, 25);
    EXPECT_EQ(r.mismatchesOutsideBand, 9);
    ASSERT_FALSE(r.pass);
    EXPECT_EQ(r.reasons[0], "coverage differs at 9 pixels outside the silhouette band");
}

TEST(Heatmap, ZeroIsBlackAndTheRampRisesMonotonically) {
    const Image8 a = noise(16, 8, 3);
    const Image8 same = diffHeatmap(a, a);
    EXPECT_EQ(same.channels, 3);
    EXPECT_TRUE(std::all_of(same.data.begin(), same.data.end(), [](uint8_t v) { return v == 0; }));
    auto luminance = [](const uint8_t* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
    for (int v = 1; v < 256; ++v) EXPECT_GE(luminance(heatRamp(v)), luminance(heatRamp(v - 1))) << v;
    for (int v : {255, 1000})  // white, clamped above
        for (int c = 0; c < 3; ++c) EXPECT_EQ(heatRamp(v)[c], 255);

    Image8 b = a;
    at(b, 1, 1, 0) ^= 1;  // difference of 1
    const uint8_t v = a.pixel(2, 1)[2];
    at(b, 2, 1, 2) = uint8_t(v < 128 ? v + 5 : v - 5);  // difference of 5
    const Image8 heat = diffHeatmap(a, b, 16);
    EXPECT_GT(luminance(heat.pixel(1, 1)), 0.0);
    EXPECT_GT(luminance(heat.pixel(2, 1)), luminance(heat.pixel(1, 1)));

    const std::vector<uint8_t> band(16 * 8, 1);  // band outline: at least dark grey
    EXPECT_EQ(diffHeatmap(a, a, band).pixel(0, 0)[1], 48);
}

TEST(Heatmap, SideBySideLaysImagesOutWithGaps) {
    const Image8 a = solid(3, 2, 3, 10), b = solid(2, 4, 4, 200);
    const Image8 s = sideBySide({&a, &b}, 4);
    EXPECT_EQ(s.width, 3 + 4 + 2);
    EXPECT_EQ(s.height, 4);
    EXPECT_EQ(s.channels, 3);
    EXPECT_EQ(s.pixel(2, 1)[0], 10);
    EXPECT_EQ(s.pixel(2, 2)[0], 24);  // padding below the shorter image
    EXPECT_EQ(s.pixel(5, 0)[0], 24);  // gap
    EXPECT_EQ(s.pixel(8, 3)[2], 200);
    EXPECT_EQ(sideBySide({}).width, 0);
}

// Leaves raster | traced | heatmap as `--renderer both` shows it, on a disc whose difference grows to
// the right, with the band outlined.
TEST(Heatmap, DemoStripIsLeftInTheOutputFolder) {
    const int w = 96, h = 64;
    Image8 a = solid(w, h), b = solid(w, h);
    std::vector<uint32_t> cov(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool inDisc = std::hypot(x - 48, y - 32) < 24.0;
            cov[size_t(y * w + x)] = inDisc;
            for (int c = 0; c < 3; ++c) at(a, x, y, c) = at(b, x, y, c) = uint8_t(inDisc ? 60 + 60 * c : 20);
            if (inDisc) at(b, x, y, 1) = uint8_t(at(a, x, y, 1) + (x - 24) / 3);  // 0..16 levels
        }
    const CompareResult r = compareImages(a, b, cov, cov);
    const Image8 heat = diffHeatmap(a, b, r.bandMask);
    const Image8 strip = sideBySide({&a, &b, &heat});
    writePng(outStem("heat_demo.png"), strip);
    EXPECT_EQ(strip.width, 3 * w + 8);
    EXPECT_GT(heat.pixel(70, 32)[0] + heat.pixel(70, 32)[1], heat.pixel(40, 32)[0] + heat.pixel(40, 32)[1]);
}

TEST(Report, JsonParsesBackWithVerdictAndMetrics) {
    const Image8 a = solid(100, 100);
    Image8 b = a;
    at(b, 12, 7, 1) += 40;
    CompareGates g;
    g.maxMean = 1.0;
    const CompareResult r = compareImages(a, b, edgeCoverage(100, 100, 50), edgeCoverage(100, 100, 50), g);
    const std::vector<std::string> paths = writeCompareEvidence(outStem("report_example"), a, b, r);
    for (const std::string& p : paths) EXPECT_TRUE(fs::exists(p)) << p;
    EXPECT_EQ(readPng(paths[2]).width, 100);

    const nlohmann::json j = nlohmann::json::parse(compareReportJson(r, "a.png", "b.png"));
    EXPECT_EQ(j["verdict"], "fail");
    EXPECT_EQ(j["pass"], false);
    EXPECT_EQ(j["image_a"], "a.png");
    ASSERT_EQ(j["reasons"].size(), 1u);
    EXPECT_EQ(j["reasons"][0], "interior: max 40/255 at (12, 7) channel G (limit 16/255; 1 pixels over)");
    EXPECT_EQ(j["gates"]["threshold"], 3);
    EXPECT_EQ(j["gates"]["max_mean"], 1.0);
    const auto& in = j["regions"]["interior"];
    EXPECT_EQ(in["max"], 40);
    EXPECT_EQ(in["max_x"], 12);
    EXPECT_EQ(in["max_y"], 7);
    EXPECT_EQ(in["max_channel"], "G");
    EXPECT_EQ(in["pixels"], 100 * 100 - 200);
    EXPECT_DOUBLE_EQ(in["mean"].get<double>(), r.interior.mean);
    EXPECT_EQ(j["regions"]["band"]["max_channel"], nullptr);  // nothing differs in the band
    EXPECT_EQ(j["regions"]["band"]["max_x"], nullptr);
    EXPECT_EQ(j["coverage"]["band_pixels"], 200);
    EXPECT_EQ(j["coverage"]["mismatches_outside_band"], 0);

    const std::string summary = compareSummary(r);
    std::printf("%s", summary.c_str());
    EXPECT_NE(summary.find("max  40 at (12, 7) G"), std::string::npos) << summary;
    EXPECT_NE(summary.find("verdict: FAIL"), std::string::npos) << summary;
}

// Not a timed test (benchmarks live in bench/): prints the cost of a 1080p compare for the record.
TEST(Compare, FullHdCompareCost) {
    const int w = 1920, h = 1080;
    const Image8 a = noise(w, h, 11);
    Image8 b = a;
    for (size_t i = 0; i < b.data.size(); i += 97) b.data[i] ^= 3;
    std::vector<uint32_t> cov(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) cov[size_t(y) * w + size_t(x)] = std::hypot(x - 960, y - 540) < 400.0;
    std::vector<double> plain, covered;
    for (int rep = 0; rep < 5; ++rep) {
        auto t0 = std::chrono::steady_clock::now();
        const CompareResult r1 = compareImages(a, b);
        auto t1 = std::chrono::steady_clock::now();
        const CompareResult r2 = compareImages(a, b, cov, cov);
        auto t2 = std::chrono::steady_clock::now();
        EXPECT_EQ(r1.all.overThreshold, 0);
        EXPECT_EQ(r2.all.pixels, int64_t(w) * h);
        plain.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        covered.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    }
    std::sort(plain.begin(), plain.end());
    std::sort(covered.begin(), covered.end());
    std::printf("1920x1080 compare, median of 5: %.2f ms without coverage, %.2f ms with coverage\n", plain[2],
                covered[2]);
}
