// Viewer automation (--script actions.json): a list of actions applied between frames, so tests and
// teachers can drive the viewer without a mouse. Each action is parsed once into a typed struct; parsing and
// the state actions are pure, and the app performs the few that need the window. Format: docs/viewer.md.
#pragma once

#include "app/material_presets.h"
#include "app/viewer_state.h"
#include "render/render_request.h"
#include "scene/light.h"
#include "scene/raster_override.h"
#include "util/input_files.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace shadelab::app {

// One struct per action, named as in the file; `object` is an object's name or "#<coverage id>".
namespace actions {

// State actions: applyScriptAction applies them to a ViewerState.
struct SetShininess {
    std::string object;
    float s = 0.0f;
};
struct SetMaterial {
    std::string object;
    MaterialOverride material;
};
struct Preset {
    std::string object;
    const MaterialPreset* preset = nullptr;
};  // never null once parsed
struct Select {
    std::string object;
};
struct SetTerm {
    Term term = Term::Ambient;
    bool on = true;
};
struct ToggleTerm {
    Term term = Term::Ambient;
};
struct Progression {
    int step = 1;
};  // 0..kProgressionSteps
struct SetModel {
    ShadingModel model = ShadingModel::Phong;
};
struct SwitchModel {
    ShadingModel model = ShadingModel::Phong;
    bool allObjects = false;
};
struct SetMode {
    ViewMode mode = ViewMode::Raster;
};
struct SetEncoding {
    Encoding encoding = Encoding::Srgb;
};
// The scene's display (viewer_state.h setDisplay); a field left out keeps its current value.
struct SetDisplay {
    std::optional<double> exposure;  // stops, kMinExposure..kMaxExposure
    std::optional<ViewTransform> transform;
};
// The Global modes' choices (viewer_state.h setGlobalPart, setGlobalDenoise); a field left out keeps its value.
struct SetGlobal {
    std::optional<trace::PathPart> part;
    std::optional<bool> denoise;
};
struct SetSplit {
    float position = 0.5f;
};  // fraction of the image width
struct SetAmbient {
    glm::vec3 Ia{0.0f};
};  // linear RGB intensity
struct SetRaster {
    RasterOverride raster;
};
struct AddLight {
    LightType type = LightType::Point;
    LightOverride light;
};
struct RemoveLight {
    int index = 0;
};  // from 0
struct SetLight {
    int index = 0;
    LightOverride light;
};  // from 0
struct Orbit {
    float yaw = 0.0f, pitch = 0.0f;
};  // degrees
struct Zoom {
    float steps = 0.0f;
};  // mouse-wheel steps
struct FrameAll {};
struct ResetCamera {};
struct Probe {
    int x = 0, y = 0;
};  // pixels, row 0 at the top
struct ClearProbe {};
struct RayTree {
    bool on = true;
};  // setRayTree
struct WhiteFurnace {
    bool on = true;
};  // setWhiteFurnace

// Window actions: the viewer performs them.
struct Screenshot {
    std::string path;
};
struct ReferenceScreenshot {
    std::string path;
};
struct WindowScreenshot {
    std::string path;
};
struct ProbeReport {
    std::string path;
};
struct SaveScene {
    std::string path;
};
struct Open {
    std::string path;
};
struct ReloadShaders {
    std::string dir;
};  // empty: shaderSourceDir()
struct WaitReference {
    float timeout = 60.0f;
};  // seconds
struct ResizeWindow {
    int width = 0, height = 0;
};  // window units
// A left-button drag from (x0, y0) to (x1, y1), image pixels (row 0 at the top), fed to the window's input as
// the mouse would: press, `steps` moves, release, one per frame; the script waits until it is done.
struct Drag {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int steps = 8;
};
// Waits (the script holds, frames go on) until the smooth still frame has all its samples (accumulation.h),
// then writes it; fails after `timeout` seconds.
struct SmoothScreenshot {
    std::string path;
    float timeout = 60.0f;
};
// Renders the current state offline, as `shadelab render` renders the saved scene (the same request, the same
// bytes), and writes the PNG: a raster, Whitted or path-traced image at any size and sample count, whatever
// the window shows. Without a size, the image's size in the window.
struct Render {
    std::string path;
    render::RenderRequest request;
    bool sizeGiven = false;
};
struct Undo {};  // the viewer holds the history (undo_history.h)
struct Redo {};

}  // namespace actions

using Action =
    std::variant<actions::SetShininess, actions::SetMaterial, actions::Preset, actions::Select, actions::SetTerm,
                 actions::ToggleTerm, actions::Progression, actions::SetModel, actions::SwitchModel, actions::SetMode,
                 actions::SetEncoding, actions::SetDisplay, actions::SetGlobal, actions::SetSplit, actions::SetAmbient,
                 actions::SetRaster, actions::AddLight, actions::RemoveLight, actions::SetLight, actions::Orbit,
                 actions::Zoom, actions::FrameAll, actions::ResetCamera, actions::Probe, actions::ClearProbe,
                 actions::RayTree, actions::WhiteFurnace, actions::Screenshot, actions::ReferenceScreenshot,
                 actions::WindowScreenshot, actions::ProbeReport, actions::SaveScene, actions::Open,
                 actions::ReloadShaders, actions::WaitReference, actions::ResizeWindow, actions::Drag,
                 actions::SmoothScreenshot, actions::Render, actions::Undo, actions::Redo>;

struct ScriptAction {
    int index = 0;     // position in the file's list, for messages ("actions[3]")
    int frame = 0;     // runs before this frame is drawn; frames count from 0
    std::string name;  // the action's name as written
    Action action;     // what it does, with its fields
};

struct Script {
    std::string file;                   // for messages
    std::vector<ScriptAction> actions;  // in file order; frames never decrease
    InputFiles inputs;                  // the script's file: no action's output replaces it (input_files.h)
    int lastFrame() const { return actions.empty() ? -1 : actions.back().frame; }
};

// Parses a script. Throws InputError naming the file, the action ("actions[3].term") and the problem.
Script parseScript(const std::string& text, const std::string& file);
Script loadScript(const std::string& path);

// True for the actions applyScriptAction handles; the others need the window.
bool isStateAction(const ScriptAction& action);

// Applies a state action. Throws InputError naming the file and action when it cannot apply (an object
// or light that does not exist in the current scene, or an action that needs the window).
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
