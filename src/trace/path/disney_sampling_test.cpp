// χ² tests of the principled BRDF's sampling routines (warp.h) against the densities they claim: anisotropic
// GGX's visible normals, GTR1's normals, and PathBsdf's whole disney mixture (diffuse, anisotropic specular,
// clearcoat) through sample() and pdf(). Each has a negative control: a deliberately wrong density must fail.
#include "shading/local_illumination.h"
#include "trace/path/chi2_test_util.h"
#include "trace/path/path_bsdf.h"

#include <gtest/gtest.h>

namespace shadelab::trace {
namespace {

using test::Chi2Result;

constexpr int kSamples = test::kChi2Samples;
constexpr double kAlpha = test::kChi2Alpha;

constexpr uint32_t kSeed = 4242u;  // this file's stream of numbers

glm::vec3 numbers(int k) { return test::sampleNumbers(k, kSeed); }

const glm::vec3 kOblique = glm::normalize(glm::vec3(0.5f, 0.2f, 0.6f));

// A micro-normal sampler against its density over the normal's solid angle. Micro-normals crowd around the pole
// (a width α² in 1 − cos θ): each bin's expected count is integrated on a finer grid than for directions.
Chi2Result testNormals(const std::function<glm::vec3(glm::vec2)>& sample,
                       const std::function<float(const glm::vec3&)>& pdf) {
    return test::chi2Directions(
        [&](int k) -> std::optional<glm::vec3> {
            const glm::vec3 u = numbers(k);
            return sample(glm::vec2(u.y, u.z));
        },
        [&](const glm::vec3& h) { return h.z > 0.0f ? pdf(h) : 0.0f; }, kSamples, 20, 40, 128);
}

TEST(DisneySampling, AnisotropicGgxVisibleNormalsMatchTheirPdf) {
    for (glm::vec2 a : {glm::vec2(0.5f, 0.1f), glm::vec2(0.2f, 0.6f), glm::vec2(0.3f, 0.3f)})
        for (glm::vec3 v : {kOblique, glm::vec3(0.0f, 0.0f, 1.0f), glm::normalize(glm::vec3(0.1f, 0.9f, 0.2f))}) {
            const Chi2Result r =
                testNormals([&](glm::vec2 u) { return sampleGgxAnisoVisibleNormal(v, a.x, a.y, u); },
                            [&](const glm::vec3& h) { return ggxAnisoVisibleNormalPdf(v, h, a.x, a.y); });
            EXPECT_GT(r.pValue, kAlpha) << "ax " << a.x << ", ay " << a.y << ": " << r.summary();
            EXPECT_EQ(r.observedOutside, 0.0);
        }
}

TEST(DisneySampling, Gtr1NormalsMatchTheirPdf) {
    for (float alpha : {0.1f, 0.05f, 0.3f}) {
        const Chi2Result r = testNormals([&](glm::vec2 u) { return sampleGtr1Normal(u, alpha); },
                                         [&](const glm::vec3& h) { return gtr1NormalPdf(h.z, alpha); });
        EXPECT_GT(r.pValue, kAlpha) << "alpha " << alpha << ": " << r.summary();
    }
}

// The BSDF on the plane z = 0 seen from V under disney: `metallic` 1 leaves the specular lobes alone.
PathBsdf makeDisney(Material& m, Surface& s, const glm::vec3& V, float metallic, float roughness, glm::vec4 d0,
                    glm::vec4 d1) {
    m.baseColor = glm::vec3(0.8f, 0.5f, 0.3f);
    m.metallic = metallic;
    m.roughness = roughness;
    s.material = &m;
    s.N = s.Nf = glm::vec3(0.0f, 0.0f, 1.0f);
    s.baseColor = m.baseColor;
    shading::SurfaceParams p = shading::surfaceParams(shading::SL_MODEL_DISNEY, m.ma, m.md, m.ms, m.s, m.baseColor,
                                                      metallic, roughness, false, d0, d1);
    return PathBsdf(s, p, V, shading::SL_MODEL_DISNEY, BsdfTerms{});
}

struct DisneyCase {
    float metallic, roughness;
    glm::vec4 d0, d1;
};

Chi2Result testDisney(const DisneyCase& c, const glm::vec3& V, const DisneyCase* claimedCase = nullptr) {
    Material m, m2;
    Surface s, s2;
    const PathBsdf bsdf = makeDisney(m, s, V, c.metallic, c.roughness, c.d0, c.d1);
    const DisneyCase& k = claimedCase ? *claimedCase : c;
    const PathBsdf claimed = makeDisney(m2, s2, V, k.metallic, k.roughness, k.d0, k.d1);
    return test::chi2OfMixture(bsdf, claimed, kSeed);
}

const glm::vec4 kD0(0.0f, 0.5f, 0.0f, 0.0f), kD1(0.0f, 0.5f, 0.0f, 1.0f);  // Disney's defaults

TEST(DisneySampling, TheMixtureMatchesItsPdf) {
    const DisneyCase cases[] = {
        {0.0f, 0.5f, kD0, kD1},                                                              // diffuse + specular
        {1.0f, 0.4f, glm::vec4(0.0f, 0.5f, 0.0f, 0.9f), kD1},                                // anisotropic metal
        {0.0f, 0.3f, glm::vec4(0.5f, 0.8f, 0.5f, 0.5f), glm::vec4(1.0f, 0.5f, 1.0f, 0.0f)},  // all lobes
        {1.0f, 0.6f, kD0, glm::vec4(0.0f, 0.5f, 1.0f, 0.5f)},                                // metal with a coat
    };
    for (const DisneyCase& c : cases)
        for (glm::vec3 V : {kOblique, glm::vec3(0.0f, 0.0f, 1.0f)}) {
            const Chi2Result r = testDisney(c, V);
            EXPECT_GT(r.pValue, kAlpha) << "metallic " << c.metallic << ", roughness " << c.roughness
                                        << ", anisotropic " << c.d0.w << ", clearcoat " << c.d1.z << ": "
                                        << r.summary();
        }
}

TEST(DisneySampling, NegativeControlWrongPdfsFail) {
    // Anisotropic GGX with its two widths swapped (the tangent taken for the bitangent), GTR1 with α off by
    // 30 %, and the whole mixture's density with the coat's gloss read wrong.
    const glm::vec2 a(0.5f, 0.1f);
    const Chi2Result swapped =
        testNormals([&](glm::vec2 u) { return sampleGgxAnisoVisibleNormal(kOblique, a.x, a.y, u); },
                    [&](const glm::vec3& h) { return ggxAnisoVisibleNormalPdf(kOblique, h, a.y, a.x); });
    EXPECT_LT(swapped.pValue, kAlpha) << swapped.summary();
    const Chi2Result gtr1 = testNormals([](glm::vec2 u) { return sampleGtr1Normal(u, 0.1f); },
                                        [](const glm::vec3& h) { return gtr1NormalPdf(h.z, 0.13f); });
    EXPECT_LT(gtr1.pValue, kAlpha) << gtr1.summary();
    const DisneyCase coat{1.0f, 0.6f, kD0, glm::vec4(0.0f, 0.5f, 1.0f, 0.0f)};
    const DisneyCase glossy{1.0f, 0.6f, kD0, glm::vec4(0.0f, 0.5f, 1.0f, 0.5f)};
    const Chi2Result mixture = testDisney(coat, kOblique, &glossy);
    EXPECT_LT(mixture.pValue, kAlpha) << mixture.summary();
}

}  // namespace
}  // namespace shadelab::trace
