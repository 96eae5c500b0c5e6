// glTF's transmission and volume in the tracers: the path tracer's mixture with a thin wall's transmitted lobe
// against its pdf over the whole sphere (χ², with a wrong-width control); Beer–Lambert through a glass ball's
// centre against its closed form c^(2R/D) in the Whitted tracer and the path tracer (the rasterizer's thickness
// as control); a clear glass ball vanishes in the white furnace, an absorbing one does not.
#include "shading/local_illumination.h"
#include "trace/integrator.h"
#include "trace/path/chi2_test_util.h"
#include "trace/path/path_bsdf.h"
#include "trace/path/path_test_util.h"
#include "trace/pbr_layers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace shadelab::trace {
namespace {

using test::Chi2Result;

constexpr double kAlpha = test::kChi2Alpha;
constexpr uint32_t kSeed = 2614u;  // this file's stream of numbers

struct ThinCase {
    float factor, roughness, ior, metallic;
    bool specular = true;
};

// The BSDF of a thin transmitting wall on the plane z = 0 seen from V, its layers set as the tracers set them.
PathBsdf makeThin(Material& m, Surface& s, const glm::vec3& V, const ThinCase& c) {
    m.baseColor = glm::vec3(0.8f, 0.7f, 0.6f);
    m.metallic = c.metallic;
    m.roughness = c.roughness;
    m.ior = c.ior;
    m.transmission.factor = c.factor;
    s.material = &m;
    s.model = shading::SL_MODEL_PBR;
    s.N = s.Nf = glm::vec3(0.0f, 0.0f, 1.0f);
    s.baseColor = m.baseColor;
    s.metallic = m.metallic;
    s.roughness = m.roughness;
    shading::SurfaceParams p =
        shading::surfaceParams(shading::SL_MODEL_PBR, m.ma, m.md, m.ms, m.s, m.baseColor, c.metallic, c.roughness);
    setPbrLayers(p, s, V);
    BsdfTerms terms;
    terms.specular = c.specular;
    return PathBsdf(s, p, V, shading::SL_MODEL_PBR, terms);
}

Chi2Result testThin(const ThinCase& c, const glm::vec3& V, const ThinCase* claimedCase = nullptr) {
    Material m, m2;
    Surface s, s2;
    const PathBsdf bsdf = makeThin(m, s, V, c);
    const PathBsdf claimed = makeThin(m2, s2, V, claimedCase ? *claimedCase : c);
    EXPECT_TRUE(bsdf.transmits());
    return test::chi2OfMixture(bsdf, claimed, kSeed, 96, true);
}

const glm::vec3 kUp(0.0f, 0.0f, 1.0f);
const glm::vec3 kOblique = glm::normalize(glm::vec3(0.5f, 0.2f, 0.6f));
const glm::vec3 kGrazing = glm::normalize(glm::vec3(0.9f, 0.0f, 0.25f));

TEST(TransmissionSampling, TheThinWallsMixtureMatchesItsPdfOverTheSphere) {
    const ThinCase cases[] = {
        {1.0f, 0.5f, 1.5f, 0.0f},         // all of the diffuse through, a moderate lobe
        {0.5f, 0.3f, 1.5f, 0.0f},         // half through, a narrow lobe
        {0.8f, 0.9f, 1.5f, 0.5f},         // rough, half metal
        {1.0f, 0.6f, 1.2f, 0.0f},         // an index near 1: the lobe narrowed by 0.4
        {1.0f, 0.5f, 1.5f, 0.0f, false},  // the specular term off: diffuse and transmitted lobes alone
    };
    for (const ThinCase& c : cases)
        for (glm::vec3 V : {kOblique, kUp, kGrazing}) {
            const Chi2Result r = testThin(c, V);
            EXPECT_GT(r.pValue, kAlpha) << "V.z " << V.z << ", factor " << c.factor << ", roughness " << c.roughness
                                        << ", ior " << c.ior << ": " << r.summary();
        }
}

TEST(TransmissionSampling, NegativeControlAWiderTransmittedLobeFails) {
    const ThinCase sampled{1.0f, 0.4f, 1.5f, 0.0f};
    const ThinCase wider{1.0f, 0.45f, 1.5f, 0.0f};
    const Chi2Result r = testThin(sampled, kOblique, &wider);
    EXPECT_LT(r.pValue, kAlpha) << r.summary();
}

// A glass ball of radius 1 at the origin in a uniform environment of radiance 1, seen head on through its centre:
// white, all of its diffuse transmitted, smooth, absorbing toward `color` over `distance`.
Scene glassBall(const glm::vec3& color, float distance, float thickness) {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fovY = 0.2f;  // every pixel within 0.01 of the centre: paths 2R long to 1e-4
    scene.model = ShadingModel::Pbr;
    scene.background = glm::vec3(1.0f);
    scene.environment = Environment{};
    scene.terms.specular = false;  // nothing reflected away: the light through is the whole picture
    scene.maxDepth = 8;
    Sphere s;
    s.material.baseColor = glm::vec3(1.0f);
    s.material.metallic = 0.0f;
    s.material.roughness = 0.0f;
    s.material.transmission.factor = 1.0f;
    s.material.volume.thickness = thickness;
    s.material.volume.attenuationDistance = distance;
    s.material.volume.attenuationColor = color;
    scene.spheres.push_back(s);
    return scene;
}

const glm::vec3 kGreen(0.3f, 0.8f, 0.5f);

glm::vec3 centre(const Scene& scene) {
    const TraceScene traced(scene);
    const WhittedIntegrator whitted(traced, scene.maxDepth);
    return whitted.radiance(Ray{scene.camera.position, glm::vec3(0.0f, 0.0f, -1.0f)}, 0);
}

// Beer–Lambert: the light through the centre keeps c^(2R/D) of each colour, in both tracers; the rasterizer's
// reading of the same ball, over its thickness (1, not the 2 the ray travels), does not (negative control).
TEST(TransmissionVolume, BeerLambertThroughTheCentreMatchesTheClosedForm) {
    const float D = 1.5f;
    const Scene scene = glassBall(kGreen, D, 1.0f);
    const glm::vec3 expected(std::pow(kGreen.x, 2.0f / D), std::pow(kGreen.y, 2.0f / D), std::pow(kGreen.z, 2.0f / D));
    const glm::vec3 whitted = centre(scene);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(whitted[c], expected[c], 1e-4f) << "Whitted, channel " << c;
    const test::PathRun r = test::pathRun(scene, test::small(8, 8, 16, 8));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.mean[c], expected[c], 2e-3) << "path, channel " << c;
    std::printf(
        "Beer-Lambert through the centre: expected (%.5f %.5f %.5f), Whitted (%.5f %.5f %.5f), path (%.5f "
        "%.5f %.5f)\n",
        expected.x, expected.y, expected.z, whitted.x, whitted.y, whitted.z, r.mean.x, r.mean.y, r.mean.z);
    if (::testing::Test::HasFailure()) test::writeEvidence("transmission_beer_lambert", r.render->image());

    // The rasterizer's approximation (no ray traced: reflections off) absorbs over the thickness alone.
    Scene local = scene;
    local.terms.reflections = false;
    const glm::vec3 approx = centre(local);
    EXPECT_NEAR(approx.y, std::pow(kGreen.y, 1.0f / D), 1e-4f);
    EXPECT_GT(std::abs(approx.y - expected.y), 0.05f) << "the thickness's tint passed for the path's";
}

// A factor of 0 is pbr exactly, whatever the volume says: the same colours bit for bit in the Whitted tracer and the
// path tracer as the ball with no transmission and no volume; a factor of 0.1 differs (control).
TEST(TransmissionVolume, AFactorOfZeroIsPbrExactly) {
    Scene zero = glassBall(kGreen, 0.5f, 2.0f);
    zero.terms.specular = true;
    zero.camera.fovY = 40.0f;
    zero.spheres[0].material.baseColor = glm::vec3(0.6f, 0.3f, 0.2f);
    zero.spheres[0].material.roughness = 0.4f;
    zero.spheres[0].material.transmission.factor = 0.0f;
    Scene plain = zero;
    plain.spheres[0].material.volume = Volume{};
    Scene some = zero;
    some.spheres[0].material.transmission.factor = 0.1f;
    const TraceScene tz(zero), tp(plain), ts(some);
    const WhittedIntegrator wz(tz, 8), wp(tp, 8), ws(ts, 8);
    for (const glm::vec3& d : {glm::vec3(0.0f, 0.0f, -1.0f), glm::normalize(glm::vec3(0.2f, 0.1f, -1.0f))}) {
        const Ray ray{zero.camera.position, d};
        const glm::vec3 a = wz.radiance(ray, 0);
        EXPECT_EQ(a, wp.radiance(ray, 0));
        EXPECT_NE(a, ws.radiance(ray, 0)) << "control: a factor of 0.1";
    }
    const test::PathRun a = test::pathRun(zero, test::small(8, 8, 4, 4));
    const test::PathRun b = test::pathRun(plain, test::small(8, 8, 4, 4));
    EXPECT_EQ(a.mean, b.mean);
}

// The white furnace: a clear ball (white, smooth, nothing absorbed) sends on all the light it takes, reflected or
// through, and vanishes against a uniform environment; an absorbing one (negative control) does not.
TEST(TransmissionVolume, AClearGlassBallVanishesInTheFurnace) {
    Scene clear = glassBall(glm::vec3(1.0f), INFINITY, 2.0f);
    clear.terms.specular = true;
    clear.camera.fovY = 30.0f;
    clear.maxDepth = 32;
    const test::PathRun r = test::pathRun(clear, test::small(16, 16, 64, 32));
    std::printf("furnace, clear glass ball: mean %.5f ± %.5f (1 = nothing lost)\n", r.mean.y, r.se.y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.mean[c], 1.0, 0.01) << "channel " << c;
    if (::testing::Test::HasFailure()) test::writeEvidence("transmission_furnace", r.render->image());

    Scene tinted = clear;
    tinted.spheres[0].material.volume.attenuationColor = kGreen;
    tinted.spheres[0].material.volume.attenuationDistance = 2.0f;
    const test::PathRun t = test::pathRun(tinted, test::small(16, 16, 64, 32));
    EXPECT_LT(t.mean.x, 0.9) << "an absorbing ball vanished in the furnace";
}

}  // namespace
}  // namespace shadelab::trace
