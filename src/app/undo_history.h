// Undo and redo over the viewer's edits (docs/viewer.md, "Undo and redo"). An edit is any change that bumps
// ViewerState::editRevision: materials, lights, the model and terms, raster settings, the opened file.
// Navigation is not an edit: the camera, the selection, the probe, the view mode and the wipe stay as they
// are when an edit is undone, as in most 3D tools. A slider drag is one step, because the viewer commits
// only between gestures (no widget active, no mouse button held).
#pragma once

#include "app/viewer_state.h"

#include <cstddef>
#include <vector>

namespace shadelab::app {

class UndoHistory {
public:
    explicit UndoHistory(size_t limit = 256) : limit_(limit) {}

    // Forgets every step; `state` becomes the baseline.
    void reset(const ViewerState& state);
    // Between gestures: when `state` was edited since the last commit, the state as last committed becomes
    // an undo step and the redo steps are dropped. Returns true when it recorded a step.
    bool commit(const ViewerState& state);
    // Restore the state before the last step / after the last undone one; false when there is none.
    // Call commit() first, so that an edit still in the open is not lost.
    bool undo(ViewerState& state);
    bool redo(ViewerState& state);
    size_t undoSteps() const { return undo_.size(); }
    size_t redoSteps() const { return redo_.size(); }

private:
    // What an edit can change, without the navigation (see above).
    struct Snapshot {
        Scene scene;
        std::string scenePath;
        Camera fileCamera;
    };
    static Snapshot take(const ViewerState& state);
    void restore(ViewerState& state, const Snapshot& s);

    size_t limit_;
    Snapshot committed_;
    uint64_t committedEdit_ = 0;
    std::vector<Snapshot> undo_, redo_;
};

}  // namespace shadelab::app
