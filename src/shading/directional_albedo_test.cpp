// directionalAlbedo against closed forms: white Lambert reflects all light at every angle, a
// tight normalised Phong lobe at normal incidence reflects ms, and GGX without multiple-scattering
// compensation loses energy, more as roughness grows. Each with a control that must fail.
#include "shading/directional_albedo.h"

#include <gtest/gtest.h>

using namespace shadelab::shading;

namespace {
const float kAngles[] = {1.0f, 0.9f, 0.7f, 0.5f, 0.3f, 0.1f, 0.02f};  // N·V
}

TEST(DirectionalAlbedo, WhiteLambertIsOneAtEveryAngle) {
    for (float NoV : kAngles) {
        EXPECT_NEAR(modelAlbedo(SL_MODEL_PHONG, NoV, vec3(1.0f), vec3(0.0f), 1.0f, true, false), 1.0f, 2e-3f) << NoV;
        EXPECT_NEAR(modelAlbedo(SL_MODEL_PBR, NoV, vec3(1.0f), vec3(0.04f), 0.5f, true, false), 1.0f, 2e-3f) << NoV;
        // Control: a 0.9 grey must not pass as white.
        EXPECT_GT(std::fabs(modelAlbedo(SL_MODEL_PHONG, NoV, vec3(0.9f), vec3(0.0f), 1.0f, true, false) - 1.0f), 0.05f);
    }
}

TEST(DirectionalAlbedo, TightNormalisedPhongAtNormalIncidenceReflectsMs) {
    // V = N: (1/π) ∫ ms (s+2)/2 (N·L)^s dω = ms (s+2)/(s+1) → ms; the lecture's lobe gives ms · 2/(s+1).
    const float ms = 0.6f;
    for (float s : {100.0f, 1000.0f, 10000.0f}) {
        const float normalized =
            modelAlbedo(SL_MODEL_PHONG, 1.0f, vec3(0.0f), vec3(ms * phongNormalization(s)), s, false, true);
        EXPECT_NEAR(normalized, ms * (s + 2.0f) / (s + 1.0f), 2e-3f) << s;
        EXPECT_NEAR(normalized, ms, 1e-2f) << s;
        const float lecture = modelAlbedo(SL_MODEL_PHONG, 1.0f, vec3(0.0f), vec3(ms), s, false, true);
        EXPECT_NEAR(lecture, ms * 2.0f / (s + 1.0f), 1e-3f) << s;
        EXPECT_GT(std::fabs(lecture - ms), 0.5f * ms) << "control: the unnormalised lobe loses the energy";
    }
}

TEST(DirectionalAlbedo, GgxWithoutCompensationIsBelowOneAndFallsWithRoughness) {
    // A white metal (F0 = 1): what is missing is the multiple scattering a single-scattering BRDF leaves out.
    for (float NoV : {1.0f, 0.7f, 0.3f}) {
        float previous = 1.0f;
        for (float roughness : {0.05f, 0.25f, 0.5f, 0.75f, 1.0f}) {
            const float e = modelAlbedo(SL_MODEL_PBR, NoV, vec3(0.0f), vec3(1.0f), roughness, false, true);
            EXPECT_LT(e, previous + (roughness <= 0.25f ? 2e-3f : 0.0f)) << NoV << " " << roughness;
            EXPECT_LT(e, 1.0f + 2e-3f) << NoV << " " << roughness;
            EXPECT_GT(e, 0.3f) << NoV << " " << roughness;
            previous = e;
        }
        EXPECT_LT(previous, 0.8f) << NoV;  // roughness 1 loses a lot (Kulla & Conty 2017, Fig. 2)
    }
    // Smooth GGX keeps almost everything: the single-scattering lobe is nearly complete.
    EXPECT_NEAR(modelAlbedo(SL_MODEL_PBR, 1.0f, vec3(0.0f), vec3(1.0f), 0.05f, false, true), 1.0f, 1e-2f);
}

TEST(DirectionalAlbedo, AgreesWithTheBruteForceGridWhereThatResolvesTheLobe) {
    // The uniform (cos θ, φ) midpoint grid of pbr_test, fine enough for a broad lobe: same answer.
    const vec3 N(0.0f, 0.0f, 1.0f);
    auto brute = [&](float NoV, float s) {
        const vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
        const int n = 512;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const float u = (float(i) + 0.5f) / float(n), r = std::sqrt(1.0f - u * u);
            for (int j = 0; j < n; ++j) {
                const float phi = 2.0f * SL_PI * (float(j) + 0.5f) / float(n);
                const vec3 L(r * std::cos(phi), r * std::sin(phi), u);
                sum += double(
                    shadeLight(N, L, V, vec3(1.0f), vec3(0.0f), vec3(1.0f), s, SL_MODEL_BLINN_PHONG, false, true).x);
            }
        }
        return float(sum / n * (2.0 / n));  // (1/π) · (1/n) · (2π/n)
    };
    for (float NoV : {0.9f, 0.4f}) {
        const float b = brute(NoV, 8.0f);
        EXPECT_NEAR(modelAlbedo(SL_MODEL_BLINN_PHONG, NoV, vec3(0.0f), vec3(1.0f), 8.0f, false, true), b, 2e-3f);
        // Control: another exponent is told apart.
        EXPECT_GT(std::fabs(modelAlbedo(SL_MODEL_BLINN_PHONG, NoV, vec3(0.0f), vec3(1.0f), 10.0f, false, true) - b),
                  1e-2f);
    }
}
