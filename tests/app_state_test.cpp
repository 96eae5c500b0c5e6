// Viewer state tests, no window: every control action changes the scene as expected and
// nothing else, an edited scene survives a JSON round trip exactly, the orbit camera, and the white furnace
// switch. The probe, the plots and scripts have their own files (app_probe_test.cpp, app_plots_test.cpp,
// app_script_test.cpp) in the same test binary.
#include "app/material_presets.h"
#include "app/orbit_camera.h"
#include "app/script.h"
#include "app/specular_lobe.h"
#include "app/viewer_state.h"
#include "app_test_util.h"
#include "scene/scene_json.h"
#include "scene/scene_limits.h"
#include "scene/scene_load.h"
#include "scene/white_furnace.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

using namespace shadelab;
using namespace shadelab::app;
using namespace shadelab::test;

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
    const bool expected[6][5] = {{0, 0, 0, 0, 0}, {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0},
                                 {1, 1, 1, 0, 0}, {1, 1, 1, 1, 0}, {1, 1, 1, 1, 1}};
    for (int step = 0; step <= 5; ++step) {
        applyProgression(s, step);
        const Terms& t = s.scene.terms;
        EXPECT_EQ(t.ambient, expected[step][0]);
        EXPECT_EQ(t.diffuse, expected[step][1]);
        EXPECT_EQ(t.specular, expected[step][2]);
        EXPECT_EQ(t.shadows, expected[step][3]);
        EXPECT_EQ(t.reflections, expected[step][4]);
        EXPECT_EQ(progressionStep(t), step);
    }
    setTerm(s, Term::Ambient, false);  // all but ambient: not a step
    EXPECT_EQ(progressionStep(s.scene.terms), -1);
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
    // disney's parameters too (its panel sliders): the edited one only, on every part, and saved.
    m = objectMaterial(s.scene, torus);
    m.disney.sheen = 0.75f;
    ASSERT_TRUE(setObjectMaterial(s, torus, m));
    EXPECT_EQ(mesh.material.disney.value[4], 0.75f);  // kDisneyFields[4] is sheen
    EXPECT_FALSE(mesh.material.disney.value[0].has_value());
    for (const MeshPart& p : mesh.parts) EXPECT_EQ(p.material.disney.sheen, 0.75f);
    EXPECT_EQ(parseSceneJson(sceneToJson(s.scene), path).meshes[0].material.disney.value[4], 0.75f);
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
    // A script's zoom far out stays finite (0.85^-1000 is past a float), a hundred steps are not held back.
    OrbitCamera far = o;
    orbitZoom(far, -100.0f);
    EXPECT_NEAR(far.distance, o.distance * std::pow(0.85f, -100.0f), 1e-3f * far.distance);
    orbitZoom(far, -1e30f);
    EXPECT_EQ(far.distance, kMaxCoordinate);
    EXPECT_TRUE(std::isfinite(cameraFromOrbit(far).position.x));
    const glm::vec3 t = o.target;
    orbitPan(o, 100.0f, 0.0f, 720.0f);
    EXPECT_GT(glm::length(o.target - t), 0.0f);
    resetCamera(s);
    EXPECT_EQ(s.scene.camera.position, file.position);  // exact: R restores the file's camera
    frameAll(s);
    EXPECT_NE(s.scene.camera.position, file.position);
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
    const Script sc =
        parseScript(R"([{"action": "whiteFurnace"}, {"action": "whiteFurnace", "on": false}])", "actions.json");
    applyScriptAction(s, sc.actions[0], "actions.json");
    EXPECT_TRUE(whiteFurnaceOn(s));
    EXPECT_TRUE(s.scene.lights.empty());
    applyScriptAction(s, sc.actions[1], "actions.json");
    EXPECT_EQ(sceneToJson(s.scene), before);
    setWhiteFurnace(s, true);
    openScene(s, loadScene(test::sourcePath("assets/scenes/torus.json")), "torus.json");
    EXPECT_FALSE(whiteFurnaceOn(s));
}
