// glTF's specular layer and ior on pbr (lighting.glsl's shadeLightPbrSpecular and its split sum) against closed
// forms: with pbr's own dielectric F0 (0.04) and weight 1 it is pbr (a dielectric and a metal); a weight of 0 has
// no specular lobe and an untouched diffuse; head-on, the dielectric reflects its F0 exactly, so that an index
// sets it; the diffuse keeps 1 − max3 of the dielectric's tinted Fresnel. Each with a negative control.
#include "shading/lighting.h"

#include <gtest/gtest.h>
#include <random>

using namespace shadelab::shading;

namespace {

vec3 randomVector(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return vec3(g(rng), g(rng), g(rng));
}

float relative(vec3 a, vec3 b) {
    const vec3 d = abs(a - b);
    return std::max({d.x, d.y, d.z}) / std::max(1.0f, std::max({std::abs(b.x), std::abs(b.y), std::abs(b.z)}));
}

const vec4 kPbrLayer(0.04f, 0.04f, 0.04f, 1.0f);  // pbr's own: F0 0.04, weight 1

}  // namespace

TEST(SpecularLayer, PbrsOwnLayerIsPbrForDielectricsAndMetals) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    float worst = 0.0f;
    for (int i = 0; i < 2000; ++i) {
        const vec3 N = randomVector(rng), L = randomVector(rng), V = randomVector(rng);
        const vec3 base(unit(rng), unit(rng), unit(rng));
        const float metallic = i % 2 ? 1.0f : 0.0f, roughness = unit(rng);
        const vec3 md = pbrDiffuseColor(base, metallic);
        const vec3 layered = shadeLightPbrSpecular(N, L, V, vec3(1.0f), md, base, metallic, roughness, kPbrLayer,
                                                   vec4(0.0f), true, true, vec3(1.0f));
        const vec3 pbr =
            shadeLight(N, L, V, vec3(1.0f), md, pbrF0(base, metallic), roughness, SL_MODEL_PBR, true, true);
        worst = std::max(worst, relative(layered, pbr));
    }
    EXPECT_LT(worst, 1e-5f);
    EXPECT_EQ(pbrSpecularF0(vec3(0.5f), 0.0f, kPbrLayer), pbrF0(vec3(0.5f), 0.0f));
    // Negative control: another F0 is not pbr.
    const vec3 N(0.0f, 0.0f, 1.0f), L = normalize(vec3(0.3f, 0.0f, 1.0f)), V = normalize(vec3(-0.3f, 0.0f, 1.0f));
    const vec3 other = shadeLightPbrSpecular(N, L, V, vec3(1.0f), vec3(0.5f), vec3(0.5f), 0.0f, 0.3f,
                                             vec4(0.1f, 0.1f, 0.1f, 1.0f), vec4(0.0f), true, true, vec3(1.0f));
    EXPECT_GT(relative(other, shadeLight(N, L, V, vec3(1.0f), vec3(0.5f), vec3(0.04f), 0.3f, SL_MODEL_PBR, true, true)),
              1e-3f);
}

TEST(SpecularLayer, WeightZeroHasNoSpecularAndAFullDiffuse) {
    std::mt19937 rng(12);
    for (int i = 0; i < 500; ++i) {
        const vec3 N = randomVector(rng), L = randomVector(rng), V = randomVector(rng);
        const vec4 none(0.04f, 0.04f, 0.04f, 0.0f);
        const vec3 all = shadeLightPbrSpecular(N, L, V, vec3(1.0f), vec3(0.6f), vec3(0.6f), 0.0f, 0.4f, none,
                                               vec4(0.0f), true, true, vec3(1.0f));
        const vec3 diffuse = shadeLightPbrSpecular(N, L, V, vec3(1.0f), vec3(0.6f), vec3(0.6f), 0.0f, 0.4f, none,
                                                   vec4(0.0f), true, false, vec3(1.0f));
        EXPECT_EQ(all, diffuse) << i;
    }
}

// Head-on (N = L = V, so V·H = 1) a dielectric reflects exactly its F0, times the weight: an index of 1.33 gives
// 0.0201 and 2.4 (diamond) 0.1696, where pbr would say 0.04.
TEST(SpecularLayer, HeadOnTheDielectricReflectsItsF0) {
    const vec3 N(0.0f, 0.0f, 1.0f);
    for (float ior : {1.33f, 1.5f, 2.4f})
        for (float w : {1.0f, 0.5f}) {
            const float r = (ior - 1.0f) / (ior + 1.0f), f0 = r * r;
            const vec4 layer(f0, f0, f0, w);
            const vec3 spec = shadeLightPbrSpecular(N, N, N, vec3(1.0f), vec3(0.0f), vec3(0.0f), 0.0f, 0.3f, layer,
                                                    vec4(0.0f), false, true, vec3(1.0f));
            const vec3 lobe = SL_PI * specularGGX(N, N, N, vec3(1.0f), 0.3f);  // D·V·π, F = 1
            EXPECT_NEAR(spec.x / lobe.x, w * f0, 1e-6f) << "ior " << ior << ", weight " << w;
            if (ior != 1.5f) {
                EXPECT_GT(std::abs(spec.x / lobe.x - w * 0.04f), 1e-3f) << "control: not pbr's 0.04";
            }
        }
}

// The extension's fresnel_mix: the diffuse keeps 1 − w·max3(F), not 1 − F per channel, so a tinted F0 does not
// colour the diffuse.
TEST(SpecularLayer, TheDiffuseKeepsOneMinusTheLargestFresnel) {
    const vec3 N(0.0f, 0.0f, 1.0f), L = normalize(vec3(0.5f, 0.0f, 1.0f)), V = normalize(vec3(-0.2f, 0.3f, 1.0f));
    const vec4 tinted(0.2f, 0.05f, 0.01f, 0.8f);
    const vec3 md(0.5f);
    const vec3 both = shadeLightPbrSpecular(N, L, V, vec3(1.0f), md, vec3(0.5f), 0.0f, 0.4f, tinted, vec4(0.0f), true,
                                            true, vec3(1.0f));
    const vec3 spec = shadeLightPbrSpecular(N, L, V, vec3(1.0f), md, vec3(0.5f), 0.0f, 0.4f, tinted, vec4(0.0f), false,
                                            true, vec3(1.0f));
    const vec3 diffuse = both - spec;
    EXPECT_NEAR(diffuse.x, diffuse.y, 1e-6f);
    EXPECT_NEAR(diffuse.y, diffuse.z, 1e-6f);
    const float VoH = dot(V, normalize(L + V));
    const vec3 Fd = 0.8f * F_Schlick(vec3(0.2f, 0.05f, 0.01f), VoH);
    EXPECT_NEAR(diffuse.x, 0.5f * dot(N, L) * (1.0f - Fd.x), 1e-6f);
    EXPECT_GT(std::abs(diffuse.z - 0.5f * dot(N, L) * (1.0f - Fd.z)), 1e-3f) << "control: per channel would differ";
}

// glTF's anisotropy (anisotropicGGX through shadeLightPbrSpecular): a strength of 0 is the isotropic lobe exactly
// (the function's own branch) and to 1e-5 through the stretched formulas (D_GTR2Aniso and the anisotropic
// height-correlated Smith at αt = αb = α are D_GGX and V_SmithGGXCorrelated); a half-turn of the direction changes
// nothing (the lobe is symmetric); the lobe is wider along its direction than across it, and a quarter-turn swaps
// the two (negative control: without the turn they stay).
TEST(Anisotropy, StrengthZeroIsTheIsotropicLobeAndTheLobeStretchesAlongItsDirection) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 500; ++i) {
        vec3 N = normalize(randomVector(rng)), L = normalize(randomVector(rng)), V = normalize(randomVector(rng));
        if (dot(N, L) < 0.05f) L = -L;
        if (dot(N, L) < 0.05f || dot(N, V) < 0.05f) continue;
        const float roughness = 0.1f + 0.9f * unit(rng), r = 6.0f * unit(rng);
        const vec4 off(anisotropyDirection(N, vec4(0.0f), vec3(0.0f, std::cos(r), std::sin(r))), 0.0f);
        const vec3 on = anisotropyDirection(N, vec4(0.0f), vec3(0.7f, std::cos(r), std::sin(r)));
        const vec3 iso = shadeLightPbrSpecular(N, L, V, vec3(1.0f), vec3(0.3f), vec3(0.3f), 0.2f, roughness, kPbrLayer,
                                               vec4(0.0f), true, true, vec3(1.0f));
        EXPECT_EQ(shadeLightPbrSpecular(N, L, V, vec3(1.0f), vec3(0.3f), vec3(0.3f), 0.2f, roughness, kPbrLayer, off,
                                        true, true, vec3(1.0f)),
                  iso);
        const float stretched = anisotropicGGX(N, L, V, vec3(off), roughness, 0.0f);
        const float ggx = specularGGX(N, L, V, vec3(1.0f), roughness).x;
        EXPECT_NEAR(stretched, ggx, 1e-5f * std::max(1.0f, ggx)) << "roughness " << roughness;
        const vec3 halfTurn(0.7f, std::cos(r + SL_PI), std::sin(r + SL_PI));
        const float a = anisotropicGGX(N, L, V, on, roughness, 0.7f);
        const float b = anisotropicGGX(N, L, V, anisotropyDirection(N, vec4(0.0f), halfTurn), roughness, 0.7f);
        EXPECT_NEAR(a, b, 1e-4f * std::max(1.0f, a));
    }
    // Head-on view, the light 30° off the mirror direction along T and then across it: the lobe reaches further
    // along T (αt = mix(α, 1, s²) > α).
    const vec3 N(0.0f, 0.0f, 1.0f), V = N;
    const vec3 aniso(0.8f, 1.0f, 0.0f), turned(0.8f, 0.0f, 1.0f);  // turns of 0 and π/2
    const vec3 T = anisotropyDirection(N, vec4(0.0f), aniso), B = cross(N, T);
    const float t = std::sin(0.52f), c = std::cos(0.52f);
    const vec3 alongT = c * N + t * T, acrossT = c * N + t * B;
    EXPECT_GT(anisotropicGGX(N, alongT, V, T, 0.3f, 0.8f), 2.0f * anisotropicGGX(N, acrossT, V, T, 0.3f, 0.8f));
    const vec3 T2 = anisotropyDirection(N, vec4(0.0f), turned);
    EXPECT_GT(anisotropicGGX(N, acrossT, V, T2, 0.3f, 0.8f), 2.0f * anisotropicGGX(N, alongT, V, T2, 0.3f, 0.8f));
    EXPECT_LT(anisotropicGGX(N, acrossT, V, T, 0.3f, 0.8f), anisotropicGGX(N, alongT, V, T, 0.3f, 0.8f));
    // A mesh's tangent sets X (made orthogonal to N), its w the bitangent's side: a quarter-turn goes toward
    // w·(N × X); a zero tangent falls back to anisotropyTangent(N).
    const vec4 meshTangent(0.0f, 1.0f, 0.3f, -1.0f);
    const vec3 X = anisotropyDirection(N, meshTangent, vec3(1.0f, 1.0f, 0.0f));
    EXPECT_NEAR(length(X - vec3(0.0f, 1.0f, 0.0f)), 0.0f, 1e-6f);
    const vec3 Y = anisotropyDirection(N, meshTangent, vec3(1.0f, 0.0f, 1.0f));
    EXPECT_NEAR(length(Y - vec3(1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f);  // −(N × X) = −(−x) = +x
    EXPECT_EQ(anisotropyDirection(N, vec4(0.0f), vec3(1.0f, 1.0f, 0.0f)), anisotropyTangent(N));
}
