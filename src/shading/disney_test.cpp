// The principled BRDF's closed forms (Burley 2012 and 2015; lighting.glsl's shadeLightDisney): its two
// distributions are normalised, its 2012 diffuse equals the 2015 split form, and a parameter at its neutral
// value changes nothing. Each with a negative control that must fail.
#include "shading/lighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace shadelab::shading {
namespace {

// ∫ D(h)·cos θh dω over the hemisphere for an isotropic D of (cos θh, 1 − cos² θh), in y = 1 − cos θh on a
// logarithmic grid: the peak of a sharp lobe (width α² in y) is resolved whatever α.
template <class D>
double projectedIntegral(D d) {
    const int n = 200000;
    const double lo = std::log(1e-14), hi = 0.0;
    double sum = d(1.0, 0.0) * 1e-14;  // the sliver below the grid
    double prevY = 1e-14, prevF = d(1.0 - 1e-14, 2e-14) * (1.0 - 1e-14);
    for (int i = 1; i <= n; ++i) {
        const double y = std::exp(lo + (hi - lo) * i / n), t = 1.0 - y;
        const double f = d(t, y * (2.0 - y)) * t;
        sum += 0.5 * (f + prevF) * (y - prevY);
        prevY = y;
        prevF = f;
    }
    return 2.0 * 3.14159265358979 * sum;
}

// The same for an anisotropic D over (cos θh, φ): φ on a uniform grid, cos θh as above.
double projectedIntegralAniso(float ax, float ay) {
    const int nPhi = 720, nY = 3000;
    const double lo = std::log(1e-12), pi = 3.14159265358979;
    double total = 0.0;
    for (int j = 0; j < nPhi; ++j) {
        const double phi = 2.0 * pi * (j + 0.5) / nPhi, c = std::cos(phi), s = std::sin(phi);
        double sum = 0.0, prevY = 0.0, prevF = 0.0;
        for (int i = 0; i <= nY; ++i) {
            const double y = i == 0 ? 0.0 : std::exp(lo + (0.0 - lo) * i / nY), t = 1.0 - y;
            const double st = std::sqrt(std::max(0.0, 1.0 - t * t));
            const float D = D_GTR2Aniso(float(t), float(st * c), float(st * s), ax, ay);
            const double f = double(D) * t;
            if (i > 0) sum += 0.5 * (f + prevF) * (y - prevY);
            prevY = y;
            prevF = f;
        }
        total += sum * (2.0 * pi / nPhi);
    }
    return total;
}

TEST(Disney, Gtr1IsNormalisedOverTheProjectedHemisphere) {
    for (float a : {0.001f, 0.01f, 0.05f, 0.1f, 0.5f, 0.9f, 1.0f}) {
        const double I = projectedIntegral([a](double t, double s2) { return double(D_GTR1(float(t), float(s2), a)); });
        EXPECT_NEAR(I, 1.0, 1e-3) << "alpha " << a;
    }
    // Negative control: GTR1 without its 1/ln(α²) normalisation (Berry's plain form) is not.
    const float a = 0.1f;
    const double wrong = projectedIntegral(
        [a](double t, double s2) { return double(D_GTR1(float(t), float(s2), a)) * std::log(a * a); });
    EXPECT_GT(std::abs(std::abs(wrong) - 1.0), 0.1);
}

TEST(Disney, AnisotropicGtr2IsNormalisedOverTheProjectedHemisphere) {
    for (float roughness : {0.1f, 0.3f, 0.7f, 1.0f})
        for (float anisotropic : {0.0f, 0.5f, 0.9f, 1.0f}) {
            const glm::vec2 a = disneyAnisoAlpha(roughness, anisotropic);
            EXPECT_NEAR(projectedIntegralAniso(a.x, a.y), 1.0, 1e-3)
                << "roughness " << roughness << ", anisotropic " << anisotropic << " (ax " << a.x << ", ay " << a.y
                << ")";
        }
    // Negative control: the distribution with one width where it reads the other's (ax·ay → ax²) is not.
    const glm::vec2 a = disneyAnisoAlpha(0.5f, 0.9f);
    EXPECT_GT(std::abs(projectedIntegralAniso(a.x, a.y) * a.y / a.x - 1.0), 0.1);
}

// Burley 2015, "Extending the Disney BRDF to a BSDF with Integrated Subsurface Scattering", §5.3: the diffuse
// split into Lambert's part (1 − FL/2)(1 − FV/2)/π and a retro-reflection Rr (FL + FV + FL·FV·(Rr − 1))/π with
// Rr = 2·roughness·cos²θd. `retro` false drops the second part (the negative control).
float splitDiffuse(float NoL, float NoV, float LoH, float roughness, bool retro = true) {
    const float FL = schlickWeight(NoL), FV = schlickWeight(NoV);
    const float Rr = 2.0f * roughness * LoH * LoH;
    const float lambert = (1.0f - 0.5f * FL) * (1.0f - 0.5f * FV) / SL_PI;
    return lambert + (retro ? Rr * (FL + FV + FL * FV * (Rr - 1.0f)) / SL_PI : 0.0f);
}

TEST(Disney, DiffuseEqualsTheSplitFormOf2015) {
    std::mt19937 rng(20261204);
    std::normal_distribution<float> g;
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const vec4 d0(0.0f, 0.5f, 0.0f, 0.0f), d1(0.0f, 0.5f, 0.0f, 1.0f);  // no subsurface, no sheen
    int cases = 0, noticed = 0;
    float worst = 0.0f;
    for (int i = 0; i < 4096; ++i) {
        const vec3 N(0.0f, 0.0f, 1.0f);
        const vec3 L = normalize(vec3(g(rng), g(rng), std::abs(g(rng)) + 0.01f));
        const vec3 V = normalize(vec3(g(rng), g(rng), std::abs(g(rng)) + 0.01f));
        const float roughness = unit(rng);
        const vec3 I =
            shadeLightDisney(N, L, V, vec3(1.0f), vec3(1.0f), 0.0f, roughness, d0, d1, true, false, vec3(1.0f));
        const float f = I.x / (SL_PI * L.z);  // the BRDF itself: the result is π·f·N·L under unit light
        const float LoH = dot(L, normalize(L + V));
        const float split = splitDiffuse(L.z, V.z, LoH, roughness);
        worst = std::max(worst, std::abs(f - split));
        if (std::abs(f - splitDiffuse(L.z, V.z, LoH, roughness, false)) > 1e-4f) ++noticed;
        ++cases;
    }
    EXPECT_LT(worst, 2e-6f) << "over " << cases << " cases";
    EXPECT_GT(noticed, cases / 2) << "the retro-reflection dropped went unnoticed: the test cannot fail";
}

// Each optional lobe at its neutral value (subsurface, sheen, clearcoat 0; anisotropic 0 is isotropic) is
// exactly absent: the full BRDF equals its parts, and a lobe turned on changes it.
TEST(Disney, LobesAtZeroAreAbsentAndOnAreNot) {
    std::mt19937 rng(7);
    std::normal_distribution<float> g;
    const vec3 N(0.0f, 0.0f, 1.0f), base(0.8f, 0.3f, 0.1f);
    const vec4 d0(0.0f, 0.5f, 0.0f, 0.0f), d1(0.0f, 0.5f, 0.0f, 1.0f);
    int sheenSeen = 0, coatSeen = 0, subsurfaceSeen = 0;
    for (int i = 0; i < 1024; ++i) {
        const vec3 L = normalize(vec3(g(rng), g(rng), std::abs(g(rng)) + 0.05f));
        const vec3 V = normalize(vec3(g(rng), g(rng), std::abs(g(rng)) + 0.05f));
        const auto f = [&](vec4 a, vec4 b, bool diffuse, bool specular) {
            return shadeLightDisney(N, L, V, vec3(1.0f), base, 0.2f, 0.4f, a, b, diffuse, specular, vec3(1.0f));
        };
        const vec3 both = f(d0, d1, true, true), sum = f(d0, d1, true, false) + f(d0, d1, false, true);
        EXPECT_NEAR(length(both - sum), 0.0f, 1e-6f);
        if (length(f(d0, vec4(1.0f, 0.5f, 0.0f, 1.0f), true, true) - both) > 1e-4f) ++sheenSeen;
        if (length(f(d0, vec4(0.0f, 0.5f, 1.0f, 1.0f), true, true) - both) > 1e-4f) ++coatSeen;
        if (length(f(vec4(1.0f, 0.5f, 0.0f, 0.0f), d1, true, true) - both) > 1e-4f) ++subsurfaceSeen;
    }
    EXPECT_GT(sheenSeen, 500);
    EXPECT_GT(coatSeen, 500);
    EXPECT_GT(subsurfaceSeen, 500);
}

// specular = 0.5, untinted, gives pbr's dielectric F0 of 0.04; a metal's F0 is its base colour.
TEST(Disney, SpecularF0MatchesPbrAtItsDefault) {
    const vec3 base(0.9f, 0.5f, 0.2f);
    EXPECT_NEAR(length(disneySpecularF0(base, 0.0f, 0.5f, 0.0f) - vec3(0.04f)), 0.0f, 1e-7f);
    EXPECT_NEAR(length(disneySpecularF0(base, 1.0f, 0.5f, 0.7f) - base), 0.0f, 1e-7f);
    EXPECT_GT(length(disneySpecularF0(base, 0.0f, 0.5f, 1.0f) - vec3(0.04f)), 0.01f) << "specularTint tints";
}

}  // namespace
}  // namespace shadelab::shading
