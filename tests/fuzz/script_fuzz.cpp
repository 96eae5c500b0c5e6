// Fuzz target: viewer scripts (app/script.h). Every input must parse into a Script or raise the InputError that
// names the file, the action and the field (a render action's bad setting included: the parser words the
// request's SettingError as that InputError). A script that parses is then played as the viewer plays it
// without a window: its state actions applied in order to a small scene until one cannot apply (an InputError,
// as the viewer stops there). Numbers in a script must not make NaN: afterwards the camera and the lights must
// be finite, or the target aborts.
#include "app/script.h"
#include "app/viewer_state.h"
#include "fuzz_outcome.h"
#include "scene/scene_json.h"
#include "util/input_error.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace shadelab;

// Named spheres and a plane for the object actions, two lights for the light actions.
const char* const kScene = R"({"shadelab": 1,
  "camera": {"position": [0, 2, 8], "target": [0, 0.5, 0], "fovY": 40},
  "materials": {"red plastic": {"md": [0.7, 0.05, 0.05], "ms": 0.5, "s": 32},
                "gold": {"md": [0.3, 0.2, 0.05], "ms": [1.0, 0.78, 0.34], "s": 64},
                "mirror": {"md": 0.05, "ms": 0.9, "s": 512, "kr": 0.6}},
  "lights": [{"type": "point", "name": "key", "position": [-5, 7, 5], "color": [1, 0.85, 0.7]},
             {"type": "directional", "name": "fill", "direction": [1, -1, -1], "color": [0.2, 0.3, 0.5]}],
  "objects": [{"type": "sphere", "name": "red plastic", "center": [-1, 0.8, 0], "radius": 0.8, "material": "red plastic"},
              {"type": "sphere", "name": "gold", "center": [1, 0.6, 0], "radius": 0.6, "material": "gold"},
              {"type": "plane", "name": "floor", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "mirror"}]})";

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void requireFinite(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "script_fuzz: after the script's state actions, %s is not finite\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const app::ViewerState initial = app::makeViewerState(parseSceneJson(kScene, "script_fuzz scene"), "");
    app::Script script;
    try {
        script = app::parseScript(std::string(reinterpret_cast<const char*>(data), size), "fuzz-script.json");
    } catch (const InputError& e) {
        fuzz::noteOutcome(e.what());
        return 0;
    }
    app::ViewerState state = initial;
    std::string outcome = "ok";
    for (const app::ScriptAction& action : script.actions) {
        if (!app::isStateAction(action)) continue;
        try {
            app::applyScriptAction(state, action, script.file);
        } catch (const InputError& e) {
            outcome = std::string("applied until: ") + e.what();
            break;
        }
    }
    requireFinite(finite(state.scene.camera.position) && finite(state.scene.camera.target), "the camera");
    for (const Light& light : state.scene.lights)
        requireFinite(finite(light.position) && finite(light.direction) && finite(light.color), "a light");
    fuzz::noteOutcome(outcome);
    return 0;
}
