// The partial redraw's cache keys (redraw_plan.h): which edits allow one, which ids it redraws, and the
// conservative pixel rectangles it is scissored to. Pure: no GL.
#include "raster/redraw_plan.h"

#include "scene/coverage.h"
#include "scene/mesh_geometry.h"

#include <gtest/gtest.h>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <memory>

namespace shadelab::raster {
namespace {

// Two point lights, two spheres, a checker floor and a mesh of two parts sharing one coverage id.
Scene lessonScene() {
    Scene s;
    s.lights.push_back(Light{LightType::Point, "key", {-5.0f, 7.0f, 5.0f}, {}, glm::vec3(1.0f), {1.0f, 0.0f, 0.0f}});
    s.lights.push_back(Light{LightType::Point, "fill", {6.0f, 4.0f, 4.0f}, {}, glm::vec3(0.3f), {1.0f, 0.0f, 0.0f}});
    s.spheres.push_back(Sphere{"red", {-3.0f, 0.8f, 0.5f}, 0.8f, Material{}});
    s.spheres.push_back(Sphere{"mirror", {3.3f, 0.9f, -0.4f}, 0.9f, Material{}});
    s.spheres[1].material.kr = glm::vec3(0.6f);
    s.planes.push_back(Plane{"floor", {0.0f, 1.0f, 0.0f}, 0.0f, Material{}, Checker{}});
    Mesh mesh;
    mesh.name = "model";
    const auto geometry = std::make_shared<MeshGeometry>();
    mesh.parts.push_back(MeshPart{geometry, Material{}});
    mesh.parts.push_back(MeshPart{geometry, Material{}});
    s.meshes.push_back(mesh);
    return s;
}

RedrawPlan plan(const Scene& before, const Scene& after, size_t maxIds = 8) {
    const DrawKey last = drawKey(before);
    return planRedraw(&last, drawKey(after), maxIds);
}

TEST(RedrawPlan, OnlyAMaterialChangedRedrawsThatObject) {
    const Scene base = lessonScene();
    Scene edited = base;
    edited.spheres[0].material.s = 77.0f;
    const RedrawPlan p = plan(base, edited);
    EXPECT_FALSE(p.full);
    EXPECT_EQ(p.ids, std::vector<uint32_t>{sphereCoverageId(base, 0)});
}

// The negative control of the one above: the same edit plus a moved light must not be partial (the
// shadows and every lit pixel change).
TEST(RedrawPlan, AMovedLightRedrawsEverything) {
    const Scene base = lessonScene();
    Scene moved = base;
    moved.spheres[0].material.s = 77.0f;
    moved.lights[1].position.x += 0.01f;
    EXPECT_TRUE(plan(base, moved).full);
    Scene recoloured = base;
    recoloured.lights[0].color = glm::vec3(0.9f);
    EXPECT_TRUE(plan(base, recoloured).full);
}

TEST(RedrawPlan, CameraGeometryTermsAndModelRedrawEverything) {
    const Scene base = lessonScene();
    std::vector<Scene> edits(7, base);
    edits[0].camera.position.x += 0.1f;
    edits[1].spheres[1].radius = 1.0f;
    edits[2].planes[0].offset = -0.5f;
    edits[3].terms.shadows = false;
    edits[4].model = ShadingModel::BlinnPhong;
    edits[5].meshes[0].parts[1].geometry = std::make_shared<MeshGeometry>();
    edits[6].ambient = glm::vec3(0.3f);
    for (size_t i = 0; i < edits.size(); ++i) EXPECT_TRUE(plan(base, edits[i]).full) << "edit " << i;
}

TEST(RedrawPlan, NothingChangedRedrawsNothing) {
    const Scene base = lessonScene();
    const RedrawPlan p = plan(base, base);
    EXPECT_FALSE(p.full);
    EXPECT_TRUE(p.ids.empty());
}

TEST(RedrawPlan, WithoutAPreviousImageEverythingIsDrawn) {
    EXPECT_TRUE(planRedraw(nullptr, drawKey(lessonScene()), 8).full);
}

TEST(RedrawPlan, CheckerAndMeshPartEditsNameTheirObjectOnce) {
    const Scene base = lessonScene();
    Scene edited = base;
    edited.planes[0].checker->md2 = glm::vec3(0.5f);
    edited.meshes[0].parts[0].material.md = glm::vec3(0.2f);
    edited.meshes[0].parts[1].material.md = glm::vec3(0.2f);
    const RedrawPlan p = plan(base, edited);
    ASSERT_FALSE(p.full);
    // Draw order: mesh parts, spheres, planes; the mesh's two parts share its coverage id.
    EXPECT_EQ(p.ids, (std::vector<uint32_t>{meshCoverageId(base, 0), planeCoverageId(base, 0)}));
}

TEST(RedrawPlan, MoreChangedObjectsThanAllowedRedrawEverything) {
    const Scene base = lessonScene();
    Scene edited = base;
    edited.spheres[0].material.s = 2.0f;
    edited.spheres[1].material.s = 2.0f;
    EXPECT_FALSE(plan(base, edited, 2).full);
    EXPECT_TRUE(plan(base, edited, 1).full);
    RedrawPlan p = plan(base, edited, 2);
    addToPlan(p, sphereCoverageId(base, 0), 2);  // already listed: no change
    EXPECT_FALSE(p.full);
    addToPlan(p, planeCoverageId(base, 0), 2);
    EXPECT_TRUE(p.full);
}

// A 90° square view from the origin down -z, near 0.5: the cube face frames' kind of projection.
glm::mat4 faceViewProj() {
    return glm::perspective(glm::radians(90.0f), 1.0f, 0.5f, 100.0f) *
           glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(RedrawPlan, BoxRectangleHoldsTheBoxsPixels) {
    const glm::mat4 vp = faceViewProj();
    // A unit box 9.5 to 10.5 ahead: its near face spans 0.5/9.5 of the half-width around the centre,
    // 64 ± 3.4 px.
    const PixelRect r = boxPixelRect(vp, {-0.5f, -0.5f, -10.5f}, {0.5f, 0.5f, -9.5f}, 128, 128);
    EXPECT_FALSE(r.empty());
    EXPECT_LE(r.x0, 60);
    EXPECT_GE(r.x1, 68);
    EXPECT_LE(r.y0, 60);
    EXPECT_GE(r.y1, 68);
    EXPECT_LE(r.x1 - r.x0, 14);  // and not much more
    // Control: a box behind the eye covers nothing, and one beside the view lies outside the viewport.
    EXPECT_TRUE(boxPixelRect(vp, {-0.5f, -0.5f, 9.5f}, {0.5f, 0.5f, 10.5f}, 128, 128).empty());
    EXPECT_TRUE(boxPixelRect(vp, {30.0f, -0.5f, -10.5f}, {31.0f, 0.5f, -9.5f}, 128, 128).empty());
}

TEST(RedrawPlan, BoxThroughTheNearPlaneIsClippedNotDropped) {
    const glm::mat4 vp = faceViewProj();
    // From behind the eye to 10 ahead, off to the right: the part ahead projects right of the centre.
    const PixelRect r = boxPixelRect(vp, {2.0f, -0.5f, -10.0f}, {3.0f, 0.5f, 5.0f}, 128, 128);
    EXPECT_FALSE(r.empty());
    EXPECT_GE(r.x0, 64);
    EXPECT_EQ(r.x1, 128);
    // Around the eye: every pixel.
    const PixelRect all = boxPixelRect(vp, glm::vec3(-1.0f), glm::vec3(1.0f), 128, 128);
    EXPECT_EQ(all.x0, 0);
    EXPECT_EQ(all.y0, 0);
    EXPECT_EQ(all.x1, 128);
    EXPECT_EQ(all.y1, 128);
}

}  // namespace
}  // namespace shadelab::raster
