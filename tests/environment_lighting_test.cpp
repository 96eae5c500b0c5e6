// Image-based lighting of pbr surfaces, raster against reference: one sphere per case in the
// shipped sky (assets/environments/sky.hdr) over roughness × metallic × {environment only, + a light,
// + energy compensation}, and in a uniform environment, gated as in design.md §4 with negative controls
// (roughness +10 %, metallic flipped). The furnace: a white sphere in a uniform environment of radiance 1
// vanishes into it (within 2/255 in the interior, in floats, both renderers), with controls that must not.
// Failures leave images, heatmaps and reports in build/test-output/environment_lighting_test/.
#include "gl_fixture.h"
#include "raster/raster_renderer.h"
#include "render_compare.h"
#include "scene/coverage.h"
#include "scene/environment_load.h"
#include "trace/trace_image.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 192, kHeight = 128;

const std::shared_ptr<const shading::PrefilteredEnvironment>& skyMap() {
    static const auto map = loadPrefilteredHdr(test::sourcePath("assets/environments/sky.hdr"));
    return map;
}

enum class Lighting { Environment, PlusLight, Compensated, Uniform };

struct Case {
    float roughness;
    float metallic;
    Lighting lighting;
};

std::string caseName(const Case& c) {
    const char* l = c.lighting == Lighting::Environment   ? "env"
                    : c.lighting == Lighting::PlusLight   ? "env_light"
                    : c.lighting == Lighting::Compensated ? "env_compensated"
                                                          : "uniform";
    return std::string(l) + "_r" + std::to_string(int(std::lround(c.roughness * 100))) + "_m" +
           std::to_string(int(c.metallic));
}

Scene makeScene(const Case& c) {
    Scene scene;
    scene.camera.position = {0.0f, 0.8f, 3.6f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fovY = 40.0f;
    scene.model = ShadingModel::Pbr;
    scene.background = glm::vec3(0.4f, 0.45f, 0.5f);
    Environment env;
    if (c.lighting != Lighting::Uniform) {
        env.hdr = "sky.hdr";
        env.map = skyMap();
        env.rotation = 30.0f;
    }
    scene.environment = env;
    scene.energyCompensation = c.lighting == Lighting::Compensated;
    Material m;
    m.baseColor = c.metallic > 0.5f ? glm::vec3(0.95f, 0.64f, 0.54f) : glm::vec3(0.7f, 0.15f, 0.1f);
    m.metallic = c.metallic;
    m.roughness = c.roughness;
    scene.spheres.push_back({"", glm::vec3(0.0f), 1.0f, m});
    if (c.lighting == Lighting::PlusLight)
        scene.lights.push_back(test::pointLight({-3.0f, 4.0f, 3.0f}, glm::vec3(2.0f)));
    return scene;
}

CompareResult compareRenders(const Scene& rasterScene, const Scene& tracedScene, const std::string& name) {
    return test::gateWithEvidence(test::rasterizeWithCoverage(rasterScene, kWidth, kHeight),
                                  test::traceWithCoverage(tracedScene, kWidth, kHeight), CompareGates{}, name);
}

std::vector<Case> allCases() {
    std::vector<Case> cases;
    for (Lighting l : {Lighting::Environment, Lighting::PlusLight, Lighting::Compensated, Lighting::Uniform})
        for (float metallic : {0.0f, 1.0f})
            for (float roughness : {0.05f, 0.3f, 0.6f, 1.0f}) cases.push_back({roughness, metallic, l});
    return cases;
}

}  // namespace

class EnvironmentMatrix : public test::GlTest, public ::testing::WithParamInterface<Case> {};

TEST_P(EnvironmentMatrix, RasterMatchesReference) {
    const Scene scene = makeScene(GetParam());
    CompareResult r = compareRenders(scene, scene, caseName(GetParam()));
    EXPECT_TRUE(r.pass) << compareSummary(r);
}

INSTANTIATE_TEST_SUITE_P(RoughnessMetallic, EnvironmentMatrix, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& p) { return caseName(p.param); });

class EnvironmentNegativeControls : public test::GlTest {};

TEST_F(EnvironmentNegativeControls, RoughnessTenPercentOffFails) {
    for (float metallic : {0.0f, 1.0f}) {
        const Case c{0.5f, metallic, Lighting::Environment};
        Scene a = makeScene(c), b = makeScene(c);
        b.spheres[0].material.roughness *= 1.1f;
        CompareResult r = compareRenders(a, b, "negative_roughness_m" + std::to_string(int(metallic)));
        EXPECT_FALSE(r.pass) << "a 10% roughness change passed the gates:\n" << compareSummary(r);
    }
}

TEST_F(EnvironmentNegativeControls, MetallicFlippedFails) {
    const Case c{0.3f, 0.0f, Lighting::Environment};
    Scene a = makeScene(c), b = makeScene(c);
    b.spheres[0].material.metallic = 1.0f;
    CompareResult r = compareRenders(a, b, "negative_metallic");
    EXPECT_FALSE(r.pass) << "flipping metallic passed the gates:\n" << compareSummary(r);
}

TEST_F(EnvironmentNegativeControls, CompensationInOneRendererOnlyFails) {
    const Case c{1.0f, 1.0f, Lighting::Environment};
    Scene a = makeScene(c), b = makeScene(c);
    b.energyCompensation = true;
    CompareResult r = compareRenders(a, b, "negative_compensation");
    EXPECT_FALSE(r.pass) << "energy compensation in one renderer passed the gates:\n" << compareSummary(r);
}

// ---- The white furnace --------------------------------------------------------------------------------

namespace {

struct FurnaceResult {
    float maxError = 0.0f;  // largest |I − 1| over the interior's pixels and channels, linear
    int interior = 0;
};

// The sphere's interior: covered by it, with its whole 3×3 neighbourhood (design.md §4's masks).
FurnaceResult furnaceError(const ImageF& img, const std::vector<uint32_t>& coverage, const std::string& name) {
    FurnaceResult r;
    for (int y = 1; y + 1 < img.height; ++y)
        for (int x = 1; x + 1 < img.width; ++x) {
            bool inside = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    inside = inside && coverage[size_t(y + dy) * size_t(img.width) + size_t(x + dx)] != kBackgroundId;
            if (!inside) continue;
            ++r.interior;
            for (int k = 0; k < 3; ++k) r.maxError = std::max(r.maxError, std::abs(img.pixel(x, y)[k] - 1.0f));
        }
    std::printf("%s: %d interior pixels, max |I - 1| = %.5f (%.2f/255)\n", name.c_str(), r.interior, r.maxError,
                r.maxError * 255.0f);
    return r;
}

Scene furnaceScene(float roughness, float metallic, glm::vec3 baseColor, bool compensation, bool specular) {
    Scene scene;
    scene.camera.position = {0.0f, 0.0f, 3.5f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.model = ShadingModel::Pbr;
    scene.background = glm::vec3(1.0f);
    scene.environment = Environment{};
    scene.energyCompensation = compensation;
    scene.terms.specular = specular;
    Material m;
    m.baseColor = baseColor;
    m.metallic = metallic;
    m.roughness = roughness;
    scene.spheres.push_back({"", glm::vec3(0.0f), 1.0f, m});
    return scene;
}

// Both renderers' worst interior error for one furnace scene.
float furnaceBoth(const Scene& scene, const std::string& name) {
    raster::RasterRenderer& r = test::sharedRasterRenderer();
    r.uploadMeshes(scene);
    const raster::RasterOutput raster = raster::renderRaster(r, scene, kWidth, kHeight, true);
    trace::TraceSettings s;
    s.width = kWidth;
    s.height = kHeight;
    s.coverage = true;
    const trace::TraceOutput traced = trace::traceImage(scene, s);
    const FurnaceResult a = furnaceError(raster.color, raster.coverage, name + " raster");
    const FurnaceResult b = furnaceError(traced.color, traced.coverage, name + " trace");
    EXPECT_GT(a.interior, 5000);
    EXPECT_GT(b.interior, 5000);
    return std::max(a.maxError, b.maxError);
}

constexpr float kFurnaceTolerance = 2.0f / 255.0f;

}  // namespace

class Furnace : public test::GlTest {};

TEST_F(Furnace, WhiteLambertVanishes) {
    EXPECT_LE(furnaceBoth(furnaceScene(0.5f, 0.0f, glm::vec3(1.0f), false, false), "furnace_lambert"),
              kFurnaceTolerance);
}

TEST_F(Furnace, WhiteDielectricWithItsSpecularLayerVanishes) {
    for (float roughness : {0.1f, 0.5f, 1.0f})
        EXPECT_LE(furnaceBoth(furnaceScene(roughness, 0.0f, glm::vec3(1.0f), false, true),
                              "furnace_dielectric_r" + std::to_string(int(roughness * 100))),
                  kFurnaceTolerance);
}

TEST_F(Furnace, WhiteMetalWithCompensationVanishes) {
    for (float roughness : {0.1f, 0.5f, 1.0f})
        EXPECT_LE(furnaceBoth(furnaceScene(roughness, 1.0f, glm::vec3(1.0f), true, true),
                              "furnace_metal_compensated_r" + std::to_string(int(roughness * 100))),
                  kFurnaceTolerance);
}

// Negative controls: single-scattering GGX loses energy at high roughness, and an albedo of 0.9 is visible.
TEST_F(Furnace, NegativeControlsShow) {
    EXPECT_GT(furnaceBoth(furnaceScene(1.0f, 1.0f, glm::vec3(1.0f), false, true), "furnace_metal_uncompensated"),
              kFurnaceTolerance);
    EXPECT_GT(furnaceBoth(furnaceScene(0.5f, 0.0f, glm::vec3(0.9f), false, false), "furnace_albedo_0.9"),
              kFurnaceTolerance);
}
