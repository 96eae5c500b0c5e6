// Spot lights, raster against reference (design.md §4): a spot over three spheres, one inside its inner cone,
// one across the cone's edge and one outside it, on a checker floor the edge crosses. The local terms alone pass
// the strict gates; with shadows (a spot outside the casters' sphere gets a perspective map, one among them a
// cube) they pass the shadow-edge gates. The range window passes the strict gates. Negative controls: the outer
// angle or the range changed in one renderer fails the same gates.
#include "compare/compare_report.h"
#include "gl_fixture.h"
#include "raster/shadow_fit.h"
#include "render_compare.h"
#include "scene/light_at.h"

#include <gtest/gtest.h>

#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 192, kHeight = 128;

const glm::vec3 kInside{0.0f, 0.5f, 0.0f}, kAcross{1.7f, 0.5f, 0.2f}, kOutside{-2.6f, 0.5f, 0.3f};

Light spot(glm::vec3 position, glm::vec3 target, float inner, float outer) {
    Light l;
    l.type = LightType::Spot;
    l.name = "spot";
    l.position = position;
    l.direction = glm::normalize(target - position);
    l.innerConeAngle = inner;
    l.outerConeAngle = outer;
    return l;
}

// The spot's cone factor at a point: 1 inside the inner cone, 0 outside the outer one.
float coneAt(const Light& l, glm::vec3 P) {
    return shading::spotAttenuation(l.direction, l.position - P, glm::vec2(lightCone(l)));
}

Scene spotScene(bool shadows) {
    Scene scene = test::comparisonStage();
    scene.terms = Terms{true, true, true, shadows, false};
    Plane floor;
    floor.material = test::colourMaterial(glm::vec3(0.8f));
    floor.checker = Checker{glm::vec3(0.25f), 0.75f};
    scene.planes.push_back(floor);
    scene.spheres.push_back({"inside", kInside, 0.5f, test::colourMaterial({0.8f, 0.2f, 0.2f})});
    scene.spheres.push_back({"across", kAcross, 0.5f, test::colourMaterial({0.2f, 0.7f, 0.3f})});
    scene.spheres.push_back({"outside", kOutside, 0.5f, test::colourMaterial({0.2f, 0.3f, 0.9f})});
    scene.lights.push_back(spot({0.0f, 4.0f, 1.0f}, {0.2f, 0.0f, 0.0f}, 0.3f, 0.5f));
    return scene;
}

CompareResult compare(const Scene& raster, const Scene& traced, const CompareGates& gates, const std::string& name) {
    return test::compareWithReference(raster, traced, kWidth, kHeight, 1, gates, name);
}

}  // namespace

class SpotLights : public test::GlTest {};

// The scene is what the tests claim: one sphere in the full cone, one across its edge, one outside it.
TEST(SpotLightScene, SpheresSitInsideAcrossAndOutsideTheCone) {
    const Light l = spotScene(false).lights[0];
    EXPECT_EQ(coneAt(l, kInside), 1.0f);
    const float across = coneAt(l, kAcross);
    EXPECT_GT(across, 0.05f);
    EXPECT_LT(across, 0.95f);
    EXPECT_EQ(coneAt(l, kOutside), 0.0f);
    // Negative control: a wide cone lights the outside sphere.
    Light wide = l;
    wide.outerConeAngle = 1.2f;
    EXPECT_GT(coneAt(wide, kOutside), 0.0f);
}

TEST_F(SpotLights, LocalTermsMatchReferenceUnderStrictGates) {
    const Scene scene = spotScene(false);
    const CompareResult r = compare(scene, scene, CompareGates{}, "spot_local");
    EXPECT_TRUE(r.pass) << compareSummary(r);
}

TEST_F(SpotLights, NegativeControlOuterAngleChangedFailsStrictGates) {
    const Scene traced = spotScene(false);
    Scene raster = traced;
    raster.lights[0].outerConeAngle = 0.55f;
    const CompareResult r = compare(raster, traced, CompareGates{}, "negative_spot_outer_angle");
    EXPECT_FALSE(r.pass) << "an outer angle of 0.55 rad against 0.5 passed:\n" << compareSummary(r);
}

TEST_F(SpotLights, ShadowsPerspectiveAndCubeMatchReference) {
    Scene scene = spotScene(true);
    // A second spot among the spheres, aimed at the floor between them: inside the casters' sphere, a cube map.
    Light low = spot({0.9f, 1.4f, 0.6f}, {0.9f, 0.0f, 1.2f}, 0.5f, 1.1f);
    low.color = glm::vec3(0.5f, 0.4f, 0.3f);
    scene.lights.push_back(low);
    const raster::ShadowFit fit = raster::fitShadows(scene, raster::casterBounds(scene, {}), scene.raster);
    EXPECT_EQ(fit.block.light[0].x, raster::kShadowPerspective);
    EXPECT_EQ(fit.block.light[1].x, raster::kShadowCube);
    const CompareResult r = compare(scene, scene, test::kShadowEdgeGates, "spot_shadows");
    EXPECT_TRUE(r.pass) << compareSummary(r);

    // Negative control: the outer angle of the first spot changed in the rasterizer fails the same gates.
    Scene wider = scene;
    wider.lights[0].outerConeAngle = 0.6f;
    const CompareResult n = compare(wider, scene, test::kShadowEdgeGates, "negative_spot_shadows_outer_angle");
    EXPECT_FALSE(n.pass) << "an outer angle of 0.6 rad against 0.5 passed the shadow gates:\n" << compareSummary(n);
}

// KHR_lights_punctual's range window on a spot and a point light (with inverse-square attenuation, as a glTF
// light would be set up), local terms, strict gates; the range changed in one renderer fails them.
TEST_F(SpotLights, RangeWindowMatchesReference) {
    Scene scene = spotScene(false);
    scene.lights[0].outerConeAngle = 0.9f;
    scene.lights[0].range = 5.0f;
    Light bulb = test::pointLight({-2.0f, 1.5f, 1.5f}, glm::vec3(2.0f));
    bulb.attenuation = {0.0f, 0.0f, 1.0f};
    bulb.range = 3.0f;
    scene.lights.push_back(bulb);
    // The floor under the spot runs past its range: the window is 0 there, and between 0 and 1 nearer.
    EXPECT_EQ(lightAt(scene.lights[0], {0.0f, 0.0f, -3.0f}).Il, glm::vec3(0.0f));
    EXPECT_GT(lightAt(scene.lights[0], {0.0f, 0.0f, 0.0f}).Il.x, 0.0f);
    const CompareResult r = compare(scene, scene, CompareGates{}, "spot_range");
    EXPECT_TRUE(r.pass) << compareSummary(r);

    Scene shorter = scene;
    shorter.lights[0].range = 4.5f;
    const CompareResult n = compare(shorter, scene, CompareGates{}, "negative_spot_range");
    EXPECT_FALSE(n.pass) << "a range of 4.5 against 5 passed:\n" << compareSummary(n);
}
