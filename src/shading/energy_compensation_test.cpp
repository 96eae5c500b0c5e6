// Multiple-scattering energy compensation (Filament, "Energy loss in specular reflectance") against
// the one albedo integrator (shading/directional_albedo.h): the DFG table holds the GGX albedo, and with
// energyCompensation() from it a white metal (F0 = 1) reflects within 1 % of all the light.
#include "shading/dfg_lut.h"
#include "shading/directional_albedo.h"
#include "shading/ibl_lookup.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace shadelab::shading;

namespace {

const vec3 kUp(0.0f, 0.0f, 1.0f);

// Directional albedo of the pbr specular lobe of shadeLightScaled (π·f·N·L per unit light), F0 = 1, by the one
// albedo integrator (shading/directional_albedo.h), independent of the table's own importance sampling.
float specularAlbedo(float NoV, float roughness, vec3 specScale) {
    return directionalAlbedo(
        [&](vec3 L, vec3 V) {
            return shadeLightScaled(kUp, L, V, vec3(1.0f), vec3(0.0f), vec3(1.0f), roughness, SL_MODEL_PBR, false, true,
                                    specScale)
                .x;
        },
        NoV);
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
