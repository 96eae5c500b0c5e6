// glTF's clear coat layer (lighting.glsl's clearcoatLight, clearcoatEnvironment) against its closed forms: a coat
// of factor 0, or with the specular term off, is the base exactly; under a white base in a white furnace the
// coated surface loses exactly factor·(Fc − E_coat) of the light, E_coat the coat lobe's albedo, which the
// split sum's DFG table holds; a coat over black reflects what the albedo integrator finds for the coat alone.
#include "shading/dfg_lut.h"
#include "shading/directional_albedo.h"
#include "shading/ibl_lookup.h"

#include <gtest/gtest.h>
#include <random>

using namespace shadelab::shading;

namespace {

const vec3 kUp(0.0f, 0.0f, 1.0f);

vec2 dfgAt(float NoV, float roughness) { return IblLookup{nullptr, &dfgLut()}.dfgAt(NoV, roughness); }

vec3 randomVector(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return vec3(g(rng), g(rng), g(rng));
}

// ρ(V) of the coat over a base (π·f·N·L of one unit light, pbr with the diffuse colour `base` and F0 0.04; none
// at all for a null `base`), mean of RGB.
float coatedAlbedo(float NoV, const vec3* base, float baseRoughness, vec2 coat) {
    return directionalAlbedo(
        [&](vec3 L, vec3 V) {
            const vec3 b =
                base ? shadeLight(kUp, L, V, vec3(1.0f), *base, vec3(0.04f), baseRoughness, SL_MODEL_PBR, true, true)
                     : vec3(0.0f);
            const vec3 I = clearcoatLight(b, kUp, L, V, vec3(1.0f), coat, true);
            return (I.x + I.y + I.z) / 3.0f;
        },
        NoV);
}

}  // namespace

TEST(Clearcoat, FactorZeroAndSpecularOffLeaveTheBaseExactly) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) {
        const vec3 base(unit(rng), unit(rng), unit(rng)), N = randomVector(rng), L = randomVector(rng),
                                                          V = randomVector(rng);
        const vec2 coat(unit(rng), unit(rng));
        EXPECT_EQ(clearcoatLight(base, N, L, V, vec3(1.0f), vec2(0.0f, coat.y), true), base);
        EXPECT_EQ(clearcoatLight(base, N, L, V, vec3(1.0f), coat, false), base);
        EXPECT_EQ(clearcoatEnvironment(base, N, V, vec3(1.0f), vec2(0.5f), vec2(0.0f, coat.y), true), base);
        EXPECT_EQ(clearcoatEnvironment(base, N, V, vec3(1.0f), vec2(0.5f), coat, false), base);
    }
    // Negative control: a coat there changes it.
    EXPECT_NE(clearcoatLight(vec3(0.5f), kUp, kUp, kUp, vec3(1.0f), vec2(0.1f, 0.3f), true), vec3(0.5f));
}

// The coat's Fresnel weight is Schlick's with F0 = 0.04: 4 % at normal incidence, all of it at grazing.
TEST(Clearcoat, WeightIsSchlicksFresnelOfTheCoat) {
    EXPECT_NEAR(clearcoatWeight(kUp, kUp, 1.0f), 0.04f, 1e-6f);
    EXPECT_NEAR(clearcoatWeight(kUp, vec3(1.0f, 0.0f, 0.0f), 1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(clearcoatWeight(kUp, kUp, 0.5f), 0.02f, 1e-6f);
}

// A coat over nothing (no base at all): what reflects is the coat's GGX lobe alone (F0 0.04), whose albedo the DFG
// table holds as 0.04·A + B; the integrator over lights and the split sum over a uniform white environment agree.
TEST(Clearcoat, CoatAloneReflectsTheSplitSumsAlbedo) {
    for (float roughness : {0.3f, 0.5f, 0.8f})
        for (float NoV : {0.3f, 0.6f, 0.95f}) {
            const vec2 coat(1.0f, roughness);
            const float lights = coatedAlbedo(NoV, nullptr, 0.5f, coat);
            const vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
            const float environment =
                clearcoatEnvironment(vec3(0.0f), kUp, V, vec3(1.0f), dfgAt(NoV, roughness), coat, true).x;
            EXPECT_NEAR(lights, environment, 0.01f) << "coat roughness " << roughness << ", N·V " << NoV;
        }
}

// The furnace: a white base (which alone reflects its whole albedo ρ_base) under a coat of factor c reflects
// ρ_base·(1 − c·Fc) + c·E_coat: the layering formula, integrated over the lights, to 1 %; a full coat at 10 %
// less is seen at grazing (negative control).
TEST(Clearcoat, WhiteFurnaceLosesTheLayeringFormulasShare) {
    for (float c : {0.5f, 1.0f})
        for (float NoV : {0.2f, 0.5f, 0.9f}) {
            const float roughness = 0.4f;
            const vec2 coat(c, roughness);
            const vec3 white(1.0f);
            const float base = coatedAlbedo(NoV, &white, 0.6f, vec2(0.0f));
            const float coated = coatedAlbedo(NoV, &white, 0.6f, coat);
            const vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
            const float Fc = clearcoatWeight(kUp, V, 1.0f);
            const vec2 dfg = dfgAt(NoV, roughness);
            const float eCoat = 0.04f * dfg.x + dfg.y;
            const float expected = base * (1.0f - c * Fc) + c * eCoat;
            EXPECT_NEAR(coated, expected, 0.01f) << "coat " << c << ", N·V " << NoV;
            const float weaker = base * (1.0f - 0.9f * c * Fc) + 0.9f * c * eCoat;
            if (c == 1.0f && NoV < 0.3f) {
                EXPECT_GT(std::abs(coated - weaker), 0.01f) << "coat " << c << ": 10 % less unseen";
            }
        }
}
