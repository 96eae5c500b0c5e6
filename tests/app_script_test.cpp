// Viewer scripts, no window: frames and actions parse once into typed fields, setRaster changes
// only what it names, and errors name the file and the action.
#include "app/script.h"
#include "app/viewer_state.h"
#include "app_test_util.h"
#include "scene/scene_json.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadelab;
using namespace shadelab::app;
using namespace shadelab::test;

namespace {

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
              "actions.json: actions[0].mode: unknown view mode 'both'; expected raster, traced, split, difference, "
              "global or local-global");
    EXPECT_EQ(parseError(R"([{"action": "setEncoding", "encoding": "gamma"}])"),
              "actions.json: actions[0].encoding: unknown encoding 'gamma'; expected srgb or linear");
    EXPECT_EQ(parseError(R"([{"action": "addLight", "type": "area"}])"),
              "actions.json: actions[0].type: unknown light type 'area'; expected point, directional or spot");
    EXPECT_EQ(parseError(R"([{"action": "addLight", "type": "spot", "outerConeAngle": 2}])"),
              "actions.json: actions[0].outerConeAngle: must be in [0, 1.5708], got 2");
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

// setGlobal: the Global modes' light paths and denoised preview, each field given changing only itself; a view
// choice, not an edit and nothing a renderer restarts for (the light paths restart the path tracer through
// the request, not the revision).
TEST(AppScript, SetGlobalChangesOnlyTheFieldsGiven) {
    const Script sc = parse(R"([{"action": "setGlobal", "denoise": false},
                                {"action": "setGlobal", "lightPaths": "indirect"},
                                {"action": "setGlobal", "lightPaths": "all", "denoise": true}])");
    ASSERT_EQ(sc.actions.size(), 3u);
    EXPECT_TRUE(isStateAction(sc.actions[0]));
    ViewerState a = defaultState();
    EXPECT_TRUE(a.globalDenoise) << "the viewer shows the denoised preview by default";
    const uint64_t revision = a.revision, edits = a.editRevision;
    applyScriptAction(a, sc.actions[0], sc.file);
    EXPECT_FALSE(a.globalDenoise);
    EXPECT_EQ(a.globalPart, trace::PathPart::All);
    applyScriptAction(a, sc.actions[1], sc.file);
    EXPECT_FALSE(a.globalDenoise);
    EXPECT_EQ(a.globalPart, trace::PathPart::Indirect);
    applyScriptAction(a, sc.actions[2], sc.file);
    EXPECT_TRUE(a.globalDenoise);
    EXPECT_EQ(a.globalPart, trace::PathPart::All);
    EXPECT_EQ(a.revision, revision);
    EXPECT_EQ(a.editRevision, edits);
    EXPECT_EQ(parseError(R"([{"action": "setGlobal", "denoise": 1}])"),
              "actions.json: actions[0].denoise: expected true or false, got number");
    EXPECT_EQ(parseError(R"([{"action": "setGlobal", "lightPaths": "some"}])"),
              "actions.json: actions[0].lightPaths: unknown light paths 'some'; expected all, direct or indirect");
}

// A spot light added and re-aimed by script, its cone and range read as the scene file reads them; an inner
// angle past the outer one is refused at the action's field and leaves the lights as they were.
TEST(AppScript, SpotLightsAreAddedAndEditedWithTheirCones) {
    ViewerState s = defaultState();
    const size_t before = s.scene.lights.size();
    const Script sc = parse(R"([{"action": "addLight", "type": "spot", "position": [0, 4, 0],
        "direction": [0, -1, 0], "innerConeAngle": 0.2, "outerConeAngle": 0.4, "range": 6},
        {"action": "setLight", "index": 0, "outerConeAngle": 0.5},
        {"action": "setLight", "index": 0, "innerConeAngle": 0.9},
        {"action": "addLight", "type": "spot", "innerConeAngle": 1.0}])");
    ASSERT_EQ(sc.actions.size(), 4u);
    applyScriptAction(s, sc.actions[0], sc.file);
    ASSERT_EQ(s.scene.lights.size(), before + 1);
    const Light& spot = s.scene.lights.back();
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_EQ(spot.position, glm::vec3(0, 4, 0));
    EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.2f);
    EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.4f);
    EXPECT_FLOAT_EQ(spot.range, 6.0f);
    std::swap(s.scene.lights.front(), s.scene.lights.back());  // the spot is light 0 for the setLight actions
    applyScriptAction(s, sc.actions[1], sc.file);
    EXPECT_FLOAT_EQ(s.scene.lights[0].outerConeAngle, 0.5f);
    try {
        applyScriptAction(s, sc.actions[2], sc.file);
        FAIL() << "an inner angle past the outer one was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("actions[2].innerConeAngle: must not exceed outerConeAngle"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FLOAT_EQ(s.scene.lights[0].innerConeAngle, 0.2f);
    EXPECT_THROW(applyScriptAction(s, sc.actions[3], sc.file), InputError);  // 1.0 past the default π/4
    EXPECT_EQ(s.scene.lights.size(), before + 1) << "a refused addLight left a light behind";
}

// setDisplay: each field given changes the scene's display and the rest stay; an edit undo steps over (not a
// change a renderer sees); refused values name the action's field.
TEST(AppScript, SetDisplayChangesOnlyTheFieldsGiven) {
    const Script sc = parse(R"([{"action": "setDisplay", "viewTransform": "filmic"},
                                {"action": "setDisplay", "exposure": -2.5},
                                {"action": "setDisplay", "exposure": 0, "viewTransform": "standard"}])");
    ASSERT_EQ(sc.actions.size(), 3u);
    EXPECT_TRUE(isStateAction(sc.actions[0]));
    ViewerState a = defaultState();
    const uint64_t revision = a.revision, edits = a.editRevision;
    applyScriptAction(a, sc.actions[0], sc.file);
    EXPECT_EQ(a.scene.display, (DisplaySettings{0.0, ViewTransform::Filmic}));
    applyScriptAction(a, sc.actions[1], sc.file);
    EXPECT_EQ(a.scene.display, (DisplaySettings{-2.5, ViewTransform::Filmic}));
    EXPECT_EQ(a.revision, revision) << "the display is not something a renderer redraws for";
    EXPECT_EQ(a.editRevision, edits + 2) << "each change is an edit undo steps over";
    EXPECT_NE(sceneToJson(a.scene).find("\"viewTransform\": \"filmic\""), std::string::npos) << "Save keeps it";
    applyScriptAction(a, sc.actions[2], sc.file);
    EXPECT_TRUE(a.scene.display.isStandard());
    EXPECT_EQ(parseError(R"([{"action": "setDisplay", "exposure": 40}])"),
              "actions.json: actions[0].exposure: must be in [-16, 16] stops, got 40");
    EXPECT_EQ(parseError(R"([{"action": "setDisplay", "viewTransform": "aces"}])"),
              "actions.json: actions[0].viewTransform: unknown view transform 'aces'; expected standard or filmic");
    EXPECT_EQ(parseError(R"([{"action": "render", "path": "x.png", "exposure": -17}])"),
              "actions.json: actions[0].exposure: must be in [-16, 16] stops, got -17");
    // The panel's setter holds the exposure to its range (NaN: 0), as the slider does.
    ViewerState b = defaultState();
    setDisplay(b, DisplaySettings{99.0, ViewTransform::Standard});
    EXPECT_EQ(b.scene.display.exposure, kMaxExposure);
    setDisplay(b, DisplaySettings{std::nan(""), ViewTransform::Filmic});
    EXPECT_EQ(b.scene.display, (DisplaySettings{0.0, ViewTransform::Filmic}));
}
