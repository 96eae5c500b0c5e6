// Multiple-scattering energy compensation (Filament, "Energy loss in specular reflectance") against
// numerical albedos: GGX without compensation loses energy, more with roughness; with
// energyCompensation() from the DFG table a white metal (F0 = 1) reflects within 1 % of all the light.
#include "shading/dfg_lut.h"
#include "shading/ibl_lookup.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace shadelab::shading;

namespace {

const vec3 kUp(0.0f, 0.0f, 1.0f);

// Directional albedo of the pbr specular lobe of shadeLightScaled (π·f·N·L per unit light), F0 = 1, by GGX
// importance sampling with 2^16 Hammersley points (pdf(L) = D·N·H / (4 V·H)), independent of the table's
// 1024.
float specularAlbedo(float NoV, float roughness, vec3 specScale) {
    const vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
    const float a = pbrAlpha(roughness);
    const int n = 1 << 16;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        float u, v;
        hammersley(unsigned(k), unsigned(n), u, v);
        const vec3 H = importanceSampleGGX(u, v, a);
        const float VoH = dot(V, H);
        const vec3 L = 2.0f * VoH * H - V;
        if (L.z <= 0.0f || VoH <= 0.0f) continue;
        const float pdf = D_GGX(H.z, H.x * H.x + H.y * H.y, a) * H.z / (4.0f * VoH);
        const vec3 I = shadeLightScaled(kUp, L, V, vec3(1.0f), vec3(0.0f), vec3(1.0f), roughness, SL_MODEL_PBR, false,
                                        true, specScale);
        sum += double(I.x) / SL_PI / double(pdf);
    }
    return float(sum / n);
}

vec2 dfgAt(float NoV, float roughness) { return IblLookup{nullptr, &dfgLut()}.dfgAt(NoV, roughness); }

}  // namespace

TEST(EnergyCompensation, DfgTableMatchesTheGgxAlbedo) {
    // A + B is the albedo of the lobe with F = 1, at texel centres and between them.
    for (float roughness : {0.3f, 0.5f, 0.8f, 1.0f})
        for (float NoV : {0.2f, 0.5f, 0.9f}) {
            const vec2 ab = dfgAt(NoV, roughness);
            EXPECT_NEAR(ab.x + ab.y, specularAlbedo(NoV, roughness, vec3(1.0f)), 0.01f)
                << "roughness " << roughness << ", N·V " << NoV;
        }
}

TEST(EnergyCompensation, GgxAlbedoWithoutCompensationIsBelowOneAndFallsWithRoughness) {
    float previous = 1.0f;
    for (float roughness : {0.25f, 0.5f, 0.75f, 1.0f}) {
        const float e = specularAlbedo(0.7f, roughness, vec3(1.0f));
        EXPECT_LT(e, previous) << "roughness " << roughness;
        previous = e;
    }
    EXPECT_LT(previous, 0.9f);  // roughness 1 loses more than 10 %
}

TEST(EnergyCompensation, WhiteMetalReflectsWithinOnePercentOfOne) {
    for (float roughness : {0.25f, 0.5f, 0.75f, 1.0f})
        for (float NoV : {0.3f, 0.6f, 1.0f}) {
            const vec3 comp = energyCompensation(vec3(1.0f), dfgAt(NoV, roughness));
            const float e = specularAlbedo(NoV, roughness, comp);
            EXPECT_NEAR(e, 1.0f, 0.01f) << "roughness " << roughness << ", N·V " << NoV;
        }
}

// Negative control: the same 1 % test must see the loss without compensation at high roughness.
TEST(EnergyCompensation, NegativeControlWithoutCompensationFails) {
    for (float roughness : {0.75f, 1.0f})
        EXPECT_GT(std::abs(specularAlbedo(0.6f, roughness, vec3(1.0f)) - 1.0f), 0.01f) << "roughness " << roughness;
}

TEST(EnergyCompensation, IsOneForDielectricsWithNoLossAndGrowsWithF0) {
    const vec2 dfg = dfgAt(0.5f, 1.0f);
    EXPECT_EQ(energyCompensation(vec3(0.0f), dfg).x, 1.0f);
    EXPECT_LT(energyCompensation(vec3(0.04f), dfg).x, energyCompensation(vec3(1.0f), dfg).x);
}

TEST(EnergyCompensation, UniformEnvironmentOnAWhiteSurfaceReflectsTheEnvironment) {
    // shadeEnvironment's layering: diffuse·(1 − E) + E = 1 for a white dielectric, and F0 = 1 compensated.
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
        const vec2 dfg = dfgAt(0.6f, roughness);
        const vec3 white(1.0f);
        EXPECT_NEAR(shadeEnvironment(white, vec3(0.04f), white, white, dfg, false, true, true).x, 1.0f, 1e-6f);
        EXPECT_NEAR(shadeEnvironment(vec3(0.0f), white, white, white, dfg, true, true, true).x, 1.0f, 1e-5f);
    }
}
