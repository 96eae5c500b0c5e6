// shaders/texture_sample.glsl through its C++ view: known texel values (nearest gives the texels, bilinear
// the analytic average), the three wrap modes, and the level selection. Negative controls: a half-texel
// shift of the sample point must change nearest's answer, and bilinear at a corner is not any one texel.
#include "shading/texture_sample.h"

#include <gtest/gtest.h>

#include <vector>

namespace shadelab::shading {
namespace {

// A 4×4 level 0 with distinct texels, its 2×2 and 1×1 box-filtered levels.
struct Chain {
    std::vector<glm::vec4> l0, l1, l2;
    TexelLevelView views[3];
    TextureLookup lookup;
    Chain() {
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) l0.push_back(glm::vec4(x / 4.0f, y / 4.0f, (x + 4 * y) / 16.0f, 1.0f));
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                l1.push_back(0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                                      at(2 * x + 1, 2 * y + 1)));
        l2.push_back(0.25f * (l1[0] + l1[1] + l1[2] + l1[3]));
        views[0] = {4, 4, l0.data()};
        views[1] = {2, 2, l1.data()};
        views[2] = {1, 1, l2.data()};
        lookup.levels = views;
        lookup.levelCount = 3;
    }
    glm::vec4 at(int x, int y) const { return l0[size_t(y * 4 + x)]; }
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
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 1.0f), c.l1[0]);
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 1.4f), c.l1[0]);
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 1.6f), c.l2[0]);
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 9.0f), c.l2[0]);
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 2.0f, false), c.at(1, 1)) << "no mipmaps: level 0";
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, -3.0f), c.at(1, 1)) << "magnified: level 0";
    EXPECT_EQ(c.sample(uv, false, kTexRepeat, 0.4f), c.at(1, 1)) << "nearest level: level 0 up to lod 0.5";
    // Linear between levels: lod 1.25 blends levels 1 and 2 by 1/4.
    const glm::vec4 blend = c.sample(uv, false, kTexRepeat, 1.25f, true, true);
    const glm::vec4 want = 0.75f * c.l1[0] + 0.25f * c.l2[0];
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(blend[k], want[k], 1e-6f);
    // Mag bilinear with min nearest: minification starts at lod 0.5 (OpenGL's c), so 0.3 is still bilinear.
    const glm::vec4 mag = c.lookup.texSample(0, 3, kTexRepeat, kTexRepeat, true, false, true, true, {0.5f, 0.5f}, 0.3f);
    const glm::vec4 corner = 0.25f * (c.at(1, 1) + c.at(2, 1) + c.at(1, 2) + c.at(2, 2));
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(mag[k], corner[k], 1e-6f);
}

}  // namespace
}  // namespace shadelab::shading
