// The pbr BRDF of shaders/lighting.glsl against closed forms: Schlick's end points, GGX's
// normalisation, Lambert's 1/π and the light units of design.md §7;
// and the normalised Phong / Blinn-Phong lobes of §7.
#include "shading/directional_albedo.h"
#include "shading/local_illumination.h"

#include <gtest/gtest.h>
#include <cmath>
#include <vector>

using namespace shadelab::shading;

namespace {

const vec3 kUp(0.0f, 0.0f, 1.0f);

}  // namespace

TEST(Pbr, SchlickEndPoints) {
    const vec3 f0(0.04f, 0.5f, 0.95f);
    const vec3 atNormal = F_Schlick(f0, 1.0f);   // θ = 0°: V·H = 1
    const vec3 atGrazing = F_Schlick(f0, 0.0f);  // θ = 90°: V·H = 0
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(atNormal[c], f0[c]);
        EXPECT_FLOAT_EQ(atGrazing[c], 1.0f);
    }
}

TEST(Pbr, GgxIntegratesToOneOverProjectedHemisphere) {
    // ∫ D(h) (N·H) dω_h = 2π ∫_0^1 D(u) u du = π ∫_0^1 D(√t) dt with t = u²; midpoint rule in t.
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
        const float a = pbrAlpha(roughness);
        const int n = 1 << 20;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double u2 = (double(i) + 0.5) / double(n);  // N·H², and 1 − N·H² exactly
            sum += D_GGX(float(std::sqrt(u2)), float(1.0 - u2), a);
        }
        EXPECT_NEAR(M_PI * sum / n, 1.0, 1e-3) << "roughness " << roughness;
    }
}

// Lambert's f = c/π: a white surface's π·f is 1. Its albedo of 1 at every angle, and GGX's loss, are
// directional_albedo_test.cpp's, over the one albedo integrator (shading/directional_albedo.h).
TEST(Pbr, LambertIsOneOverPi) { EXPECT_NEAR(SL_PI * Fd_Lambert(), 1.0f, 1e-7f); }

TEST(Pbr, WhiteLambertianMatchesTheLectureDiffuseTermExactly) {
    // design.md §7: π-scaled lights make pbr's diffuse term the lecture's md·N·L, bit for bit.
    const vec3 md(0.8f, 0.5f, 0.25f), Il(1.0f, 0.9f, 0.7f);
    for (int i = 0; i < 64; ++i) {
        const vec3 L(std::cos(0.3f * float(i)), std::sin(0.7f * float(i)), 0.1f + 0.05f * float(i));
        const vec3 V(0.2f, -0.3f, 1.0f);
        const vec3 phong = shadeLight(kUp, L, V, Il, md, vec3(0.0f), 32.0f, SL_MODEL_PHONG, true, false);
        const vec3 blinn = shadeLight(kUp, L, V, Il, md, vec3(0.0f), 32.0f, SL_MODEL_BLINN_PHONG, true, false);
        const vec3 pbr = shadeLight(kUp, L, V, Il, md, vec3(0.04f), 0.5f, SL_MODEL_PBR, true, false);
        EXPECT_EQ(pbr, phong);
        EXPECT_EQ(pbr, blinn);
    }
}

TEST(Pbr, MetalsHaveNoDiffuseAndAreTintedByBaseColour) {
    const vec3 gold(1.0f, 0.78f, 0.34f);
    const SurfaceParams metal =
        surfaceParams(SL_MODEL_PBR, vec3(0.1f), vec3(0.7f), vec3(0.3f), 32.0f, gold, 1.0f, 0.4f);
    EXPECT_EQ(metal.md, vec3(0.0f));
    EXPECT_EQ(metal.ms, gold);
    EXPECT_EQ(metal.s, 0.4f);
    const SurfaceParams plastic =
        surfaceParams(SL_MODEL_PBR, vec3(0.1f), vec3(0.7f), vec3(0.3f), 32.0f, gold, 0.0f, 0.4f);
    EXPECT_EQ(plastic.md, gold);
    EXPECT_EQ(plastic.ms, vec3(0.04f));
    // The lecture's models read the lecture's coefficients untouched.
    const SurfaceParams phong =
        surfaceParams(SL_MODEL_PHONG, vec3(0.1f), vec3(0.7f), vec3(0.3f), 32.0f, gold, 1.0f, 0.4f);
    EXPECT_EQ(phong.md, vec3(0.7f));
    EXPECT_EQ(phong.s, 32.0f);
}

TEST(Pbr, SpecularPeaksAtTheMirrorDirectionAndVanishesBelowTheHorizon) {
    const vec3 L = glm::normalize(vec3(0.5f, 0.0f, 1.0f)), V = glm::normalize(vec3(-0.5f, 0.0f, 1.0f));
    const vec3 mirror = shadeLight(kUp, L, V, vec3(1.0f), vec3(0.0f), vec3(1.0f), 0.3f, SL_MODEL_PBR, false, true);
    const vec3 off = shadeLight(kUp, L, glm::normalize(vec3(-0.2f, 0.3f, 1.0f)), vec3(1.0f), vec3(0.0f), vec3(1.0f),
                                0.3f, SL_MODEL_PBR, false, true);
    EXPECT_GT(mirror.x, off.x);
    EXPECT_EQ(
        shadeLight(kUp, vec3(0.3f, 0.0f, -1.0f), V, vec3(1.0f), vec3(0.5f), vec3(1.0f), 0.3f, SL_MODEL_PBR, true, true),
        vec3(0.0f));
}

TEST(NormalizedLobes, ScaleTheLecturesSpecularCoefficientOnly) {
    const vec3 ms(0.5f, 0.25f, 1.0f);
    const SurfaceParams phong =
        surfaceParams(SL_MODEL_PHONG, vec3(0.1f), vec3(0.7f), ms, 32.0f, vec3(0.7f), 0.0f, 0.5f, true);
    EXPECT_EQ(phong.ms, ms * 17.0f);  // (32 + 2) / 2
    EXPECT_EQ(phong.md, vec3(0.7f));
    const SurfaceParams blinn =
        surfaceParams(SL_MODEL_BLINN_PHONG, vec3(0.1f), vec3(0.7f), ms, 32.0f, vec3(0.7f), 0.0f, 0.5f, true);
    EXPECT_EQ(blinn.ms, ms * 5.0f);  // (32 + 8) / 8
    const SurfaceParams off =
        surfaceParams(SL_MODEL_PHONG, vec3(0.1f), vec3(0.7f), ms, 32.0f, vec3(0.7f), 0.0f, 0.5f, false);
    EXPECT_EQ(off.ms, ms);  // the lecture's formula stays the default
    const SurfaceParams pbr =
        surfaceParams(SL_MODEL_PBR, vec3(0.1f), vec3(0.7f), ms, 32.0f, vec3(0.7f), 0.0f, 0.5f, true);
    EXPECT_EQ(pbr.ms, vec3(0.04f));
}

TEST(NormalizedLobes, PhongAlbedoAtNormalIncidenceIsAboutOne) {
    // V = N: R·V = N·L, so (1/π) ∫ (s+2)/2 (N·L)^s dω = (s + 2)/(s + 1), which tends to 1 as s grows; the
    // unnormalised lobe's 2/(s + 1) tends to 0.
    for (float s : {10.0f, 100.0f}) {
        const float normalized =
            modelAlbedo(SL_MODEL_PHONG, 1.0f, vec3(0.0f), vec3(phongNormalization(s)), s, false, true);
        EXPECT_NEAR(normalized, (s + 2.0f) / (s + 1.0f), 1e-2f) << "s " << s;
        const float lecture = modelAlbedo(SL_MODEL_PHONG, 1.0f, vec3(0.0f), vec3(1.0f), s, false, true);
        EXPECT_NEAR(lecture, 2.0f / (s + 1.0f), 1e-2f) << "s " << s;
    }
}
