// The path tracer against closed forms and against itself (design.md §8; pbrt-v4's integrator tests are the
// model): radiance inside a diffuse emitting sphere and inside a sphere lit by a point light (both exactly
// 1), the white furnace, agreement of BSDF-only, light-only and MIS estimators, and direct lighting equal to
// the Whitted tracer (the render's determinism is path_render_test.cpp's). Every comparison is noise-aware
// (standard errors from the render itself) and has a negative control.
#include "scene/environment_load.h"
#include "scene/scene_load.h"
#include "trace/path/path_render.h"
#include "trace/path/path_test_util.h"
#include "trace/trace_image.h"
#include "trace/trace_test_util.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>

namespace shadelab::trace {
namespace {

using test::areaLightScene;
using test::PathRun;
using test::pathRun;
using test::sameBytes;
using test::small;

// The camera at the centre of a sphere of radius 1 looking along −z.
Scene insideSphere(const Material& m) {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fovY = 90.0f;
    scene.background = glm::vec3(0.0f);
    Sphere s;
    s.radius = 1.0f;
    s.material = m;
    scene.spheres.push_back(s);
    return scene;
}

Material diffuse(float albedo, ShadingModel model) {
    Material m = test::plainMaterial(glm::vec3(0.0f), glm::vec3(albedo));
    m.baseColor = glm::vec3(albedo);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    (void)model;
    return m;
}

// The fraction of pixels whose mean is more than 4 standard errors from `expected` (a few in a thousand for
// an unbiased render).
double outliers(const PathRun& r, double expected) {
    int n = 0;
    for (int y = 0; y < r.render->height(); ++y)
        for (int x = 0; x < r.render->width(); ++x) {
            const glm::vec3 m = r.render->mean(x, y), e = r.render->standardError(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(m[c] - expected) > 4.0 * e[c] + 1e-5) {
                    ++n;
                    break;
                }
        }
    return double(n) / double(r.render->width() * r.render->height());
}

// The image mean within ±tolerance of the closed form (the accuracy each case requires) and within 4 standard errors of
// it (noise-aware: tighter as samples grow), and no more than 1 % of the pixels beyond 4 of theirs.
void expectRadiance(const PathRun& r, double expected, double tolerance, const std::string& what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(r.mean[c], expected, tolerance) << what << ", channel " << c;
        EXPECT_NEAR(r.mean[c], expected, 4.0 * r.se[c] + 1e-4) << what << ", channel " << c << " (4 standard errors)";
    }
    EXPECT_LE(outliers(r, expected), 0.01) << what << ": pixels beyond 4 standard errors";
    std::printf("%s: mean %.5f ± %.5f (expected %g)\n", what.c_str(), r.mean.y, r.se.y, expected);
    if (::testing::Test::HasFailure()) test::writeEvidence("path_" + what, r.render->image());
}

// pbrt-v4's "inside a diffuse emitting sphere": L = Le / (1 − ρ) = 0.5 / 0.5 = 1 in every direction.
TEST(PathClosedForm, InsideAnEmittingDiffuseSphereRadianceIsOne) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
        Material m = diffuse(0.5f, model);
        m.emission = glm::vec3(0.5f);
        Scene scene = insideSphere(m);
        scene.model = model;
        scene.terms.specular = false;  // pbr: its Lambert lobe alone (the dielectric layer would reflect 4 %)
        const PathRun r = pathRun(scene, small(12, 12, 256, 64));
        expectRadiance(r, 1.0, 0.025, std::string("emitting_") + toString(model));
    }
}

// A point light of shadelab intensity 1 with 1/d² falloff (pbrt's intensity π: design.md §7's π-scaled
// light) at the centre: direct 0.5, and every bounce halves: L = 1.
TEST(PathClosedForm, InsideASphereLitByAPointLightRadianceIsOne) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
        Scene scene = insideSphere(diffuse(0.5f, model));
        scene.model = model;
        scene.terms.specular = false;
        Light l;
        l.position = glm::vec3(0.0f);
        l.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
        scene.lights.push_back(l);
        const PathRun r = pathRun(scene, small(12, 12, 256, 64));
        expectRadiance(r, 1.0, 0.025, std::string("point_") + toString(model));
    }
}

TEST(PathClosedForm, NegativeControlAnAlbedoOfPointFiveFiveIsNotOne) {
    Material m = diffuse(0.55f, ShadingModel::Phong);
    m.emission = glm::vec3(0.5f);
    Scene scene = insideSphere(m);
    const PathRun r = pathRun(scene, small(12, 12, 256, 64));
    EXPECT_GT(std::abs(r.mean.y - 1.0), 0.05) << "0.5/(1 − 0.55) = 1.11 must not pass as 1";
}

// The white furnace: a convex object of albedo 1 in a uniform environment of radiance 1 vanishes.
Scene furnace(const Material& m, ShadingModel model) {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fovY = 30.0f;
    scene.model = model;
    scene.background = glm::vec3(1.0f);
    Sphere s;
    s.material = m;
    scene.spheres.push_back(s);
    return scene;
}

TEST(PathFurnace, ALambertianSphereOfAlbedoOneVanishes) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
        Scene scene = furnace(diffuse(1.0f, model), model);
        scene.terms.specular = false;
        const PathRun r = pathRun(scene, small(16, 16, 64, 64));
        expectRadiance(r, 1.0, 0.01, std::string("furnace_") + toString(model));
    }
}

// The lecture's Phong is not energy conserving: md + ms = 1 reflects more or less than it receives. The test
// records how much (ctest's XML, and the log) and checks that the furnace sees it.
TEST(PathFurnace, UnnormalisedPhongGainsOrLosesEnergyAndTheFurnaceShowsIt) {
    for (float s : {1.0f, 32.0f}) {
        Material m = test::plainMaterial(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(0.5f), s);
        const PathRun r = pathRun(furnace(m, ShadingModel::Phong), small(16, 16, 128, 64));
        std::printf("furnace, Phong md = ms = 0.5, s = %g: mean %.4f ± %.4f (1 = energy conserved)\n", s, r.mean.y,
                    r.se.y);
        ::testing::Test::RecordProperty("phong_furnace_s" + std::to_string(int(s)), std::to_string(r.mean.y));
        EXPECT_GT(std::abs(r.mean.y - 1.0), 5.0 * r.se.y + 0.01) << "s = " << s;
    }
}

// The mean difference of two renders in units of its standard error.
double zScore(const PathRun& a, const PathRun& b, int channel) {
    return (a.mean[channel] - b.mean[channel]) /
           std::sqrt(a.se[channel] * a.se[channel] + b.se[channel] * b.se[channel]);
}

TEST(PathEstimators, BsdfLightAndMisSamplingConvergeToTheSameImage) {
    const Scene scene = areaLightScene();
    PathSettings s = small(32, 24, 96, 3);
    s.estimator = PathEstimator::Mis;
    const PathRun mis = pathRun(scene, s);
    s.estimator = PathEstimator::Light;
    const PathRun light = pathRun(scene, s);
    s.estimator = PathEstimator::Bsdf;
    s.spp = 384;  // hitting a small lamp by chance is noisy: more samples for the same error
    const PathRun bsdf = pathRun(scene, s);
    for (int c = 0; c < 3; ++c) {
        std::printf("channel %d: mis %.5f ± %.5f, light %.5f ± %.5f, bsdf %.5f ± %.5f\n", c, mis.mean[c], mis.se[c],
                    light.mean[c], light.se[c], bsdf.mean[c], bsdf.se[c]);
        EXPECT_LT(std::abs(zScore(mis, light, c)), 3.0) << "mis vs light, channel " << c;
        EXPECT_LT(std::abs(zScore(mis, bsdf, c)), 3.0) << "mis vs bsdf, channel " << c;
        EXPECT_LT(std::abs(zScore(light, bsdf, c)), 3.0) << "light vs bsdf, channel " << c;
    }
    // MIS is never much noisier than the better of the two.
    EXPECT_LT(mis.se.y, 1.5 * std::min(light.se.y, bsdf.se.y * 2.0));
    if (::testing::Test::HasFailure()) {
        test::writeEvidence("path_estimator_mis", mis.render->image());
        test::writeEvidence("path_estimator_light", light.render->image());
        test::writeEvidence("path_estimator_bsdf", bsdf.render->image());
    }
}

// The same with an .hdr environment as the only light: its importance sampling (light) against the BSDF's.
TEST(PathEstimators, EnvironmentMapSamplingAgreesWithBsdfSampling) {
    Scene scene = areaLightScene();
    scene.spheres.pop_back();  // the lamp
    scene.meshes.clear();      // and the panel: the sky alone
    scene.environment = Environment{};
    scene.environment->hdr = SHADELAB_SOURCE_DIR "/assets/environments/sky.hdr";
    scene.environment->rotation = 40.0f;
    shading::PrefilterSettings p;
    p.size = 32;
    p.samples = 4;
    loadEnvironment(scene, "", p);
    PathSettings s = small(32, 24, 64, 2);
    s.estimator = PathEstimator::Light;
    const PathRun light = pathRun(scene, s);
    s.estimator = PathEstimator::Bsdf;
    const PathRun bsdf = pathRun(scene, s);
    s.estimator = PathEstimator::Mis;
    const PathRun mis = pathRun(scene, s);
    for (int c = 0; c < 3; ++c) {
        std::printf("channel %d: mis %.5f ± %.5f, light %.5f ± %.5f, bsdf %.5f ± %.5f\n", c, mis.mean[c], mis.se[c],
                    light.mean[c], light.se[c], bsdf.mean[c], bsdf.se[c]);
        EXPECT_LT(std::abs(zScore(light, bsdf, c)), 3.0) << "light vs bsdf, channel " << c;
        EXPECT_LT(std::abs(zScore(mis, bsdf, c)), 3.0) << "mis vs bsdf, channel " << c;
    }
    // Negative control: the sky 10 % brighter is told apart (a sky turned about +y is not: the scene's
    // mean light comes mostly from overhead).
    scene.environment->intensity = 1.1f;
    const PathRun brighter = pathRun(scene, s);
    EXPECT_GT(std::abs(zScore(brighter, bsdf, 1)), 3.0);
}

TEST(PathEstimators, NegativeControlALampTwentyPercentBrighterIsSeen) {
    Scene scene = areaLightScene();
    PathSettings s = small(32, 24, 96, 3);
    const PathRun a = pathRun(scene, s);
    scene.spheres[2].material.emission *= 1.2f;
    s.estimator = PathEstimator::Light;
    const PathRun b = pathRun(scene, s);
    EXPECT_GT(std::abs(zScore(a, b, 1)), 3.0) << "the agreement bound must see a 20 % change in one of the two lamps";
}

// Direct lighting under the path tracer is the Whitted tracer's local model without its ambient term. The
// Whitted image is rendered with 8×8 samples per pixel; the path tracer jitters, so pixels agree within
// their noise and the grid's error, and the image means agree within 3 standard errors plus 1e-4.
struct DirectCheck {
    double z = 0.0;
    double badPixels = 0.0;  // fraction of pixels off by more than max(5 SE, 2/255)
};

DirectCheck compareWithWhitted(const Scene& path, const Scene& whitted, int maxDepth) {
    PathSettings s = small(48, 27, 64, maxDepth);
    const PathRun r = pathRun(path, s);
    TraceSettings t;
    t.width = s.width;
    t.height = s.height;
    t.spp = 64;
    t.threads = 2;
    t.maxDepth = maxDepth;
    t.coverage = false;
    const ImageF w = traceImage(whitted, t).color;
    DirectCheck out;
    glm::dvec3 wMean(0.0);
    int bad = 0;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const float* p = w.pixel(x, y);
            const glm::vec3 m = r.render->mean(x, y), e = r.render->standardError(x, y);
            wMean += glm::dvec3(p[0], p[1], p[2]) / double(s.width * s.height);
            for (int c = 0; c < 3; ++c)
                if (std::abs(m[c] - p[c]) > std::max(5.0f * e[c], 2.0f / 255.0f)) {
                    ++bad;
                    break;
                }
        }
    out.badPixels = double(bad) / double(s.width * s.height);
    out.z = std::abs(r.mean.y - wMean.y) / (r.se.y + 1e-4);
    std::printf("path %.5f ± %.5f, whitted %.5f, %.2f%% pixels apart\n", r.mean.y, r.se.y, wMean.y,
                100.0 * out.badPixels);
    if (out.z >= 3.0 || out.badPixels > 0.03) {
        test::writeEvidence("path_direct_path", r.render->image());
        test::writeEvidence("path_direct_whitted", w);
    }
    return out;
}

Scene withoutAmbient(Scene s) {
    s.terms.ambient = false;
    return s;
}

TEST(PathDirect, DirectLightingEqualsTheWhittedTracer) {
    Scene scene = loadScene(SHADELAB_SOURCE_DIR "/assets/scenes/default.json");
    scene.background = glm::vec3(0.0f);
    for (Sphere& s : scene.spheres) s.material.kr = glm::vec3(0.0f);
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
        scene.model = model;
        const DirectCheck d = compareWithWhitted(scene, withoutAmbient(scene), 0);
        EXPECT_LT(d.z, 3.0) << toString(model);
        EXPECT_LT(d.badPixels, 0.03) << toString(model);
    }
}

// One bounce through a mirror: a diffuse sphere and a mirror sphere, nothing else, so no diffuse
// inter-reflection exists and the path tracer's maxDepth 1 is Whitted's depth 1.
TEST(PathDirect, OneMirrorBounceEqualsTheWhittedTracer) {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f, 0.5f, 6.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fovY = 40.0f;
    Sphere matte;
    matte.center = glm::vec3(-1.1f, 0.0f, 0.0f);
    matte.material = test::plainMaterial(glm::vec3(0.0f), glm::vec3(0.8f, 0.3f, 0.2f), glm::vec3(0.3f), 20.0f);
    scene.spheres.push_back(matte);
    Sphere mirror = matte;
    mirror.center = glm::vec3(1.1f, 0.0f, -0.5f);
    mirror.material = test::plainMaterial(glm::vec3(0.0f));
    mirror.material.kr = glm::vec3(0.9f);
    scene.spheres.push_back(mirror);
    Light l;
    l.position = glm::vec3(-3.0f, 4.0f, 5.0f);
    scene.lights.push_back(l);
    const DirectCheck d = compareWithWhitted(scene, withoutAmbient(scene), 1);
    EXPECT_LT(d.z, 3.0);
    EXPECT_LT(d.badPixels, 0.03);
}

// Spot lights under next-event estimation: the default scene lit by one spot whose cone edge crosses the spheres,
// with shadows, equals the Whitted tracer's local model; the outer angle changed in one renderer does not.
Scene spotLitDefault() {
    Scene scene = loadScene(SHADELAB_SOURCE_DIR "/assets/scenes/default.json");
    scene.background = glm::vec3(0.0f);
    for (Sphere& s : scene.spheres) s.material.kr = glm::vec3(0.0f);
    const glm::vec3 target = scene.camera.target;
    Light l;
    l.type = LightType::Spot;
    l.position = target + glm::vec3(-1.0f, 5.0f, 2.0f);
    l.direction = glm::normalize(target - l.position);
    l.innerConeAngle = 0.2f;
    l.outerConeAngle = 0.45f;
    l.range = 12.0f;
    scene.lights = {l};
    scene.terms.shadows = true;
    return scene;
}

TEST(PathDirect, SpotLightEqualsTheWhittedTracer) {
    const Scene scene = spotLitDefault();
    const DirectCheck d = compareWithWhitted(scene, withoutAmbient(scene), 0);
    EXPECT_LT(d.z, 3.0);
    EXPECT_LT(d.badPixels, 0.03);
    Scene wider = withoutAmbient(scene);
    wider.lights[0].outerConeAngle = 0.6f;
    const DirectCheck n = compareWithWhitted(scene, wider, 0);
    EXPECT_GT(n.badPixels, 0.03) << "an outer angle of 0.6 rad against 0.45 went unnoticed";
}

TEST(PathDirect, NegativeControlWhittedWithItsAmbientTermDiffers) {
    Scene scene = loadScene(SHADELAB_SOURCE_DIR "/assets/scenes/default.json");
    scene.background = glm::vec3(0.0f);
    for (Sphere& s : scene.spheres) s.material.kr = glm::vec3(0.0f);
    const DirectCheck d = compareWithWhitted(scene, scene, 0);
    EXPECT_GT(d.z, 3.0);
    EXPECT_GT(d.badPixels, 0.03);
}

}  // namespace
}  // namespace shadelab::trace
