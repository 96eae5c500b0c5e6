// ScriptPlayer: the frame-by-frame playback of a viewer script.
#include "app/script_player.h"

#include "util/check.h"
#include "util/input_error.h"

#include <algorithm>
#include <variant>

namespace shadelab::app {

void ScriptPlayer::fail(const ScriptAction& action, const std::string& reason, const std::string& field) const {
    std::string where = "actions[" + std::to_string(action.index) + "]";
    if (!field.empty()) where += "." + field;
    throw InputError(script_.file, where, reason);
}

bool ScriptPlayer::stillHeld(ScriptWindow& window) {
    if (drag_) return true;  // a drag holds the script until it has been released
    if (smoothShot_) {
        const auto& shot = std::get<actions::SmoothScreenshot>(smoothShot_->action);
        if (window.writeSmoothFrame(shot.path)) {
            smoothShot_ = nullptr;
        } else if (window.seconds() - waitStarted_ > double(shot.timeout)) {
            fail(*smoothShot_, "the smooth frame did not complete within " + std::to_string(int(shot.timeout)) +
                                   " s (it accumulates in Raster mode only, with 'smooth edges' on)");
        } else {
            return true;
        }
    }
    if (waiting_) {
        const float timeout = std::get<actions::WaitReference>(waiting_->action).timeout;
        if (window.referenceComplete()) {
            waiting_ = nullptr;
        } else if (window.seconds() - waitStarted_ > double(timeout)) {
            fail(*waiting_, "the reference did not finish within " + std::to_string(int(timeout)) + " s");
        } else {
            return true;
        }
    }
    return false;
}

void ScriptPlayer::play(int frame, ViewerState& state, ScriptWindow& window) {
    if (stillHeld(window)) return;
    while (const ScriptAction* a = cursor_.next(frame)) {
        if (isStateAction(*a)) {
            applyScriptAction(state, *a, script_.file);
        } else if (std::holds_alternative<actions::WaitReference>(a->action)) {
            waiting_ = a;
            waitStarted_ = window.seconds();
        } else if (std::holds_alternative<actions::SmoothScreenshot>(a->action)) {
            smoothShot_ = a;
            waitStarted_ = window.seconds();
        } else if (const auto* d = std::get_if<actions::Drag>(&a->action)) {
            drag_ = DragInProgress{*d, 0};
        } else {
            window.perform(*a);
        }
        if (held()) break;
    }
}

std::optional<DragPointer> ScriptPlayer::nextDragPointer() {
    if (!drag_) return std::nullopt;
    const actions::Drag& d = drag_->drag;
    SHADELAB_DCHECK_GE(d.steps, 1);  // the script's reader refuses fewer
    const int frame = drag_->frame++;
    const float t = std::clamp(float(frame - 1) / float(d.steps), 0.0f, 1.0f);
    DragPointer p;
    p.imagePixel = glm::vec2(d.x0 + 0.5f + t * (d.x1 - d.x0), d.y0 + 0.5f + t * (d.y1 - d.y0));
    p.down = frame >= 1 && frame <= d.steps + 1;
    if (frame > d.steps + 2) drag_.reset();
    return p;
}

}  // namespace shadelab::app
