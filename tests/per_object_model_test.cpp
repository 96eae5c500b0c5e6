// Per-object shading models (Material::model): a scene whose four spheres name Phong, Blinn-Phong, pbr and disney
// renders each sphere exactly as a render of the whole scene under that model does, in the rasterizer, the Whitted
// tracer and the path tracer's direct light; and the model survives a scene file. Negative control: a sphere under
// another model than the scene-wide render's differs there. Failures leave both images behind.
#include "compare/compare_report.h"
#include "gl_fixture.h"
#include "image/png.h"
#include "render_compare.h"
#include "scene/coverage.h"
#include "scene/scene_json.h"
#include "test_output.h"
#include "trace/path/path_render.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 200, kHeight = 120;
constexpr ShadingModel kModels[] = {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr,
                                    ShadingModel::Disney};
constexpr int kSpheres = 4;

// Four spheres apart on a checkered floor, lit by two lights with shadows; sphere i names kModels[i]. The floor
// names Phong itself, so that it is the same in every render and only the spheres change.
Scene mixedScene() {
    Scene scene = test::comparisonStage();
    scene.model = ShadingModel::Pbr;  // what no object uses: every object names its own
    scene.terms = Terms{true, true, true, true, false};
    Plane floor;
    floor.material = test::colourMaterial(glm::vec3(0.7f));
    floor.checker = Checker{glm::vec3(0.3f, 0.35f, 0.4f), 0.75f};
    floor.material.model = ShadingModel::Phong;
    scene.planes.push_back(floor);
    const char* names[] = {"phong", "blinn", "pbr", "disney"};
    for (int i = 0; i < kSpheres; ++i) {
        Material m = test::colourMaterial({0.8f - 0.2f * float(i), 0.3f, 0.2f + 0.2f * float(i)}, 24.0f);
        m.baseColor = {1.0f, 0.77f, 0.34f};
        m.metallic = i == 2 ? 1.0f : 0.0f;
        m.roughness = 0.35f;
        m.disney = {0.3f, 0.6f, 0.2f, 0.5f, 0.5f, 0.5f, 0.6f, 0.8f};  // every lobe on: all of them compared
        m.model = kModels[i];
        scene.spheres.push_back({names[i], {-1.8f + 1.2f * float(i), 0.5f, 0.0f}, 0.5f, m});
    }
    scene.lights.push_back(test::pointLight({-3.0f, 5.0f, 4.0f}, glm::vec3(0.9f)));
    scene.lights.push_back(test::pointLight({3.0f, 3.0f, 2.0f}, glm::vec3(0.4f, 0.4f, 0.5f)));
    return scene;
}

// The mixed scene with every sphere under `model`, as a scene-wide render of that model shades them.
Scene sceneWide(ShadingModel model) {
    Scene scene = mixedScene();
    scene.model = model;
    for (Sphere& s : scene.spheres) s.material.model.reset();
    return scene;
}

// Pixels of sphere `i` (by `coverage`) where a and b differ; on any, both images are written under `name`.
int differingPixels(const Image8& a, const Image8& b, const std::vector<uint32_t>& coverage, uint32_t id,
                    const std::string& name) {
    int differ = 0, covered = 0;
    for (size_t p = 0; p < coverage.size(); ++p) {
        if (coverage[p] != id) continue;
        ++covered;
        if (std::memcmp(&a.data[p * 3], &b.data[p * 3], 3) != 0) ++differ;
    }
    EXPECT_GT(covered, 500) << name << ": the sphere covers too few pixels to tell";
    if (differ > 0) {
        writePng(test::outputPath(name + "_mixed.png"), a);
        writePng(test::outputPath(name + "_scene_wide.png"), b);
        std::printf("%s: %d of %d pixels differ; images in %s_*.png\n", name.c_str(), differ, covered,
                    test::outputPath(name).c_str());
    }
    return differ;
}

// The path tracer's direct light at 4 samples per pixel, as 8-bit sRGB.
Image8 pathDirect(const Scene& scene) {
    trace::PathSettings s;
    s.width = kWidth;
    s.height = kHeight;
    s.spp = 4;
    s.threads = 2;
    s.part = trace::PathPart::Direct;
    trace::PathRender render(std::make_shared<const trace::TraceScene>(scene), s);
    render.addSamples(s.spp);
    ImageF image(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 m = render.mean(x, y);
            float* p = image.pixel(x, y);
            p[0] = m.x, p[1] = m.y, p[2] = m.z, p[3] = 1.0f;
        }
    return toImage8(image, Encoding::Srgb, DisplaySettings{}, nullptr);
}

}  // namespace

TEST(PerObjectModel, TheTracerShadesEachSphereAsTheSceneWideRenderOfItsModel) {
    const Rendered mixed = test::traceWithCoverage(mixedScene(), kWidth, kHeight);
    for (int i = 0; i < kSpheres; ++i) {
        const Scene wide = sceneWide(kModels[i]);
        const Rendered r = test::traceWithCoverage(wide, kWidth, kHeight);
        const uint32_t id = sphereCoverageId(wide, size_t(i));
        EXPECT_EQ(differingPixels(mixed.pixels, r.pixels, mixed.coverage, id,
                                  std::string("per_object_trace_") + toString(kModels[i])),
                  0);
    }
    // Negative control: the Phong sphere is not what a scene-wide pbr render gives.
    const Scene pbr = sceneWide(ShadingModel::Pbr);
    const Rendered r = test::traceWithCoverage(pbr, kWidth, kHeight);
    EXPECT_GT(differingPixels(mixed.pixels, r.pixels, mixed.coverage, sphereCoverageId(pbr, 0), "per_object_negative"),
              500);
}

TEST(PerObjectModel, ThePathTracersDirectLightIsTheSceneWideRenderOfEachModel) {
    const Scene scene = mixedScene();
    const Image8 mixed = pathDirect(scene);
    const std::vector<uint32_t> coverage = test::traceWithCoverage(scene, kWidth, kHeight).coverage;
    for (int i = 0; i < kSpheres; ++i) {
        const Scene wide = sceneWide(kModels[i]);
        EXPECT_EQ(differingPixels(mixed, pathDirect(wide), coverage, sphereCoverageId(wide, size_t(i)),
                                  std::string("per_object_path_") + toString(kModels[i])),
                  0);
    }
}

TEST(PerObjectModel, AMaterialsModelSurvivesTheSceneFile) {
    const Scene scene = mixedScene();
    const std::string text = sceneToJson(scene);
    const Scene back = parseSceneJson(text, "mixed.json");
    for (size_t i = 0; i < scene.spheres.size(); ++i) EXPECT_EQ(back.spheres[i].material.model, kModels[i]);
    EXPECT_EQ(back.planes[0].material.model, ShadingModel::Phong);
    // A material without a model of its own writes none, and reads back as the scene's.
    const Scene wide = parseSceneJson(sceneToJson(sceneWide(ShadingModel::BlinnPhong)), "wide.json");
    EXPECT_EQ(wide.model, ShadingModel::BlinnPhong);
    EXPECT_FALSE(wide.spheres[0].material.model.has_value());
    EXPECT_EQ(wide.planes[0].material.model, ShadingModel::Phong);
    // A misspelt model is refused with the place and the words it takes.
    try {
        parseSceneJson(R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                          "material": {"model": "phongg"}}]})",
                       "bad.json");
        FAIL() << "a misspelt model was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[0].material.model"), std::string::npos) << e.what();
    }
}

class PerObjectModelRaster : public test::GlTest {};

TEST_F(PerObjectModelRaster, EachSphereIsTheSceneWideRenderOfItsModel) {
    const Rendered mixed = test::rasterizeWithCoverage(mixedScene(), kWidth, kHeight);
    for (int i = 0; i < kSpheres; ++i) {
        const Scene wide = sceneWide(kModels[i]);
        const Rendered r = test::rasterizeWithCoverage(wide, kWidth, kHeight);
        EXPECT_EQ(differingPixels(mixed.pixels, r.pixels, mixed.coverage, sphereCoverageId(wide, size_t(i)),
                                  std::string("per_object_raster_") + toString(kModels[i])),
                  0);
    }
    const Scene phong = sceneWide(ShadingModel::Phong);
    const Rendered r = test::rasterizeWithCoverage(phong, kWidth, kHeight);
    EXPECT_GT(differingPixels(mixed.pixels, r.pixels, mixed.coverage, sphereCoverageId(phong, 2),
                              "per_object_raster_negative"),
              500);
    // And the rasterizer agrees with the tracer on the mixed scene under the design.md §4 gates.
    const CompareResult c = test::compareWithReference(mixedScene(), mixedScene(), kWidth, kHeight, 1,
                                                       test::kShadowEdgeGates, "per_object_raster_vs_trace");
    EXPECT_TRUE(c.pass) << compareSummary(c);
}
