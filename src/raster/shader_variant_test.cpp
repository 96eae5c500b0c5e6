// The colour passes' variant key: which frame and shadow data select a program, and the #define prelude.
#include "raster/shader_variant.h"

#include "raster/frame_block.h"
#include "raster/shadow_block.h"

#include <gtest/gtest.h>

#include <string>

namespace shadelab::raster {
namespace {

// Two point lights (the second attenuated) and a directional one, with the shadow pass on.
FrameBlock threeLights() {
    FrameBlock f{};
    f.flags = glm::ivec4(1, kTermDiffuse | kTermSpecular, 3, kPassShadows);
    f.lightPos[0] = glm::vec4(1.0f, 2.0f, 3.0f, 1.0f);
    f.lightPos[1] = glm::vec4(0.0f, 5.0f, 0.0f, 1.0f);
    f.lightPos[2] = glm::vec4(0.0f, -1.0f, 0.0f, 0.0f);
    for (int i = 0; i < 3; ++i) f.lightAtten[i] = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    f.lightAtten[1] = glm::vec4(1.0f, 0.1f, 0.0f, 0.0f);
    return f;
}

ShadowBlock shadowsFor() {
    ShadowBlock s{};
    s.info = glm::ivec4(2, 1, 1024, 0);
    s.light[0] = glm::ivec4(kShadowCube, 0, 0b01, 0);
    s.light[1] = glm::ivec4(kShadowPerspective, 6, 0b11, 0);
    s.light[2] = glm::ivec4(kShadowOrtho, 7, 0, 0);
    return s;
}

bool contains(const std::string& text, const std::string& line) { return text.find(line) != std::string::npos; }

TEST(ShaderVariant, FromFrameAndShadows) {
    const ShadowBlock shadows = shadowsFor();
    const ShaderVariant v = makeShaderVariant(threeLights(), &shadows);
    EXPECT_TRUE(v.shadows);
    EXPECT_EQ(v.model, 1);
    EXPECT_EQ(v.terms, kTermDiffuse | kTermSpecular);
    EXPECT_EQ(v.lights, 3);
    EXPECT_FALSE(v.moreLights);
    EXPECT_EQ(v.planes, 2);
    EXPECT_TRUE(v.pcf);
    const std::string d = v.defines();
    EXPECT_TRUE(contains(d, "#define SL_SHADOWS 1\n"));
    EXPECT_TRUE(contains(d, "#define SL_MODEL 1\n"));
    EXPECT_TRUE(contains(d, "#define SL_AMBIENT false\n"));
    EXPECT_TRUE(contains(d, "#define SL_DIFFUSE true\n"));
    EXPECT_TRUE(contains(d, "#define SL_LIGHTS 3\n"));
    EXPECT_TRUE(contains(d,
                         "#define SL_FOR_EACH_LIGHT(F)  F(0, true, false, 3, 1, 0) F(1, true, true, 2, 3, 6)"
                         " F(2, false, false, 1, 0, 7)\n"))
        << d;
    EXPECT_TRUE(contains(d, "#define SL_SHADOW_PLANES 2\n"));
    EXPECT_TRUE(contains(d, "#define SL_PCF 1\n"));
}

// Without the shadow pass (no pass bit, or no block) the shadow fields stay zero, whatever the block says.
TEST(ShaderVariant, ShadowsOnlyWithThePass) {
    const ShadowBlock shadows = shadowsFor();
    FrameBlock f = threeLights();
    f.flags.w = 0;
    for (const ShaderVariant& v : {makeShaderVariant(f, &shadows), makeShaderVariant(threeLights(), nullptr)}) {
        EXPECT_FALSE(v.shadows);
        EXPECT_EQ(v.planes, 0);
        EXPECT_EQ(v.shadowKind[0], kShadowNone);
        EXPECT_EQ(v.planeMask[1], 0);
        EXPECT_TRUE(contains(v.defines(), "#define SL_SHADOWS 0\n"));
    }
}

// The key changes with what the programs specialise on, and not with positions or colours.
TEST(ShaderVariant, KeyFollowsSpecialisationOnly) {
    const ShadowBlock shadows = shadowsFor();
    const std::string base = makeShaderVariant(threeLights(), &shadows).defines();
    FrameBlock moved = threeLights();
    moved.lightPos[0] = glm::vec4(-4.0f, 0.5f, 2.0f, 1.0f);
    moved.lightColor[2] = glm::vec4(0.3f);
    EXPECT_EQ(makeShaderVariant(moved, &shadows).defines(), base);
    ShadowBlock otherMask = shadows;
    otherMask.light[2].z = 0b10;
    EXPECT_NE(makeShaderVariant(threeLights(), &otherMask).defines(), base);
    FrameBlock unattenuated = threeLights();
    unattenuated.lightAtten[1] = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    EXPECT_NE(makeShaderVariant(unattenuated, &shadows).defines(), base);
}

// Lights past kMaxShadowedLights go to the generic loop; the count is clamped to kMaxLights.
TEST(ShaderVariant, ManyLights) {
    FrameBlock f{};
    f.flags = glm::ivec4(0, kTermDiffuse, kMaxLights + 5, 0);
    const ShaderVariant v = makeShaderVariant(f, nullptr);
    EXPECT_EQ(v.lights, kMaxShadowedLights);
    EXPECT_TRUE(v.moreLights);
    EXPECT_TRUE(contains(v.defines(), "#define SL_MORE_LIGHTS 1\n"));
    f.flags.z = kMaxShadowedLights;
    EXPECT_FALSE(makeShaderVariant(f, nullptr).moreLights);
}

}  // namespace
}  // namespace shadelab::raster
