// Viewer automation (--script actions.json): a list of actions applied between frames, so tests and
// teachers can drive the viewer without a mouse. Parsing and the state actions are pure; the app performs
// the few actions that need the window (screenshots, reports, shader reload). Format: docs/viewer.md.
#pragma once

#include "app/viewer_state.h"
#include "scene/raster_override.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::app {

enum class ActionKind {
    // state actions (applyScriptAction)
    SetShininess, SetMaterial, Preset, Select, SetTerm, ToggleTerm, Progression, SetModel, SwitchModel,
    SetMode, SetEncoding, SetSplit, SetAmbient, SetRaster, AddLight, RemoveLight, SetLight, Orbit, Zoom, FrameAll,
    ResetCamera, Probe, ClearProbe,
    // app actions (performed by the window loop)
    Screenshot, ReferenceScreenshot, WindowScreenshot, ProbeReport, SaveScene, Open, ReloadShaders, WaitReference,
    ResizeWindow,
};

struct ScriptAction {
    int index = 0;                    // position in the file's list, for messages ("actions[3]")
    int frame = 0;                    // runs before this frame is drawn; frames count from 0
    ActionKind kind = ActionKind::Select;
    std::string name;                 // the action's name as written
    std::string object;               // object name, or "#<coverage id>"
    std::string text;                 // term, model, mode, encoding, preset name, light type, path or dir
    bool on = true;                   // setTerm; switchModel's "all"
    int step = 0;                     // progression step; light index; probe x
    int y = 0;                        // probe y; resizeWindow height (step: width)
    float value = 0.0f;               // s, split position, zoom steps, orbit yaw (degrees), timeout (s)
    float value2 = 0.0f;              // orbit pitch (degrees)
    std::optional<glm::vec3> position, direction, color;     // addLight / setLight; color also setAmbient
    MaterialOverride material;        // setMaterial
    RasterOverride raster;            // setRaster
};

struct Script {
    std::string file;                 // for messages
    std::vector<ScriptAction> actions;  // in file order; frames never decrease
    int lastFrame() const { return actions.empty() ? -1 : actions.back().frame; }
};

// Parses a script. Throws InputError naming the file, the action ("actions[3].term") and the problem.
Script parseScript(const std::string& text, const std::string& file);
Script loadScript(const std::string& path);

// True for the actions applyScriptAction handles; the others need the window.
bool isStateAction(ActionKind kind);

// Applies a state action. Throws InputError naming the file and action when it cannot apply (an object
// or light that does not exist in the current scene).
void applyScriptAction(ViewerState& state, const ScriptAction& action, const std::string& file);

// Hands out the actions of each frame in order.
class ScriptCursor {
public:
    explicit ScriptCursor(const Script& script) : script_(&script) {}
    // The next action due at or before `frame`, or nullptr.
    const ScriptAction* next(int frame);
    bool done() const { return next_ >= script_->actions.size(); }

private:
    const Script* script_;
    size_t next_ = 0;
};

}  // namespace shadelab::app
