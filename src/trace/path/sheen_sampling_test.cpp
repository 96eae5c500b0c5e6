// χ² test of PathBsdf's mixture under glTF's sheen (pbr's diffuse and GGX lobes, the sheen's Charlie fibre
// normals, and with a clear coat over them), through sample() and pdf(), as clearcoat_sampling_test.cpp does for
// the coat; its negative control claims the density of fibres rougher than those sampled.
#include "shading/local_illumination.h"
#include "trace/path/chi2_test_util.h"
#include "trace/path/path_bsdf.h"

#include <gtest/gtest.h>

namespace shadelab::trace {
namespace {

using test::Chi2Result;

constexpr double kAlpha = test::kChi2Alpha;

constexpr uint32_t kSeed = 2613u;  // this file's stream of numbers

struct SheenCase {
    float metallic, roughness;
    glm::vec4 sheen;      // (colour, roughness)
    float coat = 0.0f;    // a clear coat of roughness 0.2 over it
    bool diffuse = true;  // the diffuse term (the sheen's) on
};

// The BSDF on the plane z = 0 seen from V under pbr with the case's sheen.
PathBsdf makeSheened(Material& m, Surface& s, const glm::vec3& V, const SheenCase& c) {
    m.baseColor = glm::vec3(0.2f, 0.1f, 0.3f);
    m.metallic = c.metallic;
    m.roughness = c.roughness;
    s.material = &m;
    s.N = s.Nf = glm::vec3(0.0f, 0.0f, 1.0f);
    shading::SurfaceParams p =
        shading::surfaceParams(shading::SL_MODEL_PBR, m.ma, m.md, m.ms, m.s, m.baseColor, c.metallic, c.roughness);
    shading::SheenLookup table{&shading::sheenLut()};
    p.sheen = c.sheen;
    p.sheenTable = table.lut;
    p.sheenEV = table.at(V.z, c.sheen.w);
    p.coat = glm::vec2(c.coat, 0.2f);
    p.coatN = s.N;
    BsdfTerms terms;
    terms.diffuse = c.diffuse;
    return PathBsdf(s, p, V, shading::SL_MODEL_PBR, terms);
}

Chi2Result testSheened(const SheenCase& c, const glm::vec3& V, const SheenCase* claimedCase = nullptr) {
    Material m, m2;
    Surface s, s2;
    const PathBsdf bsdf = makeSheened(m, s, V, c);
    const PathBsdf claimed = makeSheened(m2, s2, V, claimedCase ? *claimedCase : c);
    return test::chi2OfMixture(bsdf, claimed, kSeed, 96);
}

const glm::vec3 kUp(0.0f, 0.0f, 1.0f);
const glm::vec3 kOblique = glm::normalize(glm::vec3(0.5f, 0.2f, 0.6f));
const glm::vec3 kGrazing = glm::normalize(glm::vec3(0.9f, 0.0f, 0.25f));

TEST(SheenSampling, TheMixtureMatchesItsPdf) {
    const SheenCase cases[] = {
        {0.0f, 0.6f, {1.0f, 1.0f, 1.0f, 0.3f}},               // white velvet over a dark matte
        {0.0f, 0.8f, {0.8f, 0.5f, 0.9f, 0.8f}},               // a rough tinted sheen
        {0.0f, 0.5f, {1.0f, 1.0f, 1.0f, 0.07f}},              // the narrowest fibres
        {1.0f, 0.4f, {0.5f, 0.5f, 0.5f, 0.5f}},               // sheen over a metal
        {0.0f, 0.6f, {1.0f, 1.0f, 1.0f, 0.4f}, 1.0f},         // under a clear coat
        {0.0f, 0.6f, {1.0f, 1.0f, 1.0f, 0.4f}, 0.0f, false},  // the diffuse term off: the sheen too
    };
    for (const SheenCase& c : cases)
        for (glm::vec3 V : {kOblique, kUp, kGrazing}) {
            const Chi2Result r = testSheened(c, V);
            EXPECT_GT(r.pValue, kAlpha) << "V.z " << V.z << ", metallic " << c.metallic << ", sheen roughness "
                                        << c.sheen.w << ", coat " << c.coat << ": " << r.summary();
        }
}

TEST(SheenSampling, NegativeControlWrongSheenPdfFails) {
    const SheenCase sampled{0.0f, 0.6f, {1.0f, 1.0f, 1.0f, 0.3f}};
    const SheenCase rougher{0.0f, 0.6f, {1.0f, 1.0f, 1.0f, 0.4f}};
    const Chi2Result r = testSheened(sampled, kGrazing, &rougher);
    EXPECT_LT(r.pValue, kAlpha) << r.summary();
}

}  // namespace
}  // namespace shadelab::trace
