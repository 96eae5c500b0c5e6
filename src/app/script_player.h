// ScriptPlayer: plays a viewer script (script.h) frame by frame, without a window. State actions are applied to
// the ViewerState here; the three actions that span frames are held here too: waitReference (until the window
// says the reference, or the path tracer's first whole pass, of this state is complete), smoothScreenshot (until
// the smooth frame has converged) and drag (a pointer path, fed to the window one frame at a time). Everything
// else that needs the window (screenshots, open, render, ...) is handed to it through ScriptWindow. Each wait
// has its timeout, after which playback stops with an InputError naming the action.
#pragma once

#include "app/script.h"
#include "app/viewer_state.h"

#include <glm/vec2.hpp>
#include <optional>
#include <string>

namespace shadelab::app {

// What the player asks of the window.
class ScriptWindow {
public:
    virtual ~ScriptWindow() = default;
    // Performs a window action (not a state action, not waitReference, smoothScreenshot or drag).
    virtual void perform(const ScriptAction& action) = 0;
    // Whether the reference shown for the state's current revision is complete (in the Global modes: the path
    // tracer has a whole sample pass of it).
    virtual bool referenceComplete() = 0;
    // Whether the smooth frame of the current state has converged; when it has, writes it to `path` first.
    virtual bool writeSmoothFrame(const std::string& path) = 0;
    virtual double seconds() = 0;  // a clock for the timeouts
};

// Where a scripted drag puts the pointer on one frame: a point of the image, in pixels, and the left button.
struct DragPointer {
    glm::vec2 imagePixel{0.0f};
    bool down = false;
};

class ScriptPlayer {
public:
    explicit ScriptPlayer(Script script) : script_(std::move(script)), cursor_(script_) {}
    ScriptPlayer(const ScriptPlayer&) = delete;  // the cursor points at script_
    ScriptPlayer& operator=(const ScriptPlayer&) = delete;

    // Plays what is due before `frame` is drawn, unless a wait or a drag holds the script. Throws InputError when
    // an action fails or a wait times out.
    void play(int frame, ViewerState& state, ScriptWindow& window);
    // The drag's pointer for this frame, and then the next (nullopt when no drag is in progress): frame 0 of a
    // drag moves to its start, 1 presses, then `steps` moves, then the release; after that the script goes on.
    std::optional<DragPointer> nextDragPointer();

    // Every action played and nothing held.
    bool finished() const { return cursor_.done() && !held(); }
    bool waitingForReference() const { return waiting_ != nullptr; }
    const std::string& file() const { return script_.file; }
    // An InputError naming `action` (and `field` under it, when given): "<file>: actions[3].path: <reason>".
    [[noreturn]] void fail(const ScriptAction& action, const std::string& reason, const std::string& field = {}) const;

private:
    bool held() const { return waiting_ || drag_ || smoothShot_; }
    bool stillHeld(ScriptWindow& window);  // clears what is done; throws on a timeout

    Script script_;
    ScriptCursor cursor_;
    const ScriptAction* waiting_ = nullptr;     // a waitReference holding the script
    const ScriptAction* smoothShot_ = nullptr;  // a smoothScreenshot waiting for the smooth frame
    double waitStarted_ = 0.0;
    struct DragInProgress {
        actions::Drag drag;
        int frame = 0;
    };
    std::optional<DragInProgress> drag_;
};

}  // namespace shadelab::app
