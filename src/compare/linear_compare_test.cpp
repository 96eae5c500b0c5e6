// compareLinear: identical images pass, a real change in any gate's direction fails (negative controls), the
// floor keeps near-black noise from counting as huge, and non-finite samples are compared as documented.
#include "compare/linear_compare.h"

#include "util/input_error.h"

#include <gtest/gtest.h>
#include <limits>
#include <nlohmann/json.hpp>

using namespace shadelab;

namespace {

// A radiance ramp reaching 40 (far above display white) with a dark corner.
ImageF radiance(int w, int h) {
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            p[0] = 40.0f * float(x) / float(w);
            p[1] = 0.5f + 0.01f * float(y);
            p[2] = x < 4 && y < 4 ? 0.0f : 2.0f;
            p[3] = 1.0f;
        }
    return img;
}

}  // namespace

TEST(LinearCompare, IdenticalImagesPass) {
    const ImageF a = radiance(64, 48);
    const LinearCompareResult r = compareLinear(a, a);
    EXPECT_TRUE(r.pass);
    EXPECT_EQ(r.maxRelative, 0.0);
    EXPECT_EQ(r.relativeRmse, 0.0);
    EXPECT_EQ(r.maxX, -1);
    EXPECT_NE(linearSummary(r).find("verdict: PASS"), std::string::npos);
}

TEST(LinearCompare, ScaleFreeAndFloored) {
    const ImageF a = radiance(64, 48);
    // 2 % brighter everywhere: within the 5 % threshold per pixel, but the relative RMSE gate (1 %) sees it.
    ImageF b = a;
    for (float& v : b.rgba) v *= 1.02f;
    LinearCompareResult r = compareLinear(a, b);
    EXPECT_EQ(r.overThreshold, 0);
    EXPECT_NEAR(r.relativeRmse, 0.02, 0.002);
    EXPECT_FALSE(r.pass) << linearSummary(r);
    // The same 2 % passes once the RMSE gate allows it: the per-pixel gates are relative, not absolute, so a
    // brightness of 40 is judged like one of 0.5.
    LinearGates loose;
    loose.maxRelativeRmse = 0.03;
    EXPECT_TRUE(compareLinear(a, b, loose).pass) << linearSummary(compareLinear(a, b, loose));
    // Near black, the floor: 0.001 against 0 is 9 % of (0.001 + 0.01), not infinitely different.
    ImageF c = a;
    c.pixel(1, 1)[2] = 0.001f;
    r = compareLinear(a, c);
    EXPECT_NEAR(r.maxRelative, 0.001 / 0.011, 1e-6);
    EXPECT_EQ(r.overHardMax, 0);
}

TEST(LinearCompare, NegativeControlsFail) {
    const ImageF a = radiance(64, 48);
    // One pixel far off: the hard maximum.
    ImageF b = a;
    b.pixel(30, 20)[1] *= 2.0f;
    LinearCompareResult r = compareLinear(a, b);
    EXPECT_FALSE(r.pass);
    EXPECT_EQ(r.overHardMax, 1);
    EXPECT_EQ(r.maxX, 30);
    EXPECT_EQ(r.maxY, 20);
    EXPECT_EQ(r.maxChannel, 1);
    // 1 % of pixels 10 % off: the fraction over the threshold (and its percentile).
    ImageF c = a;
    for (int i = 0; i < 31; ++i) c.pixel(i * 2, 10)[0] = a.pixel(i * 2, 10)[0] * 1.1f + 0.01f;
    r = compareLinear(a, c);
    EXPECT_FALSE(r.pass) << linearSummary(r);
    EXPECT_EQ(r.overThreshold, 31);
    EXPECT_GT(r.percentile, 0.05);
    // A NaN in one image only.
    ImageF d = a;
    d.pixel(2, 2)[0] = std::numeric_limits<float>::quiet_NaN();
    r = compareLinear(a, d);
    EXPECT_FALSE(r.pass);
    EXPECT_EQ(r.nonFiniteMismatches, 1);
    EXPECT_TRUE(compareLinear(d, d).pass) << "the same NaN in both is no difference";
    const nlohmann::json j = nlohmann::json::parse(linearReportJson(r, "a.exr", "b.exr"));
    EXPECT_EQ(j["verdict"], "fail");
    EXPECT_EQ(j["max"]["relative"], "inf");
}

TEST(LinearCompare, SizesMustMatch) {
    EXPECT_THROW(compareLinear(radiance(8, 8), radiance(8, 9)), InputError);
    LinearGates bad;
    bad.threshold = -1.0;
    EXPECT_THROW(compareLinear(radiance(8, 8), radiance(8, 8), bad), InputError);
}

TEST(LinearCompare, HeatmapIsBlackWhereEqualAndWhiteAtTheHardMaximum) {
    const ImageF a = radiance(16, 16);
    ImageF b = a;
    b.pixel(5, 5)[0] = a.pixel(5, 5)[0] * 2.0f + 1.0f;
    const Image8 heat = linearHeatmap(compareLinear(a, b));
    EXPECT_EQ(heat.pixel(0, 0)[0], 0);
    EXPECT_EQ(heat.pixel(5, 5)[0], 255);
    EXPECT_EQ(heat.pixel(5, 5)[1], 255);
}
