// χ² test of PathBsdf's mixture under glTF's clear coat (pbr's diffuse, its GGX lobe and the coat's GGX lobe
// around the coat's own normal), with glTF's specular layer (its picking probabilities) and with its anisotropy (the
// GGX lobe stretched along a turned direction, sampled by its visible normals in that frame), through sample() and
// pdf(), as disney_sampling_test.cpp does for disney; its negative control claims the density of a coat rougher than
// the one sampled. A glossy coat's lobe is a few thousandths of cos θ wide: each bin's expected count is integrated on
// a 96² grid.
#include "shading/local_illumination.h"
#include "trace/path/chi2_test_util.h"
#include "trace/path/path_bsdf.h"

#include <gtest/gtest.h>

namespace shadelab::trace {
namespace {

using test::Chi2Result;

constexpr double kAlpha = test::kChi2Alpha;

constexpr uint32_t kSeed = 2612u;  // this file's stream of numbers

struct CoatCase {
    float metallic, roughness;
    glm::vec2 coat;
    glm::vec3 coatN;        // the coat's normal (the base's is +z)
    glm::vec4 layer{0.0f};  // glTF's specular layer (f0d, weight); none here when the weight is 0
    glm::vec3 aniso{0.0f};  // glTF's anisotropy (Anisotropy::packed), with the layer (the layered function)
};

// The BSDF on the plane z = 0 seen from V under pbr with the case's coat.
PathBsdf makeCoated(Material& m, Surface& s, const glm::vec3& V, const CoatCase& c) {
    m.baseColor = glm::vec3(0.5f, 0.1f, 0.05f);
    m.metallic = c.metallic;
    m.roughness = c.roughness;
    s.material = &m;
    s.N = s.Nf = glm::vec3(0.0f, 0.0f, 1.0f);
    shading::SurfaceParams p =
        shading::surfaceParams(shading::SL_MODEL_PBR, m.ma, m.md, m.ms, m.s, m.baseColor, c.metallic, c.roughness);
    p.coat = c.coat;
    p.coatN = c.coatN;
    if (c.layer.w > 0.0f) {
        p.layered = true;
        p.specLayer = c.layer;
        p.aniso = glm::vec4(shading::anisotropyDirection(s.N, glm::vec4(0.0f), c.aniso), c.aniso.x);
        p.baseColor = m.baseColor;
        p.metallic = c.metallic;
        p.ms = shading::pbrSpecularF0(m.baseColor, c.metallic, c.layer);
    }
    return PathBsdf(s, p, V, shading::SL_MODEL_PBR, BsdfTerms{});
}

Chi2Result testCoated(const CoatCase& c, const glm::vec3& V, const CoatCase* claimedCase = nullptr) {
    Material m, m2;
    Surface s, s2;
    const PathBsdf bsdf = makeCoated(m, s, V, c);
    const PathBsdf claimed = makeCoated(m2, s2, V, claimedCase ? *claimedCase : c);
    return test::chi2OfMixture(bsdf, claimed, kSeed, 96);
}

const glm::vec3 kUp(0.0f, 0.0f, 1.0f);
const glm::vec3 kOblique = glm::normalize(glm::vec3(0.5f, 0.2f, 0.6f));
const glm::vec3 kTilted = glm::normalize(glm::vec3(0.2f, -0.1f, 1.0f));

// Each coat seen obliquely, and the rougher ones also head-on: a gloss coat's lobe seen head-on sits inside the
// pole's first sub-cell of cos θ, where the bins' integration cannot resolve it.
TEST(ClearcoatSampling, TheMixtureMatchesItsPdf) {
    struct Seen {
        CoatCase coat;
        bool headOn;
    };
    const Seen cases[] = {
        {{0.0f, 0.5f, {1.0f, 0.1f}, kUp}, false},                              // a gloss coat over plastic
        {{0.0f, 0.3f, {0.5f, 0.5f}, kUp}, true},                               // half a rough coat
        {{1.0f, 0.6f, {1.0f, 0.3f}, kUp}, true},                               // a coat over a rough metal
        {{0.0f, 0.5f, {1.0f, 0.15f}, kTilted}, false},                         // a coat normal map's tilt
        {{0.3f, 0.4f, {0.0f, 0.0f}, kUp, {0.15f, 0.1f, 0.05f, 0.6f}}, true},   // glTF's specular layer alone
        {{0.0f, 0.4f, {1.0f, 0.3f}, kUp, {0.02f, 0.02f, 0.02f, 0.5f}}, true},  // the layer under a coat
        {{1.0f, 0.4f, {0.0f, 0.0f}, kUp, {0.04f, 0.04f, 0.04f, 1.0f}, Anisotropy{0.8f, 0.4f}.packed()}, true},
        {{0.0f, 0.3f, {0.0f, 0.0f}, kUp, {0.04f, 0.04f, 0.04f, 1.0f}, Anisotropy{1.0f, -1.2f}.packed()}, true},
    };
    for (const Seen& k : cases)
        for (glm::vec3 V : {kOblique, kUp}) {
            if (V == kUp && !k.headOn) continue;
            const CoatCase& c = k.coat;
            const Chi2Result r = testCoated(c, V);
            EXPECT_GT(r.pValue, kAlpha) << "V.z " << V.z << ", metallic " << c.metallic << ", coat " << c.coat.x
                                        << " rough " << c.coat.y << ": " << r.summary();
        }
}

// glTF's anisotropy: the stretched lobe's density claimed with its direction turned by 0.3 rad is noticed.
TEST(ClearcoatSampling, NegativeControlTurnedAnisotropyPdfFails) {
    const CoatCase sampled{1.0f, 0.4f, {0.0f, 0.0f}, kUp, {0.04f, 0.04f, 0.04f, 1.0f}, Anisotropy{0.8f, 0.4f}.packed()};
    const CoatCase turned{1.0f, 0.4f, {0.0f, 0.0f}, kUp, {0.04f, 0.04f, 0.04f, 1.0f}, Anisotropy{0.8f, 0.7f}.packed()};
    const Chi2Result r = testCoated(sampled, kOblique, &turned);
    EXPECT_LT(r.pValue, kAlpha) << r.summary();
}

TEST(ClearcoatSampling, NegativeControlWrongCoatPdfFails) {
    const CoatCase sampled{1.0f, 0.6f, {1.0f, 0.1f}, kUp};
    const CoatCase rougher{1.0f, 0.6f, {1.0f, 0.13f}, kUp};
    const Chi2Result r = testCoated(sampled, kOblique, &rougher);
    EXPECT_LT(r.pValue, kAlpha) << r.summary();
}

}  // namespace
}  // namespace shadelab::trace
