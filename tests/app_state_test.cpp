// Viewer state tests (issue 4 §3), no window: every control action changes the scene as expected and
// nothing else, an edited scene survives a JSON round trip exactly, the probe equals the shared C++
// shading, the equivalent-Blinn rule, the orbit camera, and script parsing with file-and-index errors.
#include "app/albedo_plot.h"
#include "app/lobe_plot.h"
#include "app/material_presets.h"
#include "app/orbit_camera.h"
#include "app/probe.h"
#include "app/script.h"
#include "app/specular_lobe.h"
#include "app/viewer_state.h"
#include "scene/coverage.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "scene/white_furnace.h"
#include "shading/lighting.h"
#include "shading/local_illumination.h"
#include "test_output.h"
#include "trace/integrator.h"
#include "trace/tile_renderer.h"
#include "util/input_error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

using namespace shadelab;
using namespace shadelab::app;

namespace {

ViewerState defaultState() {
    const std::string path = test::sourcePath("assets/scenes/default.json");
    return makeViewerState(loadScene(path), path);
}

uint32_t idOf(const ViewerState& s, const std::string& name) {
    auto id = findObject(s.scene, name);
    EXPECT_TRUE(id.has_value()) << name;
    return id.value_or(0);
}

// Projects a world point to the pixel that contains it in a width x height image.
glm::ivec2 pixelOf(const Scene& scene, int width, int height, const glm::vec3& p) {
    const ViewSetup v = makeViewSetup(scene, width, height);
    const glm::vec4 clip = v.viewProj * glm::vec4(p, 1.0f);
    const float x = (clip.x / clip.w * 0.5f + 0.5f) * float(width);
    const float y = (1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * float(height);
    return {int(std::floor(x)), int(std::floor(y))};
}

Script parse(const std::string& text) { return parseScript(text, "actions.json"); }

std::string parseError(const std::string& text) {
    try {
        parse(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

// ---- Control actions -----------------------------------------------------------------------------------

TEST(AppState, SetShininessChangesOnlyThatObjectAndClamps) {
    ViewerState s = defaultState();
    const Scene before = s.scene;
    const uint32_t red = idOf(s, "red plastic"), blue = idOf(s, "shiny blue");
    const uint64_t rev = s.revision, referenceRev = s.referenceRevision;
    ASSERT_TRUE(setShininess(s, red, 300.0f));
    EXPECT_EQ(s.scene.spheres[red - 1].material.s, 300.0f);
    EXPECT_GT(s.revision, rev);
    EXPECT_GT(s.referenceRevision, referenceRev) << "a material edit restarts the reference";
    // Negative control: the other objects keep their exponent.
    EXPECT_EQ(s.scene.spheres[blue - 1].material.s, before.spheres[blue - 1].material.s);
    setShininess(s, red, 1e9f);
    EXPECT_EQ(s.scene.spheres[red - 1].material.s, kMaxShininess);
    setShininess(s, red, -3.0f);
    EXPECT_EQ(s.scene.spheres[red - 1].material.s, 0.0f);
    EXPECT_FALSE(setShininess(s, 0, 10.0f));    // background
    EXPECT_FALSE(setShininess(s, 999, 10.0f));  // no such object
}

TEST(AppState, TermsToggleOneAtATime) {
    ViewerState s = defaultState();
    for (Term t : {Term::Ambient, Term::Diffuse, Term::Specular, Term::Shadows, Term::Reflections}) {
        const Terms before = s.scene.terms;
        toggleTerm(s, t);
        EXPECT_NE(termEnabled(s.scene.terms, t), termEnabled(before, t)) << toString(t);
        for (Term o : {Term::Ambient, Term::Diffuse, Term::Specular, Term::Shadows, Term::Reflections}) {
            if (o == t) continue;
            EXPECT_EQ(termEnabled(s.scene.terms, o), termEnabled(before, o)) << toString(o);
        }
        setTerm(s, t, true);
        EXPECT_TRUE(termEnabled(s.scene.terms, t));
        EXPECT_EQ(parseTerm(toString(t)), t);
    }
    EXPECT_FALSE(parseTerm("spec").has_value());
}

TEST(AppState, ProgressionStepsAreTheLecturesOrder) {
    ViewerState s = defaultState();
    const bool expected[5][5] = {{1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 1, 1, 0, 0}, {1, 1, 1, 1, 0}, {1, 1, 1, 1, 1}};
    for (int step = 1; step <= 5; ++step) {
        applyProgression(s, step);
        const Terms& t = s.scene.terms;
        EXPECT_EQ(t.ambient, expected[step - 1][0]);
        EXPECT_EQ(t.diffuse, expected[step - 1][1]);
        EXPECT_EQ(t.specular, expected[step - 1][2]);
        EXPECT_EQ(t.shadows, expected[step - 1][3]);
        EXPECT_EQ(t.reflections, expected[step - 1][4]);
        EXPECT_EQ(progressionStep(t), step);
    }
    setTerm(s, Term::Ambient, false);  // all but ambient: not a step
    EXPECT_EQ(progressionStep(s.scene.terms), 0);
}

TEST(AppState, ModelSwitchAndEquivalentExponentConversion) {
    ViewerState s = defaultState();
    setModel(s, ShadingModel::BlinnPhong);
    EXPECT_EQ(s.scene.model, ShadingModel::BlinnPhong);
    setModel(s, ShadingModel::Phong);
    const uint32_t red = idOf(s, "red plastic"), gold = idOf(s, "gold");
    select(s, red);
    switchModelKeepingHighlights(s, ShadingModel::BlinnPhong, false);
    EXPECT_EQ(s.scene.model, ShadingModel::BlinnPhong);
    EXPECT_FLOAT_EQ(s.scene.spheres[red - 1].material.s, equivalentBlinnExponent(32.0f));
    EXPECT_EQ(s.scene.spheres[gold - 1].material.s, 64.0f);  // not selected: unchanged
    switchModelKeepingHighlights(s, ShadingModel::Phong, false);
    EXPECT_NEAR(s.scene.spheres[red - 1].material.s, 32.0f, 1e-2f);
    switchModelKeepingHighlights(s, ShadingModel::Phong, true);  // already Phong: exponents untouched
    EXPECT_NEAR(s.scene.spheres[red - 1].material.s, 32.0f, 1e-2f);
    // pbr reads roughness, not s: switching to it and back converts no exponent.
    const float before = s.scene.spheres[red - 1].material.s;
    switchModelKeepingHighlights(s, ShadingModel::Pbr, true);
    EXPECT_EQ(s.scene.model, ShadingModel::Pbr);
    switchModelKeepingHighlights(s, ShadingModel::BlinnPhong, true);
    EXPECT_EQ(s.scene.spheres[red - 1].material.s, before);
    setNormalized(s, true);
    EXPECT_TRUE(s.scene.normalized);
}

TEST(AppState, MeshPbrEditsGoToTheOverride) {
    const std::string path = test::sourcePath("assets/scenes/torus.json");
    ViewerState s = makeViewerState(loadScene(path), path);
    const uint32_t torus = idOf(s, "torus");
    Material m = objectMaterial(s.scene, torus);
    m.roughness = 0.125f;
    m.metallic = 1.0f;
    ASSERT_TRUE(setObjectMaterial(s, torus, m));
    const Mesh& mesh = s.scene.meshes[0];
    EXPECT_EQ(mesh.material.roughness, 0.125f);
    EXPECT_EQ(mesh.material.metallic, 1.0f);
    EXPECT_FALSE(mesh.material.baseColor.has_value());
    for (const MeshPart& p : mesh.parts) EXPECT_EQ(p.material.roughness, 0.125f);
    const Scene back = parseSceneJson(sceneToJson(s.scene), path);
    EXPECT_EQ(back.meshes[0].material.roughness, 0.125f);
}

TEST(AppState, PresetsComeFromTheClassicTable) {
    ASSERT_GE(materialPresets().size(), 24u);
    for (const char* name : {"brass", "chrome", "jade", "pearl", "red plastic", "black rubber"})
        EXPECT_NE(findMaterialPreset(name), nullptr) << name;
    EXPECT_EQ(findMaterialPreset("unobtainium"), nullptr);
    ViewerState s = defaultState();
    const uint32_t mirror = idOf(s, "mirror"), red = idOf(s, "red plastic");
    const Material redBefore = s.scene.spheres[red - 1].material;
    ASSERT_TRUE(applyPreset(s, mirror, *findMaterialPreset("brass")));
    const Material& m = s.scene.spheres[mirror - 1].material;
    EXPECT_EQ(m.ma, glm::vec3(0.329412f, 0.223529f, 0.027451f));
    EXPECT_EQ(m.md, glm::vec3(0.780392f, 0.568627f, 0.113725f));
    EXPECT_EQ(m.ms, glm::vec3(0.992157f, 0.941176f, 0.807843f));
    EXPECT_FLOAT_EQ(m.s, 0.21794872f * 128.0f);
    EXPECT_EQ(m.kr, glm::vec3(0.6f));                               // kept: presets set ma, md, ms and s only
    EXPECT_EQ(s.scene.spheres[red - 1].material.md, redBefore.md);  // negative control
}

TEST(AppState, LightsAddRemoveAndAmbient) {
    ViewerState s = defaultState();
    ASSERT_EQ(s.scene.lights.size(), 2u);
    const int i = addLight(s, LightType::Directional);
    ASSERT_EQ(i, 2);
    EXPECT_EQ(s.scene.lights[2].type, LightType::Directional);
    EXPECT_NEAR(glm::length(s.scene.lights[2].direction), 1.0f, 1e-5f);
    const std::string keyName = s.scene.lights[0].name;
    EXPECT_TRUE(removeLight(s, 0));
    EXPECT_EQ(s.scene.lights.size(), 2u);
    EXPECT_NE(s.scene.lights[0].name, keyName);
    EXPECT_FALSE(removeLight(s, 5));
    while (addLight(s, LightType::Point) >= 0) {}
    EXPECT_EQ(s.scene.lights.size(), size_t(kMaxLights));
    setAmbient(s, glm::vec3(0.3f, -1.0f, 0.1f));
    EXPECT_EQ(s.scene.ambient, glm::vec3(0.3f, 0.0f, 0.1f));
    const ColorIntensity ci = splitIntensity(glm::vec3(2.0f, 1.0f, 0.5f));
    EXPECT_EQ(ci.color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(ci.intensity, 2.0f);
    EXPECT_EQ(joinIntensity(ci), glm::vec3(2.0f, 1.0f, 0.5f));
}

TEST(AppState, RasterSettingsChangeOnlySceneRasterAndClamp) {
    ViewerState s = defaultState();
    select(s, idOf(s, "gold"));
    setMode(s, ViewMode::Split);
    const ViewerState before = s;
    const RasterSettings wanted{2048, 0.5f, 3.25f, true, 256};
    setRasterSettings(s, wanted);
    EXPECT_EQ(s.scene.raster.shadowMapSize, 2048);
    EXPECT_EQ(s.scene.raster.depthBias, 0.5f);
    EXPECT_EQ(s.scene.raster.normalBias, 3.25f);
    EXPECT_TRUE(s.scene.raster.pcf);
    EXPECT_EQ(s.scene.raster.reflectionCubeSize, 256);
    EXPECT_GT(s.revision, before.revision) << "the rasterizer must redraw";
    EXPECT_EQ(s.referenceRevision, before.referenceRevision) << "the tracer has no raster settings: no restart";
    // Nothing else changed: the scene with its old raster settings saves to the same text, and the view is kept.
    Scene restored = s.scene;
    restored.raster = before.scene.raster;
    EXPECT_EQ(sceneToJson(restored), sceneToJson(before.scene));
    EXPECT_NE(sceneToJson(s.scene), sceneToJson(before.scene)) << "a save keeps the new settings";
    EXPECT_EQ(s.selected, before.selected);
    EXPECT_EQ(s.mode, before.mode);
    EXPECT_EQ(s.geometryRevision, before.geometryRevision);

    setRasterSettings(s, RasterSettings{5, -1.0f, 1e9f, false, 1 << 20});
    EXPECT_EQ(s.scene.raster.shadowMapSize, kMinShadowMapSize);
    EXPECT_EQ(s.scene.raster.depthBias, 0.0f);
    EXPECT_EQ(s.scene.raster.normalBias, kMaxShadowBias);
    EXPECT_FALSE(s.scene.raster.pcf);
    EXPECT_EQ(s.scene.raster.reflectionCubeSize, kMaxReflectionCubeSize);
    setRasterSettings(s, RasterSettings{-3, std::nanf(""), 2.0f, false, 1});
    EXPECT_EQ(s.scene.raster.shadowMapSize, 0) << "<= 0 is auto";
    EXPECT_EQ(s.scene.raster.depthBias, 0.0f);
    EXPECT_EQ(s.scene.raster.reflectionCubeSize, kMinReflectionCubeSize);
}

TEST(AppState, MeshMaterialEditsGoToTheOverrideAndEveryPart) {
    const std::string path = test::sourcePath("assets/scenes/torus.json");
    ViewerState s = makeViewerState(loadScene(path), path);
    const uint32_t torus = idOf(s, "torus");
    ASSERT_EQ(objectRef(s.scene, torus).kind, ObjectKind::Mesh);
    const Mesh& mesh = s.scene.meshes[0];
    ASSERT_FALSE(mesh.parts.empty());
    const glm::vec3 mdBefore = mesh.parts[0].material.md;
    setShininess(s, torus, 500.0f);
    EXPECT_EQ(mesh.material.s, 500.0f);
    EXPECT_FALSE(mesh.material.md.has_value());  // only the changed field is overridden
    for (const MeshPart& p : mesh.parts) EXPECT_EQ(p.material.s, 500.0f);
    EXPECT_EQ(mesh.parts[0].material.md, mdBefore);
    const Scene back = parseSceneJson(sceneToJson(s.scene), path);
    EXPECT_EQ(back.meshes[0].material.s, 500.0f);
}

// ---- Save / load ---------------------------------------------------------------------------------------

TEST(AppState, EditedSceneRoundTripsLosslessly) {
    ViewerState s = defaultState();
    setShininess(s, idOf(s, "gold"), 77.125f);
    applyPreset(s, idOf(s, "matte green"), *findMaterialPreset("jade"));
    setModel(s, ShadingModel::BlinnPhong);
    applyProgression(s, 3);
    setAmbient(s, glm::vec3(0.05f, 0.1f, 0.2f));
    const int li = addLight(s, LightType::Point);
    Light l = s.scene.lights[size_t(li)];
    l.color = joinIntensity({glm::vec3(1.0f, 0.5f, 0.25f), 3.0f});
    setLight(s, li, l);
    OrbitCamera o = s.orbit;
    orbitRotate(o, 0.3f, 0.1f);
    applyOrbit(s, o);

    const std::string json = sceneToJson(s.scene);
    const Scene back = parseSceneJson(json, "edited.json");
    EXPECT_EQ(sceneToJson(back), json);
    EXPECT_EQ(back.spheres[idOf(s, "gold") - 1].material.s, 77.125f);
    EXPECT_EQ(back.model, ShadingModel::BlinnPhong);
    EXPECT_FALSE(back.terms.shadows);
    EXPECT_EQ(back.lights.back().color, glm::vec3(3.0f, 1.5f, 0.75f));
    EXPECT_EQ(back.camera.position, s.scene.camera.position);
    // Negative control: the JSON does see a one-ulp change of one exponent.
    setShininess(s, idOf(s, "gold"), std::nextafter(77.125f, 100.0f));
    EXPECT_NE(sceneToJson(s.scene), json);
}

// ---- Camera --------------------------------------------------------------------------------------------

TEST(AppState, OrbitCameraRoundTripAndMotions) {
    ViewerState s = defaultState();
    const Camera file = s.scene.camera;
    const Camera c = cameraFromOrbit(orbitFromCamera(file));
    EXPECT_NEAR(glm::length(c.position - file.position), 0.0f, 1e-5f);
    EXPECT_EQ(c.target, file.target);
    OrbitCamera o = s.orbit;
    orbitRotate(o, 0.5f, 0.2f);
    applyOrbit(s, o);
    EXPECT_NEAR(glm::length(s.scene.camera.position - s.scene.camera.target), s.orbit.distance, 1e-4f);
    EXPECT_GT(glm::length(s.scene.camera.position - file.position), 0.5f);
    orbitRotate(o, 0.0f, 10.0f);
    EXPECT_LE(o.pitch, kMaxPitch);
    const float d = o.distance;
    orbitZoom(o, 1.0f);
    EXPECT_NEAR(o.distance, 0.85f * d, 1e-5f);
    const glm::vec3 t = o.target;
    orbitPan(o, 100.0f, 0.0f, 720.0f);
    EXPECT_GT(glm::length(o.target - t), 0.0f);
    resetCamera(s);
    EXPECT_EQ(s.scene.camera.position, file.position);  // exact: R restores the file's camera
    frameAll(s);
    EXPECT_NE(s.scene.camera.position, file.position);
}

// ---- Probe ---------------------------------------------------------------------------------------------

TEST(AppState, ProbeOnSphereEqualsSharedShading) {
    ViewerState s = defaultState();
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    const Sphere& sphere = s.scene.spheres[green - 1];
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center + glm::vec3(0.3f, 0.3f, 0.0f));
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    EXPECT_EQ(p.objectId, green);
    EXPECT_EQ(p.kind, ObjectKind::Sphere);

    // Independently: the same ray, hit and vectors from the shared functions.
    const ViewSetup v = makeViewSetup(s.scene, w, h);
    const glm::vec3 dir = shading::cameraRayDirection(v.forward, v.right, v.up, v.tanHalfFovY, float(w), float(h),
                                                      px.x + 0.5f, px.y + 0.5f);
    const float t = shading::intersectSphere(v.eye, dir, sphere.center, sphere.radius, 0.0f);
    const glm::vec3 P = v.eye + t * dir;
    const glm::vec3 N = glm::normalize(shading::faceForward((P - sphere.center) / sphere.radius, -dir));
    ASSERT_EQ(p.lights.size(), s.scene.lights.size());
    glm::vec3 sum = shading::shadeAmbient(s.scene.ambient, sphere.material.ma, true);
    for (size_t i = 0; i < s.scene.lights.size(); ++i) {
        const glm::vec3 L = glm::normalize(s.scene.lights[i].position - P);
        EXPECT_NEAR(p.lights[i].NoL, glm::dot(N, L), 1e-6f) << i;
        EXPECT_NEAR(p.lights[i].RoV, glm::dot(shading::reflectLight(N, L), -dir), 1e-5f) << i;
        sum += shading::shadeLight(N, L, -dir, s.scene.lights[i].color, sphere.material.md, sphere.material.ms,
                                   sphere.material.s, shading::SL_MODEL_PHONG, true, true);
        // The per-light terms add up to the light's contribution.
        const glm::vec3 parts = p.lights[i].diffuse + p.lights[i].specularPhong;
        EXPECT_NEAR(glm::length(parts - shading::shadeLight(N, L, -dir, s.scene.lights[i].color, sphere.material.md,
                                                            sphere.material.ms, sphere.material.s, 0, true, true)),
                    0.0f, 1e-6f);
    }
    EXPECT_NEAR(glm::length(p.totalPhong - sum), 0.0f, 1e-5f);
    // Negative control: a pixel 40 to the left sees a different normal.
    const ProbeResult q = probePixel(trace::TraceScene(s.scene), w, h, px.x - 40, px.y);
    EXPECT_GT(std::fabs(q.lights[0].NoL - p.lights[0].NoL), 1e-3f);
    // The report carries the numbers.
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_EQ(j["object"]["id"], green);
    EXPECT_NEAR(j["lights"][0]["NoL"].get<float>(), p.lights[0].NoL, 1e-7f);
}

TEST(AppState, ProbeFindsPlanesMeshesAndBackground) {
    ViewerState s = defaultState();
    const ProbeResult floor = probePixel(trace::TraceScene(s.scene), 640, 360, 320, 350);
    EXPECT_TRUE(floor.hit);
    EXPECT_EQ(floor.kind, ObjectKind::Plane);
    const ProbeResult sky = probePixel(trace::TraceScene(s.scene), 640, 360, 320, 2);
    EXPECT_FALSE(sky.hit);
    const std::string path = test::sourcePath("assets/scenes/torus.json");
    ViewerState t = makeViewerState(loadScene(path), path);
    const Mesh& torus = t.scene.meshes[0];
    const Bounds b = torus.parts[0].geometry->bounds;
    // The near side of the tube, above the torus' centre.
    const glm::vec3 c = 0.5f * (b.lo + b.hi);
    const glm::ivec2 px = pixelOf(t.scene, 640, 360, glm::vec3(c.x, b.hi.y, c.z));
    const ProbeResult m = probePixel(trace::TraceScene(t.scene), 640, 360, px.x, px.y + 2);
    ASSERT_TRUE(m.hit);
    EXPECT_EQ(m.kind, ObjectKind::Mesh);
    EXPECT_GT(glm::dot(m.N, m.V), 0.0f);  // faces the viewer
}

// A floor point in a sphere's shadow: the probe's vis_l is the shadow ray's, and the totals hold only the
// ambient term; with shadows off (the negative control) the same pixel is lit.
TEST(AppState, ProbeReportsShadowRayVisibility) {
    Scene scene;
    scene.camera.position = {0.0f, 2.0f, 6.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.ambient = glm::vec3(0.1f);
    scene.planes.push_back(Plane{});
    scene.spheres.push_back({"blocker", {0.0f, 1.0f, 0.0f}, 0.5f, Material{}});
    Light above;
    above.position = {0.0f, 5.0f, 0.0f};
    scene.lights.push_back(above);
    const int w = 320, h = 180;
    const glm::ivec2 under = pixelOf(scene, w, h, glm::vec3(0.0f, 0.0f, 0.0f));
    const ProbeResult shadowed = probePixel(trace::TraceScene(scene), w, h, under.x, under.y);
    ASSERT_TRUE(shadowed.hit);
    ASSERT_EQ(shadowed.kind, ObjectKind::Plane);
    EXPECT_EQ(shadowed.lights[0].visibility, 0.0f);
    EXPECT_EQ(shadowed.lights[0].diffuse, glm::vec3(0.0f));
    EXPECT_NEAR(glm::length(shadowed.totalPhong - shadowed.ambient), 0.0f, 1e-7f);
    const glm::ivec2 aside = pixelOf(scene, w, h, glm::vec3(2.0f, 0.0f, 0.0f));
    EXPECT_EQ(probePixel(trace::TraceScene(scene), w, h, aside.x, aside.y).lights[0].visibility, 1.0f);
    scene.terms.shadows = false;
    const ProbeResult lit = probePixel(trace::TraceScene(scene), w, h, under.x, under.y);
    EXPECT_EQ(lit.lights[0].visibility, 1.0f);
    EXPECT_GT(lit.totalPhong.r, shadowed.totalPhong.r + 0.1f);
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(shadowed, scene, shadowed.objectId));
    EXPECT_EQ(j["lights"][0]["visibility"].get<float>(), 0.0f);
}

// ---- Equivalent Blinn exponent -------------------------------------------------------------------------

TEST(AppState, EquivalentBlinnExponentMatchesHalfMaximum) {
    for (float s : {1.0f, 4.0f, 32.0f, 200.0f, 2048.0f}) {
        const float sb = equivalentBlinnExponent(s);
        const double halfAngle = std::acos(std::pow(0.5, 1.0 / s));  // Phong's half maximum
        EXPECT_NEAR(std::pow(std::cos(halfAngle / 2.0), double(sb)), 0.5, 1e-4) << s;
        EXPECT_NEAR(equivalentPhongExponent(sb), s, 1e-3f * s) << s;
        // Better than the classic 4s everywhere, and much better than the same exponent (negative control).
        EXPECT_LT(lobeRmsDifference(s, sb), lobeRmsDifference(s, fourTimesRule(s))) << s;
        EXPECT_GT(lobeRmsDifference(s, s), 5.0f * lobeRmsDifference(s, sb)) << s;
    }
    EXPECT_NEAR(equivalentBlinnExponent(512.0f), 4.0f * 512.0f + std::log(2.0f), 0.01f);
    EXPECT_EQ(equivalentBlinnExponent(0.0f), 0.0f);
    EXPECT_EQ(equivalentPhongExponent(1.5f), 0.0f);
    const std::vector<float> lobe = phongLobe(8.0f, 91);
    EXPECT_EQ(lobe.front(), 1.0f);
    EXPECT_NEAR(lobe.back(), 0.0f, 1e-6f);
}

// ---- Lobe plots (issues 12 and 15) ----------------------------------------------------------------------

namespace {

// The axis the lobe plot used before issue 15: four times Phong's half-maximum angle, within [5, 90] degrees.
// Its curve looked the same for every s >= 32 (the negative control below).
float oldRescaledAxis(float s) {
    const double halfMax = std::acos(std::exp2(-1.0 / double(s))) * 180.0 / M_PI;
    return float(std::clamp(4.0 * halfMax, 5.0, 90.0));
}

// True when every width is smaller than the one before.
bool strictlyShrinking(const std::vector<float>& widths) {
    for (size_t i = 1; i < widths.size(); ++i)
        if (!(widths[i] < widths[i - 1])) return false;
    return true;
}

const float kExponents[] = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048};

}  // namespace

TEST(LobePlot, HalfWidthReadFromTheDataShrinksAsShininessGrows) {
    // What the panel draws on its fixed 0..90° axis: the half-width, as a fraction of the plot's width, must
    // shrink at every step from s = 1 to 2048, for each lecture lobe.
    for (LobeModel m : {LobeModel::Phong, LobeModel::BlinnSame, LobeModel::BlinnEquivalent}) {
        std::vector<float> screen;
        for (float s : kExponents) {
            LobePlotSettings settings;
            settings.phongExponent = s;
            const LobePlot plot = makeLobePlot(settings);
            ASSERT_EQ(plot.curves[size_t(m)].value.size(), size_t(settings.samples));
            const float hwhm = halfWidthAtHalfMaximum(plot.curves[size_t(m)].value, plot.settings.axis);
            screen.push_back(hwhm / plot.settings.axis);
            if (m == LobeModel::Phong) {  // the closed form: cos(a)^s = 1/2
                EXPECT_NEAR(hwhm, std::acos(std::exp2(-1.0 / s)) * 180.0 / M_PI, 0.05) << s;
            }
        }
        // Blinn-Phong at the same s = 1 and 2 stays above half beyond 90° (cos(a/2)^s = 1/2 at a = 120°, 90°):
        // it is checked from s = 4 on.
        if (m == LobeModel::BlinnSame) screen.erase(screen.begin(), screen.begin() + 2);
        EXPECT_TRUE(strictlyShrinking(screen)) << "model " << int(m) << ": " << testing::PrintToString(screen);
        EXPECT_LT(screen.back(), m == LobeModel::BlinnSame ? 0.04f : 0.02f) << "s = 2048 must look narrow on screen";
    }
    // Equivalent exponents give Phong's half-width (the rule of specular_lobe.h), same exponents a wider one.
    LobePlotSettings settings;
    settings.phongExponent = 64.0f;
    const LobePlot plot = makeLobePlot(settings);
    const auto hw = [&](LobeModel m) { return halfWidthAtHalfMaximum(plot.curves[size_t(m)].value, 90.0f); };
    EXPECT_NEAR(hw(LobeModel::BlinnEquivalent), hw(LobeModel::Phong), 0.05f);
    EXPECT_GT(hw(LobeModel::BlinnSame), 1.8f * hw(LobeModel::Phong));
}

TEST(LobePlot, TheOldRescaledAxisAndAConstantLobeFailTheCheck) {
    // Negative controls for the check above: on the old axis the on-screen width stopped shrinking at s = 32,
    // and a lobe that never changes cannot shrink.
    std::vector<float> rescaled, constant;
    for (float s : kExponents) {
        LobePlotSettings settings;
        settings.phongExponent = s;
        settings.axis = oldRescaledAxis(s);
        const LobePlot plot = makeLobePlot(settings);
        rescaled.push_back(halfWidthAtHalfMaximum(plot.curves[0].value, plot.settings.axis) / plot.settings.axis);
        LobePlotSettings fixed;
        fixed.phongExponent = 32.0f;
        const LobePlot same = makeLobePlot(fixed);
        constant.push_back(halfWidthAtHalfMaximum(same.curves[0].value, 90.0f) / 90.0f);
    }
    EXPECT_FALSE(strictlyShrinking(rescaled));
    EXPECT_FALSE(strictlyShrinking(constant));
    EXPECT_NEAR(rescaled[6], rescaled.back(), 0.01f);  // s = 64 and 2048 looked alike
}

TEST(LobePlot, PolarLobesPeakAtTheMirrorDirectionAndNarrowWithRoughness) {
    LobePlotSettings settings;
    settings.incidence = 40.0f;
    settings.phongExponent = 50.0f;
    settings.roughness = 0.3f;
    const LobePlot plot = makeLobePlot(settings);
    for (const LobeCurve& c : plot.curves) {
        size_t best = 0;
        for (size_t i = 0; i < c.polar.size(); ++i)
            if (c.polar[i] > c.polar[best]) best = i;
        EXPECT_NEAR(plot.polarAngleAt(int(best)), 40.0f, 3.0f) << c.label;
        EXPECT_NEAR(c.polar[best], 1.0f, 1e-6f) << c.label;
        EXPECT_GT(c.peak, 0.0f) << c.label;
    }
    // The pbr lobe narrows as roughness falls (its half-width read from the Cartesian data).
    std::vector<float> widths;
    for (float r : {1.0f, 0.7f, 0.5f, 0.3f, 0.2f, 0.1f}) {
        settings.roughness = r;
        const LobePlot p = makeLobePlot(settings);
        widths.push_back(halfWidthAtHalfMaximum(p.curves[size_t(LobeModel::Pbr)].value, 90.0f));
    }
    EXPECT_TRUE(strictlyShrinking(widths));
    // The probe's vectors in the plane of incidence: L on the left, R its mirror, V out of the plane.
    const glm::vec3 N(0, 1, 0), L = glm::normalize(glm::vec3(-1, 1, 0)), V = glm::normalize(glm::vec3(0.5f, 1, 0.5f));
    const PlaneOfIncidence pi = planeOfIncidence(N, L, V);
    EXPECT_NEAR(pi.incidence, 45.0f, 1e-3f);
    EXPECT_NEAR(pi.L.x, -pi.R.x, 1e-6f);
    EXPECT_LT(pi.L.x, 0.0f);
    EXPECT_NEAR(pi.vOutOfPlane, std::asin(0.5f / glm::length(glm::vec3(0.5f, 1, 0.5f))) * 180.0f / M_PI, 1e-3f);
}

TEST(AlbedoPlot, CurvesTellWhichModelsKeepTheirEnergy) {
    AlbedoPlotSettings settings;
    settings.phongExponent = 64.0f;
    settings.roughness = 1.0f;
    const AlbedoPlot plot = makeAlbedoPlot(settings);
    ASSERT_EQ(plot.curves.size(), 7u);
    for (float v : plot.curves[0].albedo) EXPECT_NEAR(v, 1.0f, 3e-3f);  // Lambert
    EXPECT_NEAR(plot.curves[1].albedo.front(), 2.0f / 65.0f, 2e-3f);    // Phong: 2/(s+1)
    EXPECT_NEAR(plot.curves[2].albedo.front(), 66.0f / 65.0f, 5e-3f);   // normalised
    for (float v : plot.curves[5].albedo) EXPECT_LT(v, 0.999f);         // GGX loses
    // With compensation a white metal keeps its energy (issue 12: within 1 %), away from grazing angles.
    EXPECT_EQ(plot.curves[6].label, "GGX  compensated");
    for (size_t i = 0; i < plot.viewAngles.size(); ++i)
        if (plot.viewAngles[i] <= 75.0f) {
            EXPECT_NEAR(plot.curves[6].albedo[i], 1.0f, 0.015f) << plot.viewAngles[i];
        }
    // The hook: a curve from any shade function.
    AlbedoPlot copy = plot;
    addAlbedoCurve(copy, "half Lambert",
                   [](const shading::vec3& L, const shading::vec3&) { return 0.5f * std::max(L.z, 0.0f); });
    EXPECT_NEAR(copy.curves.back().albedo[3], 0.5f, 2e-3f);
}

// ---- White furnace --------------------------------------------------------------------------------------

TEST(AppState, WhiteFurnaceOnAndOffRestoresTheScene) {
    ViewerState s = defaultState();
    const std::string before = sceneToJson(s.scene);
    const uint64_t revision = s.revision;
    setWhiteFurnace(s, true);
    EXPECT_TRUE(whiteFurnaceOn(s));
    EXPECT_GT(s.revision, revision);
    EXPECT_EQ(sceneToJson(s.scene), sceneToJson(whiteFurnaceScene(*s.beforeFurnace)));
    EXPECT_NE(sceneToJson(s.scene), before);
    setWhiteFurnace(s, true);  // no-op
    setWhiteFurnace(s, false);
    EXPECT_FALSE(whiteFurnaceOn(s));
    EXPECT_EQ(sceneToJson(s.scene), before);
    // Through a script, and opening a scene leaves the furnace.
    const Script sc = parse(R"([{"action": "whiteFurnace"}, {"action": "whiteFurnace", "on": false}])");
    applyScriptAction(s, sc.actions[0], "actions.json");
    EXPECT_TRUE(whiteFurnaceOn(s));
    EXPECT_TRUE(s.scene.lights.empty());
    applyScriptAction(s, sc.actions[1], "actions.json");
    EXPECT_EQ(sceneToJson(s.scene), before);
    setWhiteFurnace(s, true);
    openScene(s, loadScene(test::sourcePath("assets/scenes/torus.json")), "torus.json");
    EXPECT_FALSE(whiteFurnaceOn(s));
}

TEST(AppState, ProbePbrColumnEqualsSharedShading) {
    ViewerState s = defaultState();
    setModel(s, ShadingModel::Pbr);
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    Sphere& sphere = s.scene.spheres[green - 1];
    sphere.material.metallic = 0.3f;
    sphere.material.roughness = 0.35f;
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center + glm::vec3(0.3f, 0.3f, 0.0f));
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    const Material& m = sphere.material;
    const shading::SurfaceParams sp =
        shading::surfaceParams(shading::SL_MODEL_PBR, m.ma, m.md, m.ms, m.s, m.baseColor, m.metallic, m.roughness);
    EXPECT_EQ(p.pbrDiffuseColor, sp.md);
    EXPECT_EQ(p.pbrF0, sp.ms);
    glm::vec3 sum = p.ambient;
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const ProbeLight& l = p.lights[i];
        const glm::vec3 one =
            shading::shadeLight(p.N, l.L, p.V, l.Il, sp.md, sp.ms, sp.s, shading::SL_MODEL_PBR, true, true);
        EXPECT_NEAR(glm::length(l.diffusePbr + l.specularPbr - l.visibility * one), 0.0f, 1e-5f) << i;
        // D·Vis·F is the specular BRDF: π · f · N·L · Il is the specular part.
        const glm::vec3 spec = shading::SL_PI * l.D * l.Vis * l.F * std::max(l.NoL, 0.0f) * l.Il * l.visibility;
        EXPECT_NEAR(glm::length(spec - l.specularPbr), 0.0f, 1e-4f * std::max(1.0f, glm::length(spec))) << i;
        sum += l.diffusePbr + l.specularPbr;
    }
    EXPECT_NEAR(glm::length(p.totalPbr - sum), 0.0f, 1e-5f);
    EXPECT_GT(glm::length(p.totalPbr - p.totalPhong), 1e-3f) << "control: pbr is not Phong here";
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_NEAR(j["total"]["pbr"][0].get<float>(), p.totalPbr.x, 1e-6f);
    EXPECT_NEAR(j["lights"][0]["D"].get<float>(), p.lights[0].D, 1e-6f);
    EXPECT_EQ(j["model"], "pbr");

    // On the checker floor the tile's colour is pbr's base colour, as in the integrator (F0 stays the plane's).
    const Plane& floor = s.scene.planes[0];
    ASSERT_TRUE(floor.checker.has_value());
    int seen[2] = {0, 0};
    for (int x = 0; x < w && (!seen[0] || !seen[1]); x += 7) {
        const ProbeResult f = probePixel(trace::TraceScene(s.scene), w, h, x, h - 5);
        if (!f.hit || f.kind != ObjectKind::Plane) continue;
        const int parity = shading::checkerParity(f.P, floor.normal, floor.checker->size);
        const glm::vec3 base = parity == 1 ? floor.checker->md2 : floor.material.baseColor;
        EXPECT_EQ(f.pbrDiffuseColor, shading::pbrDiffuseColor(base, floor.material.metallic)) << x;
        EXPECT_EQ(f.pbrF0, shading::pbrF0(floor.material.baseColor, floor.material.metallic)) << x;
        ++seen[parity];
    }
    EXPECT_TRUE(seen[0] && seen[1]) << "both kinds of tile";
    EXPECT_NE(floor.checker->md2, floor.material.baseColor) << "control: the tiles differ";
}

TEST(AppState, ProbeTotalsEqualTheIntegratorsLocalTermsUnderEveryModel) {
    // The probe explains the reference's pixel: its total for the scene's model is the integrator's own local
    // term (reflections are not in the probe's numbers), on spheres and on both kinds of checker tile.
    ViewerState s = defaultState();
    s.scene.spheres[0].material.metallic = 0.6f;
    s.scene.spheres[0].material.roughness = 0.3f;
    const int w = 96, h = 54;
    for (const ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
        for (const bool normalized : {false, true}) {
            SCOPED_TRACE(std::string(toString(model)) + (normalized ? " normalized" : ""));
            Scene scene = s.scene;
            scene.model = model;
            scene.normalized = normalized;
            const trace::TraceScene ts(scene);
            const trace::WhittedIntegrator integrator(ts, 0);
            const ViewSetup view = makeViewSetup(scene, w, h);
            int checked = 0, otherDiffers = 0;
            for (int y = 1; y < h; y += 4)
                for (int x = 1; x < w; x += 4) {
                    const trace::Ray ray = trace::sampleRay(view, 1, x, y, 0, 0);
                    const std::optional<trace::Hit> hit = ts.intersect(ray);
                    if (!hit) continue;
                    const glm::vec3 expected = integrator.local(ray, integrator.surfaceAt(ray, *hit));
                    const ProbeResult p = probePixel(ts, w, h, x, y);
                    const glm::vec3 total = model == ShadingModel::Phong        ? p.totalPhong
                                            : model == ShadingModel::BlinnPhong ? p.totalBlinn
                                                                                : p.totalPbr;
                    const glm::vec3 other = model == ShadingModel::Pbr ? p.totalPhong : p.totalPbr;
                    EXPECT_NEAR(glm::length(total - expected), 0.0f, 1e-5f * std::max(1.0f, glm::length(expected)))
                        << x << "," << y;
                    otherDiffers += glm::length(other - expected) > 1e-3f;
                    ++checked;
                }
            EXPECT_GT(checked, 150);
            EXPECT_GT(otherDiffers, checked / 4) << "control: another model's column is not the image";
        }
    }
}

// ---- Scripts -------------------------------------------------------------------------------------------

TEST(AppScript, ParsesFramesAndActions) {
    const Script sc = parse(R"({"actions": [
        {"action": "setShininess", "object": "gold", "s": 128},
        {"action": "setTerm", "term": "specular", "on": false},
        {"frame": 5, "action": "setModel", "model": "blinn-phong"},
        {"action": "probe", "x": 10, "y": 20},
        {"frame": 9, "action": "screenshot", "path": "a.png"}
    ]})");
    ASSERT_EQ(sc.actions.size(), 5u);
    EXPECT_EQ(sc.actions[0].frame, 0);
    EXPECT_EQ(sc.actions[1].frame, 0);
    EXPECT_EQ(sc.actions[2].frame, 5);
    EXPECT_EQ(sc.actions[3].frame, 5);
    EXPECT_EQ(sc.lastFrame(), 9);
    EXPECT_FALSE(isStateAction(sc.actions[4]));
    ScriptCursor cursor(sc);
    int dueAtZero = 0;
    while (cursor.next(0)) ++dueAtZero;
    EXPECT_EQ(dueAtZero, 2);
    EXPECT_EQ(cursor.next(4), nullptr);
    EXPECT_NE(cursor.next(5), nullptr);

    ViewerState a = defaultState(), b = defaultState();
    for (const ScriptAction& act : sc.actions)
        if (isStateAction(act)) applyScriptAction(a, act, sc.file);
    setShininess(b, idOf(b, "gold"), 128.0f);
    setTerm(b, Term::Specular, false);
    setModel(b, ShadingModel::BlinnPhong);
    setProbe(b, 10, 20);
    EXPECT_EQ(sceneToJson(a.scene), sceneToJson(b.scene));
    EXPECT_TRUE(a.probe.active);
    EXPECT_EQ(a.probe.y, 20);
    // A bare list works too.
    EXPECT_EQ(parse(R"([{"action": "frameAll"}])").actions.size(), 1u);
}

TEST(AppScript, ActionsAreParsedOnceIntoTypedFields) {
    const Script sc = parse(R"([
        {"action": "setTerm", "term": "shadows", "on": false},
        {"action": "switchModel", "model": "blinn", "all": true},
        {"action": "setMode", "mode": "difference"},
        {"action": "setEncoding", "encoding": "linear"},
        {"action": "addLight", "type": "directional", "direction": [0, -2, 0]},
        {"action": "setMaterial", "object": 2, "s": 7, "kr": 0.5},
        {"action": "resizeWindow", "width": 640, "height": 480}
    ])");
    ASSERT_EQ(sc.actions.size(), 7u);
    const auto& term = std::get<actions::SetTerm>(sc.actions[0].action);
    EXPECT_EQ(term.term, Term::Shadows);
    EXPECT_FALSE(term.on);
    const auto& model = std::get<actions::SwitchModel>(sc.actions[1].action);
    EXPECT_EQ(model.model, ShadingModel::BlinnPhong) << "blinn is the table's alias, as on the command line";
    EXPECT_TRUE(model.allObjects);
    EXPECT_EQ(std::get<actions::SetMode>(sc.actions[2].action).mode, ViewMode::Difference);
    EXPECT_EQ(std::get<actions::SetEncoding>(sc.actions[3].action).encoding, Encoding::Linear);
    const auto& light = std::get<actions::AddLight>(sc.actions[4].action);
    EXPECT_EQ(light.type, LightType::Directional);
    EXPECT_EQ(light.light.direction, glm::vec3(0, -1, 0)) << "the scene file's unit-vector reader";
    EXPECT_FALSE(light.light.position.has_value());
    const auto& material = std::get<actions::SetMaterial>(sc.actions[5].action);
    EXPECT_EQ(material.object, "#2");
    EXPECT_EQ(material.material.s, 7.0f);
    EXPECT_EQ(material.material.kr, glm::vec3(0.5f));
    EXPECT_FALSE(material.material.md.has_value());
    EXPECT_FALSE(isStateAction(sc.actions[6]));
    EXPECT_EQ(std::get<actions::ResizeWindow>(sc.actions[6].action).height, 480);
    // Words outside a table are refused at their path, listing the table.
    EXPECT_EQ(parseError(R"([{"action": "setMode", "mode": "both"}])"),
              "actions.json: actions[0].mode: unknown view mode 'both'; expected raster, traced, split, difference, global or local-global");
    EXPECT_EQ(parseError(R"([{"action": "setEncoding", "encoding": "gamma"}])"),
              "actions.json: actions[0].encoding: unknown encoding 'gamma'; expected srgb or linear");
    EXPECT_EQ(parseError(R"([{"action": "addLight", "type": "spot"}])"),
              "actions.json: actions[0].type: unknown light type 'spot'; expected point or directional");
}

TEST(AppScript, SetRasterChangesOnlyTheFieldsGiven) {
    const Script sc = parse(R"([{"action": "setRaster", "shadowMapSize": 512, "pcf": true},
                                {"action": "setRaster", "shadowMapSize": "auto", "normalBias": 0.75},
                                {"action": "setRaster", "depthBias": 2, "reflectionCubeSize": 64}])");
    ASSERT_EQ(sc.actions.size(), 3u);
    EXPECT_TRUE(isStateAction(sc.actions[0]));
    ViewerState a = defaultState(), b = defaultState();
    applyScriptAction(a, sc.actions[0], sc.file);
    EXPECT_EQ(a.scene.raster.shadowMapSize, 512);
    EXPECT_TRUE(a.scene.raster.pcf);
    EXPECT_EQ(a.scene.raster.depthBias, RasterSettings{}.depthBias);
    applyScriptAction(a, sc.actions[1], sc.file);
    applyScriptAction(a, sc.actions[2], sc.file);
    setRasterSettings(b, RasterSettings{0, 2.0f, 0.75f, true, 64});
    EXPECT_EQ(sceneToJson(a.scene), sceneToJson(b.scene));
    // The viewer's moving preview (on by default, the control) is switched like the others.
    const Script off = parse(R"([{"action": "setRaster", "movingPreview": false}])");
    ViewerState c = defaultState();
    EXPECT_TRUE(c.scene.raster.movingPreview);
    applyScriptAction(c, off.actions[0], off.file);
    EXPECT_FALSE(c.scene.raster.movingPreview);
    EXPECT_EQ(c.scene.raster.pcf, RasterSettings{}.pcf);
    // Errors name the field as the scene file's do; a field of another action is refused.
    EXPECT_EQ(parseError(R"([{"action": "setRaster", "shadowMapSize": 5}])"),
              "actions.json: actions[0].shadowMapSize: expected \"auto\" or an integer in 16..8192, got 5");
    EXPECT_NE(parseError(R"([{"action": "setRaster", "reflectionCubeSize": 4096}])")
                  .find("actions[0].reflectionCubeSize: must be in [8, 2048]"),
              std::string::npos);
    EXPECT_NE(parseError(R"([{"action": "setRaster", "pcf": "on"}])").find("actions[0].pcf: expected true or false"),
              std::string::npos);
    EXPECT_NE(parseError(R"([{"action": "setRaster", "s": 3}])").find("actions[0].s: not a field of 'setRaster'"),
              std::string::npos);
}

TEST(AppScript, ErrorsNameTheFileAndTheAction) {
    EXPECT_EQ(parseError(R"([{"action": "frameAll"}, {"action": "setShine", "s": 1}])"),
              "actions.json: actions[1].action: unknown action 'setShine' (docs/viewer.md lists them)");
    EXPECT_NE(
        parseError(R"([{"action": "setTerm", "term": "spec", "on": true}])").find("actions.json: actions[0].term:"),
        std::string::npos);
    EXPECT_NE(parseError(R"([{"action": "setShininess", "object": "gold"}])").find("actions[0].s: "),
              std::string::npos);
    EXPECT_NE(parseError(R"([{"frame": 3, "action": "frameAll"}, {"frame": 1, "action": "frameAll"}])")
                  .find("actions[1].frame: frames must not decrease"),
              std::string::npos);
    EXPECT_NE(parseError(R"([{"action": "probe", "x": 1, "y": 2, "z": 3}])").find("actions[0].z: not a field"),
              std::string::npos);
    EXPECT_NE(parseError("[{").find("actions.json: line"), std::string::npos);
    EXPECT_EQ(parseError(R"([{"action": "setMode", "mode": "split"}])"), "(no error)");  // negative control

    ViewerState s = defaultState();
    const Script sc = parse(R"([{"action": "frameAll"}, {"action": "select", "object": "teapot"}])");
    try {
        applyScriptAction(s, sc.actions[1], sc.file);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("actions.json: actions[1].object: no object 'teapot'"), std::string::npos)
            << e.what();
    }
    const Script rm = parse(R"([{"action": "removeLight", "index": 7}])");
    EXPECT_THROW(applyScriptAction(s, rm.actions[0], rm.file), InputError);
}
