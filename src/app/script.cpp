// Script parsing (JSON through the scene loader's path-naming reader) and the state actions.
#include "app/script.h"

#include "app/material_presets.h"
#include "scene/json_reader.h"
#include "util/atomic_file.h"
#include "util/input_error.h"
#include "util/warning.h"

#include <cstdio>
#include <glm/trigonometric.hpp>

namespace shadelab::app {
namespace {

struct ActionInfo {
    const char* name;
    ActionKind kind;
    std::initializer_list<const char*> fields;   // besides "action" and "frame"
};

const ActionInfo kActions[] = {
    {"setShininess", ActionKind::SetShininess, {"object", "s"}},
    {"setMaterial", ActionKind::SetMaterial, {"object", "ma", "md", "ms", "s", "kr", "kt", "ior"}},
    {"preset", ActionKind::Preset, {"object", "name"}},
    {"select", ActionKind::Select, {"object"}},
    {"setTerm", ActionKind::SetTerm, {"term", "on"}},
    {"toggleTerm", ActionKind::ToggleTerm, {"term"}},
    {"progression", ActionKind::Progression, {"step"}},
    {"setModel", ActionKind::SetModel, {"model"}},
    {"switchModel", ActionKind::SwitchModel, {"model", "all"}},
    {"setMode", ActionKind::SetMode, {"mode"}},
    {"setEncoding", ActionKind::SetEncoding, {"encoding"}},
    {"setSplit", ActionKind::SetSplit, {"position"}},
    {"setAmbient", ActionKind::SetAmbient, {"value"}},
    {"setRaster", ActionKind::SetRaster, {"shadowMapSize", "depthBias", "normalBias", "pcf", "reflectionCubeSize"}},
    {"addLight", ActionKind::AddLight, {"type", "position", "direction", "color"}},
    {"removeLight", ActionKind::RemoveLight, {"index"}},
    {"setLight", ActionKind::SetLight, {"index", "position", "direction", "color"}},
    {"orbit", ActionKind::Orbit, {"yaw", "pitch"}},
    {"zoom", ActionKind::Zoom, {"steps"}},
    {"frameAll", ActionKind::FrameAll, {}},
    {"resetCamera", ActionKind::ResetCamera, {}},
    {"probe", ActionKind::Probe, {"x", "y"}},
    {"clearProbe", ActionKind::ClearProbe, {}},
    {"screenshot", ActionKind::Screenshot, {"path"}},
    {"referenceScreenshot", ActionKind::ReferenceScreenshot, {"path"}},
    {"windowScreenshot", ActionKind::WindowScreenshot, {"path"}},
    {"probeReport", ActionKind::ProbeReport, {"path"}},
    {"saveScene", ActionKind::SaveScene, {"path"}},
    {"open", ActionKind::Open, {"path"}},
    {"reloadShaders", ActionKind::ReloadShaders, {"dir"}},
    {"waitReference", ActionKind::WaitReference, {"timeout"}},
    {"resizeWindow", ActionKind::ResizeWindow, {"width", "height"}},
};

std::string objectField(const JsonNode& a) {
    const JsonNode o = a.child("object");
    if (o.json().is_number_integer()) return "#" + std::to_string(o.integerIn(1, 1 << 30));
    return o.string();
}

void parseFields(const JsonNode& a, ScriptAction& act) {
    auto optVec = [&](const char* key, bool unit) -> std::optional<glm::vec3> {
        if (auto n = a.find(key)) return unit ? n->unitVec3() : n->vec3();
        return std::nullopt;
    };
    switch (act.kind) {
        case ActionKind::SetShininess:
            act.object = objectField(a);
            act.value = a.child("s").inRange(0.0f, kMaxShininess, false, false);
            break;
        case ActionKind::SetMaterial:
            act.object = objectField(a);
            if (auto n = a.find("ma")) act.material.ma = n->rgb();
            if (auto n = a.find("md")) act.material.md = n->rgb();
            if (auto n = a.find("ms")) act.material.ms = n->rgb();
            if (auto n = a.find("kr")) act.material.kr = n->rgb();
            if (auto n = a.find("kt")) act.material.kt = n->rgb();
            if (auto n = a.find("s")) act.material.s = n->inRange(0.0f, kMaxShininess, false, false);
            if (auto n = a.find("ior")) act.material.ior = n->positive();
            break;
        case ActionKind::Preset:
            act.object = objectField(a);
            act.text = a.child("name").string();
            if (!findMaterialPreset(act.text)) a.failAt("name", "unknown preset '" + act.text + "'");
            break;
        case ActionKind::Select: act.object = objectField(a); break;
        case ActionKind::SetTerm:
        case ActionKind::ToggleTerm:
            act.text = a.child("term").string();
            if (!parseTerm(act.text))
                a.failAt("term", "unknown term '" + act.text +
                                     "'; expected ambient, diffuse, specular, shadows or reflections");
            if (act.kind == ActionKind::SetTerm) act.on = a.child("on").boolean();
            break;
        case ActionKind::Progression: act.step = a.child("step").integerIn(1, kProgressionSteps); break;
        case ActionKind::SetModel:
        case ActionKind::SwitchModel:
            act.text = a.child("model").string();
            if (act.text != "phong" && act.text != "blinn-phong")
                a.failAt("model", "expected phong or blinn-phong, got '" + act.text + "'");
            if (auto n = a.find("all")) act.on = n->boolean();
            else act.on = false;
            break;
        case ActionKind::SetMode:
            act.text = a.child("mode").string();
            if (!parseViewMode(act.text))
                a.failAt("mode", "expected raster, traced, split or difference, got '" + act.text + "'");
            break;
        case ActionKind::SetEncoding:
            act.text = a.child("encoding").string();
            if (act.text != "srgb" && act.text != "linear")
                a.failAt("encoding", "expected srgb or linear, got '" + act.text + "'");
            break;
        case ActionKind::SetSplit: act.value = a.child("position").inRange(0.0f, 1.0f, false, false); break;
        case ActionKind::SetAmbient: act.color = a.child("value").rgb(); break;
        case ActionKind::SetRaster: act.raster = parseRasterOverride(a); break;
        case ActionKind::AddLight:
            act.text = a.has("type") ? a.child("type").string() : "point";
            if (act.text != "point" && act.text != "directional")
                a.failAt("type", "expected point or directional, got '" + act.text + "'");
            act.position = optVec("position", false);
            act.direction = optVec("direction", true);
            if (auto n = a.find("color")) act.color = n->rgb();
            break;
        case ActionKind::RemoveLight: act.step = a.child("index").integerIn(0, kMaxLights - 1); break;
        case ActionKind::SetLight:
            act.step = a.child("index").integerIn(0, kMaxLights - 1);
            act.position = optVec("position", false);
            act.direction = optVec("direction", true);
            if (auto n = a.find("color")) act.color = n->rgb();
            break;
        case ActionKind::Orbit:
            act.value = a.has("yaw") ? a.child("yaw").finite() : 0.0f;
            act.value2 = a.has("pitch") ? a.child("pitch").finite() : 0.0f;
            break;
        case ActionKind::Zoom: act.value = a.child("steps").finite(); break;
        case ActionKind::Probe:
            act.step = a.child("x").integerIn(0, 16383);
            act.y = a.child("y").integerIn(0, 16383);
            break;
        case ActionKind::Screenshot:
        case ActionKind::ReferenceScreenshot:
        case ActionKind::WindowScreenshot:
        case ActionKind::ProbeReport:
        case ActionKind::SaveScene:
        case ActionKind::Open:
            act.text = a.child("path").string();
            if (act.text.empty()) a.failAt("path", "must not be empty");
            break;
        case ActionKind::WaitReference:
            act.value = a.has("timeout") ? a.child("timeout").positive() : 60.0f;
            break;
        case ActionKind::ResizeWindow:
            act.step = a.child("width").integerIn(1, 16384);
            act.y = a.child("height").integerIn(1, 16384);
            break;
        case ActionKind::ReloadShaders:
            if (auto n = a.find("dir")) act.text = n->string();
            break;
        case ActionKind::FrameAll:
        case ActionKind::ResetCamera:
        case ActionKind::ClearProbe: break;
    }
}

[[noreturn]] void failAction(const std::string& file, const ScriptAction& a, const std::string& field,
                             const std::string& reason) {
    std::string place = "actions[" + std::to_string(a.index) + "]";
    if (!field.empty()) place += "." + field;
    throw InputError(file, place, reason);
}

uint32_t resolveObject(const ViewerState& state, const ScriptAction& a, const std::string& file) {
    if (auto id = findObject(state.scene, a.object)) return *id;
    failAction(file, a, "object", "no object '" + a.object + "' in the scene (names, or #1..#" +
                                      std::to_string(objectCount(state.scene)) + ")");
}

}  // namespace

Script parseScript(const std::string& text, const std::string& file) {
    const nlohmann::json doc = parseJsonText(text, file);
    const JsonNode root(doc, "", file, printWarning);
    // Either a bare list of actions or {"actions": [...]}; paths read "actions[i]" in both cases.
    const nlohmann::json* list = &doc;
    if (doc.is_object()) {
        root.warnUnknownKeys({"actions"});
        if (!doc.contains("actions")) root.fail("expected a list of actions or {\"actions\": [...]}");
        list = &doc["actions"];
    }
    const JsonNode actions(*list, "actions", file, printWarning);
    if (!list->is_array()) actions.fail(std::string("expected an array, got ") + jsonTypeName(*list));
    Script script;
    script.file = file;
    int frame = 0;
    for (size_t i = 0; i < actions.arraySize(); ++i) {
        const JsonNode a = actions[i];
        a.requireObject();
        ScriptAction act;
        act.index = int(i);
        act.name = a.child("action").string();
        const ActionInfo* info = nullptr;
        for (const ActionInfo& candidate : kActions)
            if (act.name == candidate.name) info = &candidate;
        if (!info) a.failAt("action", "unknown action '" + act.name + "' (docs/viewer.md lists them)");
        act.kind = info->kind;
        if (auto f = a.find("frame")) {
            const int n = f->integerIn(0, 1 << 24);
            if (n < frame) f->fail("frames must not decrease (the previous action runs at frame " +
                                   std::to_string(frame) + ")");
            frame = n;
        }
        act.frame = frame;
        std::vector<const char*> known = {"action", "frame"};
        known.insert(known.end(), info->fields.begin(), info->fields.end());
        for (const auto& item : a.json().items()) {
            bool ok = false;
            for (const char* k : known) ok = ok || item.key() == k;
            if (!ok) a.failAt(item.key(), "not a field of '" + act.name + "'");
        }
        parseFields(a, act);
        script.actions.push_back(std::move(act));
    }
    return script;
}

Script loadScript(const std::string& path) { return parseScript(readFile(path), path); }

bool isStateAction(ActionKind kind) { return kind < ActionKind::Screenshot; }

void applyScriptAction(ViewerState& state, const ScriptAction& a, const std::string& file) {
    switch (a.kind) {
        case ActionKind::SetShininess: setShininess(state, resolveObject(state, a, file), a.value); break;
        case ActionKind::SetMaterial: {
            const uint32_t id = resolveObject(state, a, file);
            Material m = objectMaterial(state.scene, id);
            a.material.applyTo(m);
            setObjectMaterial(state, id, m);
            break;
        }
        case ActionKind::Preset:
            applyPreset(state, resolveObject(state, a, file), *findMaterialPreset(a.text));
            break;
        case ActionKind::Select: select(state, resolveObject(state, a, file)); break;
        case ActionKind::SetTerm: setTerm(state, *parseTerm(a.text), a.on); break;
        case ActionKind::ToggleTerm: toggleTerm(state, *parseTerm(a.text)); break;
        case ActionKind::Progression: applyProgression(state, a.step); break;
        case ActionKind::SetModel: setModel(state, *parseShadingModel(a.text)); break;
        case ActionKind::SwitchModel: switchModelKeepingHighlights(state, *parseShadingModel(a.text), a.on); break;
        case ActionKind::SetMode: setMode(state, *parseViewMode(a.text)); break;
        case ActionKind::SetEncoding:
            setEncoding(state, a.text == "linear" ? Encoding::Linear : Encoding::Srgb);
            break;
        case ActionKind::SetSplit: setSplitPosition(state, a.value); break;
        case ActionKind::SetAmbient: setAmbient(state, *a.color); break;
        case ActionKind::SetRaster: {
            RasterSettings r = state.scene.raster;
            a.raster.applyTo(r);
            setRasterSettings(state, r);
            break;
        }
        case ActionKind::AddLight: {
            const int i = addLight(state, a.text == "directional" ? LightType::Directional : LightType::Point);
            if (i < 0) failAction(file, a, "", "the scene already has " + std::to_string(kMaxLights) + " lights");
            Light l = state.scene.lights[size_t(i)];
            if (a.position) l.position = *a.position;
            if (a.direction) l.direction = *a.direction;
            if (a.color) l.color = *a.color;
            setLight(state, i, l);
            break;
        }
        case ActionKind::RemoveLight:
        case ActionKind::SetLight: {
            if (size_t(a.step) >= state.scene.lights.size())
                failAction(file, a, "index", "no light " + std::to_string(a.step) + " (the scene has " +
                                                 std::to_string(state.scene.lights.size()) + ")");
            if (a.kind == ActionKind::RemoveLight) {
                removeLight(state, a.step);
                break;
            }
            Light l = state.scene.lights[size_t(a.step)];
            if (a.position) l.position = *a.position;
            if (a.direction) l.direction = *a.direction;
            if (a.color) l.color = *a.color;
            setLight(state, a.step, l);
            break;
        }
        case ActionKind::Orbit: {
            OrbitCamera o = state.orbit;
            orbitRotate(o, glm::radians(a.value), glm::radians(a.value2));
            applyOrbit(state, o);
            break;
        }
        case ActionKind::Zoom: {
            OrbitCamera o = state.orbit;
            orbitZoom(o, a.value);
            applyOrbit(state, o);
            break;
        }
        case ActionKind::FrameAll: frameAll(state); break;
        case ActionKind::ResetCamera: resetCamera(state); break;
        case ActionKind::Probe: setProbe(state, a.step, a.y); break;
        case ActionKind::ClearProbe: clearProbe(state); break;
        default: failAction(file, a, "", "'" + a.name + "' needs the viewer window");
    }
}

const ScriptAction* ScriptCursor::next(int frame) {
    if (next_ >= script_->actions.size() || script_->actions[next_].frame > frame) return nullptr;
    return &script_->actions[next_++];
}

}  // namespace shadelab::app
