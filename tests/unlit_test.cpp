// "No illumination", the progression's step 0 (docs/lighting.md): with no light term on, every surface shows its
// unlit colour, md under Phong and Blinn-Phong and the base colour under pbr (a metal's too), a checker's second
// tiles md2. The Whitted tracer's floats are exactly those colours, the rasterizer equals it under the strict
// design.md §4 gates, and the path tracer shows the same colour at the first hit. Negative controls: a changed md
// fails the gates, and the documented colour is not what a lit render gives.
#include "compare/compare_report.h"
#include "gl_fixture.h"
#include "render_compare.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "trace/path/path_render.h"
#include "trace/trace_image.h"

#include <gtest/gtest.h>

#include <glm/vec4.hpp>
#include <memory>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 192, kHeight = 128;

Scene unlitScene(ShadingModel model) {
    Scene scene = test::comparisonStage();
    scene.model = model;
    scene.terms = Terms{false, false, false, false, false};
    Plane floor;
    floor.material = test::colourMaterial(glm::vec3(0.8f));
    floor.material.baseColor = glm::vec3(0.7f, 0.6f, 0.5f);
    floor.checker = Checker{glm::vec3(0.25f, 0.3f, 0.35f), 0.75f};
    scene.planes.push_back(floor);
    Material red = test::colourMaterial({0.8f, 0.2f, 0.2f});
    red.baseColor = {0.9f, 0.1f, 0.1f};
    red.metallic = 0.0f;
    Material gold = test::colourMaterial({0.3f, 0.25f, 0.1f});
    gold.baseColor = {1.0f, 0.77f, 0.34f};
    gold.metallic = 1.0f;  // no diffuse colour at all: unlit, it still shows its base colour
    scene.spheres.push_back({"red", {-0.9f, 0.6f, 0.0f}, 0.6f, red});
    scene.spheres.push_back({"gold", {0.9f, 0.6f, 0.0f}, 0.6f, gold});
    scene.lights.push_back(test::pointLight({-3.0f, 5.0f, 4.0f}, glm::vec3(1.0f)));
    return scene;
}

// The pixel a world point falls in.
glm::ivec2 pixelOf(const Scene& scene, glm::vec3 p) {
    const ViewSetup v = makeViewSetup(scene, kWidth, kHeight);
    const glm::vec4 clip = v.viewProj * glm::vec4(p, 1.0f);
    return {int((clip.x / clip.w * 0.5f + 0.5f) * float(kWidth)),
            int((1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * float(kHeight))};
}

glm::vec3 tracedAt(const Scene& scene, glm::ivec2 px) {
    trace::TraceSettings t;
    t.width = kWidth;
    t.height = kHeight;
    t.threads = 2;
    const ImageF img = trace::traceImage(scene, t).color;
    const float* p = img.pixel(px.x, px.y);
    return {p[0], p[1], p[2]};
}

// The documented unlit colour of sphere `i` under the scene's model.
glm::vec3 documented(const Scene& scene, size_t i) {
    const Material& m = scene.spheres[i].material;
    return scene.model == ShadingModel::Pbr ? m.baseColor : m.md;
}

}  // namespace

TEST(Unlit, TheTracerShowsTheDocumentedColours) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
        const Scene scene = unlitScene(model);
        for (size_t i = 0; i < scene.spheres.size(); ++i) {
            const glm::vec3 c = tracedAt(scene, pixelOf(scene, scene.spheres[i].center));
            EXPECT_EQ(c, documented(scene, i)) << toString(model) << ", sphere " << scene.spheres[i].name;
        }
        // Negative control: the same scene lit (step 3) does not show those colours.
        Scene lit = scene;
        lit.terms = Terms{true, true, true, false, false};
        EXPECT_NE(tracedAt(lit, pixelOf(lit, lit.spheres[1].center)), documented(lit, 1)) << toString(model);
    }
}

TEST(Unlit, ThePathTracerShowsThemAtTheFirstHit) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
        const Scene scene = unlitScene(model);
        trace::PathSettings s;
        s.width = kWidth;
        s.height = kHeight;
        s.spp = 4;
        s.threads = 2;
        trace::PathRender render(std::make_shared<const trace::TraceScene>(scene), s);
        render.addSamples(s.spp);
        for (size_t i = 0; i < scene.spheres.size(); ++i) {
            const glm::ivec2 px = pixelOf(scene, scene.spheres[i].center);
            const glm::vec3 c = render.mean(px.x, px.y);
            const glm::vec3 d = documented(scene, i);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], d[k], 1e-6f) << toString(model) << ", sphere " << i;
        }
    }
}

class UnlitRaster : public test::GlTest {};

TEST_F(UnlitRaster, MatchesTheReferenceUnderStrictGates) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
        const Scene scene = unlitScene(model);
        const std::string name = std::string("unlit_") + toString(model);
        const CompareResult r = test::compareWithReference(scene, scene, kWidth, kHeight, 1, CompareGates{}, name);
        EXPECT_TRUE(r.pass) << toString(model) << ": " << compareSummary(r);
    }
    // Step 0 with reflections on: the plane's mirror and the spheres' environment cubes reflect the unlit scene.
    Scene mirrored = unlitScene(ShadingModel::Phong);
    mirrored.terms.reflections = true;
    mirrored.planes[0].material.kr = glm::vec3(0.3f);
    const CompareResult m =
        test::compareWithReference(mirrored, mirrored, kWidth, kHeight, 1, CompareGates{}, "unlit_mirror");
    EXPECT_TRUE(m.pass) << compareSummary(m);
}

TEST_F(UnlitRaster, NegativeControlAChangedColourFails) {
    const Scene traced = unlitScene(ShadingModel::Phong);
    Scene raster = traced;
    raster.spheres[0].material.md += glm::vec3(0.05f, 0.0f, 0.0f);
    const CompareResult r =
        test::compareWithReference(raster, traced, kWidth, kHeight, 1, CompareGates{}, "negative_unlit_md");
    EXPECT_FALSE(r.pass) << "md 0.05 brighter in one renderer passed:\n" << compareSummary(r);
    // And under pbr the base colour, not md, is what shows: md changed alone still passes.
    const Scene pbr = unlitScene(ShadingModel::Pbr);
    Scene pbrMd = pbr;
    pbrMd.spheres[0].material.md += glm::vec3(0.05f, 0.0f, 0.0f);
    EXPECT_TRUE(test::compareWithReference(pbrMd, pbr, kWidth, kHeight, 1, CompareGates{}, "unlit_pbr_md").pass);
    Scene pbrBase = pbr;
    pbrBase.spheres[0].material.baseColor += glm::vec3(0.0f, 0.05f, 0.0f);
    EXPECT_FALSE(
        test::compareWithReference(pbrBase, pbr, kWidth, kHeight, 1, CompareGates{}, "negative_unlit_pbr_base").pass);
}

// Textured: the base-colour texture multiplies md (Phong) and the base colour (pbr), a metallic-roughness map
// gives Phong's diffuse colour, in both renderers alike.
TEST_F(UnlitRaster, TexturedModelsMatchTheReference) {
    for (const char* name : {"uv_checker", "metal_rough"}) {
        for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
            Scene scene = loadScene(test::sourcePath(std::string("assets/models/textures/") + name + ".gltf"));
            scene.model = model;
            scene.terms = Terms{false, false, false, false, false};
            const std::string what = std::string("unlit_") + name + "_" + toString(model);
            const CompareResult r = test::compareWithReference(scene, scene, kWidth, kHeight, 1, CompareGates{}, what);
            EXPECT_TRUE(r.pass) << what << ": " << compareSummary(r);
        }
    }
}
