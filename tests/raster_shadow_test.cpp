// Raster shadows against the reference: spheres on a checker plane under 1 and 3 lights (point and
// directional), shadows on, gated as design.md §4 with a shadow-edge allowance; a light moved in one renderer
// must fail. Also: no acne on an unoccluded lit plane, and no NaNs in any example scene with every term on.
#include "compare/compare_report.h"
#include "compare/image_compare.h"
#include "gl_fixture.h"
#include "image/encode.h"
#include "raster/offscreen.h"
#include "render_compare.h"
#include "scene/scene_load.h"
#include "test_output.h"
#include "trace/trace_image.h"

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 192, kHeight = 128;

raster::RasterRenderer& renderer() { return test::sharedRasterRenderer(); }

Scene spheresOnPlane(int lights) {
    Scene scene = test::comparisonStage();
    scene.terms = Terms{true, true, true, true, false};
    Plane floor;
    floor.material = test::colourMaterial(glm::vec3(0.8f));
    floor.checker = Checker{glm::vec3(0.25f), 0.75f};
    scene.planes.push_back(floor);
    const glm::vec3 colours[3] = {{0.8f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.3f}, {0.2f, 0.3f, 0.9f}};
    const glm::vec3 centres[3] = {{-1.5f, 0.6f, 0.0f}, {0.0f, 0.8f, -0.6f}, {1.4f, 0.5f, 0.7f}};
    const float radii[3] = {0.6f, 0.8f, 0.5f};
    for (int i = 0; i < 3; ++i) scene.spheres.push_back({"", centres[i], radii[i], test::colourMaterial(colours[i])});
    if (lights == 1) {
        scene.lights.push_back(test::pointLight({-3.0f, 5.0f, 4.0f}, glm::vec3(1.0f)));
    } else {
        scene.lights.push_back(test::pointLight({-3.0f, 4.0f, 3.0f}, {0.7f, 0.3f, 0.3f}));
        scene.lights.push_back(
            test::pointLight({0.5f, 1.2f, 0.9f}, {0.2f, 0.5f, 0.2f}));  // between the spheres: cube map
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.6f));
        sun.color = {0.3f, 0.3f, 0.7f};
        scene.lights.push_back(sun);
    }
    return scene;
}

CompareResult compareRenders(const Scene& rasterScene, const Scene& tracedScene, const std::string& name) {
    return test::compareWithReference(rasterScene, tracedScene, kWidth, kHeight, 1, test::kShadowEdgeGates, name);
}

}  // namespace

class RasterShadows : public test::GlTest {};

TEST_F(RasterShadows, OnePointLightMatchesReference) {
    const Scene scene = spheresOnPlane(1);
    CompareResult r = compareRenders(scene, scene, "shadow_1light");
    EXPECT_TRUE(r.pass) << compareSummary(r);
}

TEST_F(RasterShadows, ThreeLightsPointCubeAndDirectionalMatchReference) {
    const Scene scene = spheresOnPlane(3);
    CompareResult r = compareRenders(scene, scene, "shadow_3lights");
    EXPECT_TRUE(r.pass) << compareSummary(r);
}

TEST_F(RasterShadows, LightMovedInOneRendererFails) {
    const Scene a = spheresOnPlane(1);
    Scene b = a;
    b.lights[0].position += glm::vec3(0.5f, 0.0f, 0.0f);
    CompareResult r = compareRenders(a, b, "negative_shadow_light_moved");
    EXPECT_FALSE(r.pass) << "a light moved in one renderer passed the shadow gates:\n" << compareSummary(r);
}

// Planes occlude analytically, and only for the lights the CPU finds they can block (shadow_maps.cpp
// planeMask). A wall between a second light and the stage must block that light everywhere the camera
// sees, as the tracer's shadow ray does: the raster image is then exactly the image without that light,
// and without the wall (the control) the light does reach the stage.
Scene walledStage(bool wall, bool lightBehind) {
    Scene scene = spheresOnPlane(1);
    scene.lights[0].position = {-2.0f, 3.0f, 2.0f};
    if (lightBehind) scene.lights.push_back(test::pointLight({4.0f, 2.5f, 0.5f}, {0.6f, 0.5f, 0.3f}));
    if (wall) {
        Plane w;
        w.normal = {-1.0f, 0.0f, 0.0f};
        w.offset = -2.6f;  // the plane x = 2.6, facing the stage; the second light stands at x = 4
        w.material = test::colourMaterial(glm::vec3(0.5f, 0.55f, 0.6f));
        scene.planes.push_back(w);
    }
    return scene;
}

TEST_F(RasterShadows, WallPlaneBlocksTheLightBehindItAsTheReference) {
    const Scene scene = walledStage(true, true);
    CompareResult r = compareRenders(scene, scene, "shadow_wall_plane");
    EXPECT_TRUE(r.pass) << compareSummary(r);

    raster::RasterRenderer& renderer = test::sharedRasterRenderer();
    auto pixels = [&renderer](const Scene& s) {
        renderer.uploadMeshes(s);
        return raster::renderRaster(renderer, s, kWidth, kHeight, false).color.rgba;
    };
    EXPECT_EQ(pixels(walledStage(true, true)), pixels(walledStage(true, false)))
        << "the light behind the wall reached something the camera sees";
    EXPECT_NE(pixels(walledStage(false, true)), pixels(walledStage(false, false)))
        << "control: without the wall the second light should light the stage";
}

// Acne: a lit plane with no occluders has no shadowed pixel, so shadows on renders exactly shadows off.
// A sphere far outside the view still makes the renderer build and sample a shadow map.
TEST_F(RasterShadows, UnoccludedPlaneHasNoAcne) {
    Scene scene = spheresOnPlane(3);
    scene.spheres = {{"", {40.0f, 1.0f, -40.0f}, 0.5f, test::colourMaterial(glm::vec3(0.5f))}};
    raster::RasterRenderer& r = renderer();
    r.uploadMeshes(scene);
    scene.terms.shadows = false;
    const raster::RasterOutput off = raster::renderRaster(r, scene, kWidth, kHeight, false);
    scene.terms.shadows = true;
    const raster::RasterOutput on = raster::renderRaster(r, scene, kWidth, kHeight, false);
    ASSERT_EQ(off.color.rgba.size(), on.color.rgba.size());
    size_t differing = 0;
    for (size_t i = 0; i < on.color.rgba.size(); ++i) differing += on.color.rgba[i] != off.color.rgba[i];
    EXPECT_EQ(differing, 0u) << "shadow acne: shadows on differs from off on an unoccluded plane";
}

TEST_F(RasterShadows, ExampleScenesHaveNoNaNsWithEveryTerm) {
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("assets/scenes"))) {
        if (entry.path().extension() != ".json") continue;
        Scene scene = loadScene(entry.path().string());
        scene.terms = Terms{true, true, true, true, true};
        raster::RasterRenderer& r = renderer();
        r.uploadMeshes(scene);
        const raster::RasterOutput out = raster::renderRaster(r, scene, kWidth, kHeight, false);
        size_t bad = 0;
        for (float v : out.color.rgba) bad += !std::isfinite(v);
        EXPECT_EQ(bad, 0u) << entry.path().filename() << ": non-finite values";
    }
}
