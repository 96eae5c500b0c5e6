// shaders/texture_sample.glsl through its C++ view over 8-bit texels: known texel values (nearest gives the
// texels, bilinear the analytic average), the three wrap modes, and the level selection. Negative controls: a
// half-texel shift of the sample point must change nearest's answer, and bilinear at a corner is not any one texel.
#include "shading/texture_sample.h"

#include "shading/texel_decode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace shadelab::shading {
namespace {

// A 4×4 level 0 with distinct 8-bit texels (linear codes), its 2×2 and 1×1 levels (each texel the rounded mean
// of the four below it: which codes they hold does not matter here, only that lookups return them).
struct Chain {
    std::vector<uint8_t> l0, l1, l2;
    TexelLevelView views[3];
    TextureLookup lookup;
    Chain() {
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x)
                for (int v : {x * 60, y * 60, (x + 4 * y) * 15, 255}) l0.push_back(uint8_t(v));
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                for (int k = 0; k < 4; ++k)
                    l1.push_back(uint8_t((code(l0, 4, 2 * x, 2 * y, k) + code(l0, 4, 2 * x + 1, 2 * y, k) +
                                          code(l0, 4, 2 * x, 2 * y + 1, k) + code(l0, 4, 2 * x + 1, 2 * y + 1, k) + 2) /
                                         4));
        for (int k = 0; k < 4; ++k)
            l2.push_back(uint8_t(
                (code(l1, 2, 0, 0, k) + code(l1, 2, 1, 0, k) + code(l1, 2, 0, 1, k) + code(l1, 2, 1, 1, k) + 2) / 4));
        views[0] = {4, 4, l0.data()};
        views[1] = {2, 2, l1.data()};
        views[2] = {1, 1, l2.data()};
        lookup.levels = views;
        lookup.levelCount = 3;
        lookup.rgb = unormDecodeTable().data();
        lookup.alpha = unormDecodeTable().data();
    }
    static int code(const std::vector<uint8_t>& l, int w, int x, int y, int k) {
        return l[size_t((y * w + x) * 4 + k)];
    }
    // Texel (x, y) of a level as the lookup decodes it.
    static glm::vec4 decoded(const std::vector<uint8_t>& l, int w, int x, int y) {
        const auto& t = unormDecodeTable();
        return {t[size_t(code(l, w, x, y, 0))], t[size_t(code(l, w, x, y, 1))], t[size_t(code(l, w, x, y, 2))],
                t[size_t(code(l, w, x, y, 3))]};
    }
    glm::vec4 at(int x, int y) const { return decoded(l0, 4, x, y); }
    glm::vec4 level1(int i) const { return decoded(l1, 2, i % 2, i / 2); }
    glm::vec4 level2() const { return decoded(l2, 1, 0, 0); }
    glm::vec4 sample(glm::vec2 uv, bool linear, int wrap = kTexRepeat, float lod = 0.0f, bool mipmaps = true,
                     bool mipLinear = false) {
        return lookup.texSample(0, 3, wrap, wrap, linear, linear, mipmaps, mipLinear, uv, lod);
    }
};

TEST(TextureSample, NearestAtPixelExactScaleGivesTheTexels) {
    Chain c;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            // A 4×4-pixel quad head-on: pixel (x, y)'s centre samples uv = ((x + 0.5)/4, (y + 0.5)/4).
            const glm::vec2 uv((x + 0.5f) / 4.0f, (y + 0.5f) / 4.0f);
            EXPECT_EQ(c.sample(uv, false), c.at(x, y)) << x << "," << y;
            EXPECT_EQ(c.sample(uv, true), c.at(x, y)) << "bilinear at a texel centre is that texel";
        }
    // Negative control: half a texel off, nearest moves to the next texel.
    EXPECT_NE(c.sample({(1 + 1.0f) / 4.0f + 0.01f, 0.125f}, false), c.at(1, 0));
}

TEST(TextureSample, BilinearGivesTheAnalyticAverage) {
    Chain c;
    // At the corner shared by texels (1,1), (2,1), (1,2), (2,2): their mean.
    const glm::vec4 corner = 0.25f * (c.at(1, 1) + c.at(2, 1) + c.at(1, 2) + c.at(2, 2));
    const glm::vec4 got = c.sample({0.5f, 0.5f}, true);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], corner[k], 1e-6f);
    EXPECT_NE(got, c.at(1, 1));  // negative control: not any one texel
    // A quarter of the way from (0,0)'s centre to (1,0)'s: weights 3/4, 1/4.
    const glm::vec4 q = c.sample({(0.5f + 0.25f) / 4.0f, 0.125f}, true);
    const glm::vec4 want = 0.75f * c.at(0, 0) + 0.25f * c.at(1, 0);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(q[k], want[k], 1e-6f);
}

TEST(TextureSample, WrapModes) {
    Chain c;
    EXPECT_EQ(c.sample({1.125f, 0.125f}, false, kTexRepeat), c.at(0, 0));
    EXPECT_EQ(c.sample({-0.875f, 0.125f}, false, kTexRepeat), c.at(0, 0));
    EXPECT_EQ(c.sample({1.125f, 0.125f}, false, kTexMirroredRepeat), c.at(3, 0));
    EXPECT_EQ(c.sample({-0.125f, 0.125f}, false, kTexMirroredRepeat), c.at(0, 0));
    EXPECT_EQ(c.sample({2.125f, 0.125f}, false, kTexMirroredRepeat), c.at(0, 0));
    EXPECT_EQ(c.sample({1.5f, 0.125f}, false, kTexClamp), c.at(3, 0));
    EXPECT_EQ(c.sample({-3.0f, 0.125f}, false, kTexClamp), c.at(0, 0));
    // Bilinear across the seam: repeat blends the last and first columns; clamp stays on the edge texel.
    const glm::vec4 seam = c.sample({0.0f, 0.125f}, true, kTexRepeat);
    const glm::vec4 want = 0.5f * (c.at(3, 0) + c.at(0, 0));
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(seam[k], want[k], 1e-6f);
    EXPECT_EQ(c.sample({0.0f, 0.125f}, true, kTexClamp), c.at(0, 0));
    EXPECT_EQ(c.sample({0.0f, 0.125f}, true, kTexMirroredRepeat), c.at(0, 0));
}

TEST(TextureSample, LevelSelection) {
    Chain c;
    // One texel per pixel: lod 0; two: lod 1; four: lod 2; more: clamped to the last level.
    EXPECT_NEAR(c.lookup.texLod(4, 4, {0.25f, 0.0f}, {0.0f, 0.25f}), 0.0f, 1e-6f);
    EXPECT_NEAR(c.lookup.texLod(4, 4, {0.5f, 0.0f}, {0.0f, 0.1f}), 1.0f, 1e-6f);
    EXPECT_NEAR(c.lookup.texLod(4, 4, {0.0f, 0.0f}, {0.0f, 1.0f}), 2.0f, 1e-6f);
    const glm::vec2 uv(0.3f, 0.3f);
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 1.0f), c.level1(0));
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 1.4f), c.level1(0));
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 1.6f), c.level2());
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 9.0f), c.level2());
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 2.0f, false), c.at(1, 1)) << "no mipmaps: level 0";
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, -3.0f), c.at(1, 1)) << "magnified: level 0";
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 0.4f), c.at(1, 1)) << "nearest level: level 0 up to lod 0.5";
    // Linear between levels: lod 1.25 blends levels 1 and 2 by 1/4.
    const glm::vec4 blend = c.sample(uv, false, kTexRepeat, 1.25f, true, true);
    const glm::vec4 want = 0.75f * c.level1(0) + 0.25f * c.level2();
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(blend[k], want[k], 1e-6f);
    // Mag bilinear with min nearest: minification starts at lod 0.5 (OpenGL's c), so 0.3 is still bilinear.
    const glm::vec4 mag = c.lookup.texSample(0, 3, kTexRepeat, kTexRepeat, true, false, true, true, {0.5f, 0.5f}, 0.3f);
    const glm::vec4 corner = 0.25f * (c.at(1, 1) + c.at(2, 1) + c.at(1, 2) + c.at(2, 2));
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(mag[k], corner[k], 1e-6f);
}

}  // namespace
}  // namespace shadelab::shading

namespace shadelab::shading {
namespace {

// A texture transform can overflow (scale 2 on a coordinate of 3e38) or a file can hold NaN: the fold must
// still land in the wrap mode's period, so the texel index that follows stays inside the image.
TEST(TextureSample, NonFiniteAndHugeCoordinatesFoldIntoThePeriod) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float hostile[] = {nan, inf, -inf, 1e38f, -1e38f, 3e38f * 2.0f, -0.0f, 1e-45f, -1e-45f};
    TextureLookup lookup;
    for (float c : hostile) {
        EXPECT_GE(lookup.texFold(c, kTexRepeat), 0.0f) << c;
        EXPECT_LT(lookup.texFold(c, kTexRepeat), 1.0f) << c;
        EXPECT_GE(lookup.texFold(c, kTexMirroredRepeat), 0.0f) << c;
        EXPECT_LT(lookup.texFold(c, kTexMirroredRepeat), 2.0f) << c;
        EXPECT_GE(lookup.texFold(c, kTexClamp), 0.0f) << c;
        EXPECT_LE(lookup.texFold(c, kTexClamp), 1.0f) << c;
    }
    // Negative control: the plain fold c − floor(c) leaves the period on exactly these inputs (NaN for NaN and
    // ±inf), and floor of NaN times the width as an int is what indexed before the image.
    for (float c : {nan, inf, -inf}) {
        const float plain = c - std::floor(c);
        EXPECT_FALSE(plain >= 0.0f && plain < 1.0f) << c;
    }
    // Finite coordinates fold as before.
    EXPECT_FLOAT_EQ(lookup.texFold(2.25f, kTexRepeat), 0.25f);
    EXPECT_FLOAT_EQ(lookup.texFold(-0.25f, kTexRepeat), 0.75f);
    EXPECT_FLOAT_EQ(lookup.texFold(3.5f, kTexMirroredRepeat), 1.5f);
    EXPECT_FLOAT_EQ(lookup.texFold(-3.0f, kTexClamp), 0.0f);
    EXPECT_FLOAT_EQ(lookup.texFold(0.5f, kTexClamp), 0.5f);
}

TEST(TextureSample, ASampleAtANonFiniteCoordinateIsATexelOfTheImage) {
    Chain c;
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (glm::vec2 uv : {glm::vec2(nan, 0.5f), glm::vec2(inf, -inf), glm::vec2(1e38f, 3e38f * 2.0f)})
        for (int wrap : {kTexRepeat, kTexMirroredRepeat, kTexClamp})
            for (bool linear : {false, true})
                for (float lod : {0.0f, 1.5f, inf, nan}) {
                    const glm::vec4 s = c.sample(uv, linear, wrap, lod, true, linear);
                    EXPECT_TRUE(std::isfinite(s.x + s.y + s.z + s.w)) << uv.x << " " << uv.y << " lod " << lod;
                    for (int k = 0; k < 4; ++k) {
                        EXPECT_GE(s[k], 0.0f);
                        EXPECT_LE(s[k], 1.0f);
                    }
                }
}

}  // namespace
}  // namespace shadelab::shading
