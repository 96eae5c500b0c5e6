// Script parsing (JSON through the scene loader's path-naming reader, and its material, light and raster
// readers) into typed actions, once; and the state actions, applied without parsing anything again.
#include "app/script.h"

#include "image/image.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "util/input_error.h"
#include "util/messages.h"
#include "util/read_file.h"

#include <cctype>
#include <glm/trigonometric.hpp>
#include <limits>
#include <type_traits>

namespace shadelab::app {
namespace {

using namespace actions;

std::string objectField(const JsonNode& a) {
    const JsonNode o = a.child("object");
    if (o.json().is_number_integer()) return "#" + std::to_string(o.integerIn(1, 1 << 30));
    return o.string();
}

template <typename PathAction>
Action pathAction(const JsonNode& a) {
    std::string path = a.child("path").string();
    if (path.empty()) a.failAt("path", "must not be empty");
    return PathAction{std::move(path)};
}

float optionalFinite(const JsonNode& a, const char* key) { return a.has(key) ? a.child(key).finite() : 0.0f; }

// A whole number whose range the render request checks (render/render_request.h), not the reader.
int wholeNumber(const JsonNode& n) {
    return n.integerIn(std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
}

// The script's name for a render request's field: its keys are camelCase ("time_limit" -> "timeLimit").
std::string scriptField(const std::string& field) {
    std::string key;
    for (size_t i = 0; i < field.size(); ++i)
        key += field[i] == '_' && i + 1 < field.size() ? char(std::toupper(static_cast<unsigned char>(field[++i])))
                                                       : field[i];
    return key;
}

Action renderAction(const JsonNode& a) {
    actions::Render r;
    r.path = a.child("path").string();
    if (r.path.empty()) a.failAt("path", "must not be empty");
    render::RenderRequest& q = r.request;
    if (a.has("renderer")) q.engine = a.child("renderer").oneOf(render::kEngineNames, "renderer");
    if (q.engine == render::Engine::Both)
        a.failAt("renderer", "'both' is the command line's side-by-side picture; render raster and trace apart");
    if (a.has("size")) {
        const JsonNode size = a.child("size");
        if (size.arraySize() != 2) a.failAt("size", "expected [width, height]");
        q.width = wholeNumber(size[0]);
        q.height = wholeNumber(size[1]);
        r.sizeGiven = true;
    }
    if (a.has("spp")) q.spp = wholeNumber(a.child("spp"));
    if (a.has("depth")) q.depth = wholeNumber(a.child("depth"));
    if (a.has("threads")) q.threads = wholeNumber(a.child("threads"));
    if (a.has("timeLimit")) q.path.timeLimit = a.child("timeLimit").number();
    if (a.has("estimator")) q.path.estimator = a.child("estimator").oneOf(trace::kPathEstimatorNames, "estimator");
    if (a.has("lightPaths")) q.path.part = a.child("lightPaths").oneOf(trace::kPathPartNames, "light paths");
    if (a.has("sampler")) q.path.sampler = a.child("sampler").oneOf(trace::kPathSamplerNames, "sampler");
    // Unset: the state's scene's display (what the window shows), as a request's unset fields always are.
    if (a.has("exposure")) q.exposure = a.child("exposure").number();
    if (a.has("viewTransform")) q.viewTransform = a.child("viewTransform").oneOf(kViewTransformNames, "view transform");
    // The ranges are the request's, as every front end holds them; only the names are the script's.
    if (std::optional<render::RequestProblem> p = render::check(q)) a.failAt(scriptField(p->field), p->reason);
    return r;
}

// Every action: its name, its fields besides "action" and "frame", and its parser (fields in list order).
struct ActionInfo {
    const char* name;
    std::initializer_list<const char*> fields;
    Action (*parse)(const JsonNode& a);
};

const ActionInfo kActions[] = {
    {"setShininess",
     {"object", "s"},
     [](const JsonNode& a) -> Action {
         return SetShininess{objectField(a), a.child("s").inRange(0.0f, kMaxShininess, false, false)};
     }},
    {"setMaterial",
     {"object", "ma", "md", "ms", "s", "kr", "kt", "ior", "baseColor", "metallic", "roughness", "model", "disney",
      "clearcoat", "specular", "sheen", "anisotropy", "transmission", "volume"},
     [](const JsonNode& a) -> Action {
         return SetMaterial{objectField(a), parseMaterialOverride(a)};
     }},
    {"preset",
     {"object", "name"},
     [](const JsonNode& a) -> Action {
         Preset p;
         p.object = objectField(a);
         const std::string name = a.child("name").string();
         p.preset = findMaterialPreset(name);
         if (!p.preset) a.failAt("name", "unknown preset '" + name + "'");
         return p;
     }},
    {"select", {"object"}, [](const JsonNode& a) -> Action { return Select{objectField(a)}; }},
    {"setTerm",
     {"term", "on"},
     [](const JsonNode& a) -> Action {
         return SetTerm{a.child("term").oneOf(kTermNames, "term"), a.child("on").boolean()};
     }},
    {"toggleTerm",
     {"term"},
     [](const JsonNode& a) -> Action { return ToggleTerm{a.child("term").oneOf(kTermNames, "term")}; }},
    {"progression",
     {"step"},
     [](const JsonNode& a) -> Action { return Progression{a.child("step").integerIn(0, kProgressionSteps)}; }},
    {"setModel",
     {"model"},
     [](const JsonNode& a) -> Action { return SetModel{a.child("model").oneOf(kShadingModelNames, "shading model")}; }},
    {"switchModel",
     {"model", "all"},
     [](const JsonNode& a) -> Action {
         return SwitchModel{a.child("model").oneOf(kShadingModelNames, "shading model"),
                            a.has("all") && a.child("all").boolean()};
     }},
    {"setMode",
     {"mode"},
     [](const JsonNode& a) -> Action { return SetMode{a.child("mode").oneOf(kViewModeNames, "view mode")}; }},
    {"setEncoding",
     {"encoding"},
     [](const JsonNode& a) -> Action { return SetEncoding{a.child("encoding").oneOf(kEncodingNames, "encoding")}; }},
    {"setDisplay",
     {"exposure", "viewTransform"},
     [](const JsonNode& a) -> Action {
         SetDisplay d;
         if (auto f = a.find("exposure")) {
             const double stops = f->number();
             if (std::optional<std::string> why = exposureProblem(stops)) f->fail(*why);
             d.exposure = stops;
         }
         if (auto f = a.find("viewTransform")) d.transform = f->oneOf(kViewTransformNames, "view transform");
         return d;
     }},
    {"setGlobal",
     {"lightPaths", "denoise"},
     [](const JsonNode& a) -> Action {
         SetGlobal g;
         if (auto f = a.find("lightPaths")) g.part = f->oneOf(trace::kPathPartNames, "light paths");
         if (auto f = a.find("denoise")) g.denoise = f->boolean();
         return g;
     }},
    {"setSplit",
     {"position"},
     [](const JsonNode& a) -> Action { return SetSplit{a.child("position").inRange(0.0f, 1.0f, false, false)}; }},
    {"setAmbient", {"value"}, [](const JsonNode& a) -> Action { return SetAmbient{a.child("value").rgb()}; }},
    {"setRaster",
     {"shadowMapSize", "depthBias", "normalBias", "pcf", "reflectionCubeSize", "movingPreview"},
     [](const JsonNode& a) -> Action { return SetRaster{parseRasterOverride(a)}; }},
    {"addLight",
     {"type", "position", "direction", "color", "innerConeAngle", "outerConeAngle", "range"},
     [](const JsonNode& a) -> Action {
         const LightType type = a.has("type") ? a.child("type").oneOf(kLightTypeNames, "light type") : LightType::Point;
         return AddLight{type, parseLightOverride(a)};
     }},
    {"removeLight",
     {"index"},
     [](const JsonNode& a) -> Action { return RemoveLight{a.child("index").integerIn(0, kMaxLights - 1)}; }},
    {"setLight",
     {"index", "position", "direction", "color", "innerConeAngle", "outerConeAngle", "range"},
     [](const JsonNode& a) -> Action {
         return SetLight{a.child("index").integerIn(0, kMaxLights - 1), parseLightOverride(a)};
     }},
    {"orbit",
     {"yaw", "pitch"},
     [](const JsonNode& a) -> Action {
         return Orbit{optionalFinite(a, "yaw"), optionalFinite(a, "pitch")};
     }},
    {"zoom", {"steps"}, [](const JsonNode& a) -> Action { return Zoom{a.child("steps").finite()}; }},
    {"frameAll", {}, [](const JsonNode&) -> Action { return FrameAll{}; }},
    {"resetCamera", {}, [](const JsonNode&) -> Action { return ResetCamera{}; }},
    {"probe",
     {"x", "y"},
     [](const JsonNode& a) -> Action {
         return Probe{a.child("x").integerIn(0, 16383), a.child("y").integerIn(0, 16383)};
     }},
    {"clearProbe", {}, [](const JsonNode&) -> Action { return ClearProbe{}; }},
    {"rayTree", {"on"}, [](const JsonNode& a) -> Action { return RayTree{!a.has("on") || a.child("on").boolean()}; }},
    {"whiteFurnace",
     {"on"},
     [](const JsonNode& a) -> Action { return WhiteFurnace{!a.has("on") || a.child("on").boolean()}; }},
    {"screenshot", {"path"}, pathAction<Screenshot>},
    {"referenceScreenshot", {"path"}, pathAction<ReferenceScreenshot>},
    {"windowScreenshot", {"path"}, pathAction<WindowScreenshot>},
    {"probeReport", {"path"}, pathAction<ProbeReport>},
    {"saveScene", {"path"}, pathAction<SaveScene>},
    {"open", {"path"}, pathAction<Open>},
    {"reloadShaders",
     {"dir"},
     [](const JsonNode& a) -> Action { return ReloadShaders{a.has("dir") ? a.child("dir").string() : ""}; }},
    {"waitReference",
     {"timeout"},
     [](const JsonNode& a) -> Action {
         return WaitReference{a.has("timeout") ? a.child("timeout").positive() : 60.0f};
     }},
    {"drag",
     {"x0", "y0", "x1", "y1", "steps"},
     [](const JsonNode& a) -> Action {
         return Drag{float(a.child("x0").integerIn(0, 16383)), float(a.child("y0").integerIn(0, 16383)),
                     float(a.child("x1").integerIn(0, 16383)), float(a.child("y1").integerIn(0, 16383)),
                     a.has("steps") ? a.child("steps").integerIn(1, 1000) : 8};
     }},
    {"smoothScreenshot",
     {"path", "timeout"},
     [](const JsonNode& a) -> Action {
         return SmoothScreenshot{a.child("path").string(), a.has("timeout") ? a.child("timeout").positive() : 60.0f};
     }},
    {"render",
     {"path", "renderer", "size", "spp", "depth", "threads", "timeLimit", "estimator", "lightPaths", "sampler",
      "exposure", "viewTransform"},
     renderAction},
    {"undo", {}, [](const JsonNode&) -> Action { return Undo{}; }},
    {"redo", {}, [](const JsonNode&) -> Action { return Redo{}; }},
    {"resizeWindow",
     {"width", "height"},
     [](const JsonNode& a) -> Action {
         return ResizeWindow{a.child("width").integerIn(1, kMaxImageSide),
                             a.child("height").integerIn(1, kMaxImageSide)};
     }},
};

[[noreturn]] void failAction(const std::string& file, const ScriptAction& a, const std::string& field,
                             const std::string& reason) {
    std::string place = "actions[" + std::to_string(a.index) + "]";
    if (!field.empty()) place += "." + field;
    throw InputError(file, place, reason);
}

// Applies each state action; window actions have no overload here, which is what isStateAction asks.
struct StateApplier {
    ViewerState& state;
    const ScriptAction& a;
    const std::string& file;

    uint32_t object(const std::string& nameOrId) const {
        if (auto id = findObject(state.scene, nameOrId)) return *id;
        failAction(file, a, "object",
                   "no object '" + nameOrId + "' in the scene (names, or #1..#" +
                       std::to_string(objectCount(state.scene)) + ")");
    }
    void requireLight(int index) const {
        if (size_t(index) >= state.scene.lights.size())
            failAction(file, a, "index",
                       "no light " + std::to_string(index) + " (the scene has " +
                           std::to_string(state.scene.lights.size()) + ")");
    }

    void operator()(const SetShininess& x) const { setShininess(state, object(x.object), x.s); }
    void operator()(const SetMaterial& x) const {
        const uint32_t id = object(x.object);
        Material m = objectMaterial(state.scene, id);
        x.material.applyValues(m);  // setObjectMaterial derives what follows from the edit
        setObjectMaterial(state, id, m);
    }
    void operator()(const Preset& x) const { applyPreset(state, object(x.object), *x.preset); }
    void operator()(const Select& x) const { select(state, object(x.object)); }
    void operator()(const SetTerm& x) const { setTerm(state, x.term, x.on); }
    void operator()(const ToggleTerm& x) const { toggleTerm(state, x.term); }
    void operator()(const Progression& x) const { applyProgression(state, x.step); }
    void operator()(const SetModel& x) const { setModel(state, x.model); }
    void operator()(const SwitchModel& x) const { switchModelKeepingHighlights(state, x.model, x.allObjects); }
    void operator()(const SetMode& x) const { setMode(state, x.mode); }
    void operator()(const SetEncoding& x) const { setEncoding(state, x.encoding); }
    void operator()(const SetDisplay& x) const {
        DisplaySettings d = state.scene.display;
        if (x.exposure) d.exposure = *x.exposure;
        if (x.transform) d.transform = *x.transform;
        setDisplay(state, d);
    }
    void operator()(const SetGlobal& x) const {
        if (x.part) setGlobalPart(state, *x.part);
        if (x.denoise) setGlobalDenoise(state, *x.denoise);
    }
    void operator()(const SetSplit& x) const { setSplitPosition(state, x.position); }
    void operator()(const SetAmbient& x) const { setAmbient(state, x.Ia); }
    void operator()(const SetRaster& x) const {
        RasterSettings r = state.scene.raster;
        x.raster.applyTo(r);
        setRasterSettings(state, r);
    }
    void operator()(const AddLight& x) const {
        // A new light has the default cone: checked before it is added, so a refused action adds nothing.
        const float outer = x.light.outerConeAngle.value_or(kDefaultOuterConeAngle);
        if (x.light.innerConeAngle.value_or(kDefaultInnerConeAngle) > outer)
            failAction(file, a, "innerConeAngle", "must not exceed outerConeAngle (" + std::to_string(outer) + ")");
        const int i = addLight(state, x.type);
        if (i < 0) failAction(file, a, "", "the scene already has " + std::to_string(kMaxLights) + " lights");
        Light l = state.scene.lights[size_t(i)];
        x.light.applyTo(l);
        setLight(state, i, l);
    }
    void operator()(const RemoveLight& x) const {
        requireLight(x.index);
        removeLight(state, x.index);
    }
    void operator()(const SetLight& x) const {
        requireLight(x.index);
        Light l = state.scene.lights[size_t(x.index)];
        x.light.applyTo(l);
        if (l.innerConeAngle > l.outerConeAngle)
            failAction(file, a, "innerConeAngle",
                       "must not exceed outerConeAngle (" + std::to_string(l.outerConeAngle) + ")");
        setLight(state, x.index, l);
    }
    void operator()(const Orbit& x) const {
        OrbitCamera o = state.orbit;
        orbitRotate(o, glm::radians(x.yaw), glm::radians(x.pitch));
        applyOrbit(state, o);
    }
    void operator()(const Zoom& x) const {
        OrbitCamera o = state.orbit;
        orbitZoom(o, x.steps);
        applyOrbit(state, o);
    }
    void operator()(const FrameAll&) const { frameAll(state); }
    void operator()(const ResetCamera&) const { resetCamera(state); }
    void operator()(const Probe& x) const { setProbe(state, x.x, x.y); }
    void operator()(const ClearProbe&) const { clearProbe(state); }
    void operator()(const RayTree& x) const { setRayTree(state, x.on); }
    void operator()(const WhiteFurnace& x) const { setWhiteFurnace(state, x.on); }
};

template <typename T>
constexpr bool kIsStateAction = std::is_invocable_v<StateApplier, const T&>;

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
        if (auto f = a.find("frame")) {
            const int n = f->integerIn(0, 1 << 24);
            if (n < frame)
                f->fail("frames must not decrease (the previous action runs at frame " + std::to_string(frame) + ")");
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
        act.action = info->parse(a);
        script.actions.push_back(std::move(act));
    }
    return script;
}

Script loadScript(const std::string& path) {
    InputFiles inputs;
    InputRecorder recorder(inputs);
    Script script = parseScript(readFile(path, kMaxScriptFileBytes), path);
    script.inputs = std::move(inputs);
    return script;
}

bool isStateAction(const ScriptAction& action) {
    return std::visit([](const auto& x) { return kIsStateAction<std::decay_t<decltype(x)>>; }, action.action);
}

void applyScriptAction(ViewerState& state, const ScriptAction& a, const std::string& file) {
    std::visit(
        [&](const auto& x) {
            if constexpr (kIsStateAction<std::decay_t<decltype(x)>>)
                StateApplier{state, a, file}(x);
            else
                failAction(file, a, "", "'" + a.name + "' needs the viewer window");
        },
        a.action);
}

const ScriptAction* ScriptCursor::next(int frame) {
    if (next_ >= script_->actions.size() || script_->actions[next_].frame > frame) return nullptr;
    return &script_->actions[next_++];
}

}  // namespace shadelab::app
