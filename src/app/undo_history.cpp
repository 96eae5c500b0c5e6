#include "app/undo_history.h"

namespace shadelab::app {
namespace {

// The same meshes, by identity: an edit never replaces geometry, only opening a file does.
bool sameGeometry(const Scene& a, const Scene& b) {
    if (a.meshes.size() != b.meshes.size()) return false;
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        const std::vector<MeshPart>& pa = a.meshes[i].parts;
        const std::vector<MeshPart>& pb = b.meshes[i].parts;
        if (pa.size() != pb.size()) return false;
        for (size_t k = 0; k < pa.size(); ++k)
            if (pa[k].geometry != pb[k].geometry) return false;
    }
    return true;
}

}  // namespace

UndoHistory::Snapshot UndoHistory::take(const ViewerState& state) {
    // Mesh geometry is shared and immutable (scene/mesh_geometry.h): a snapshot copies pointers, not triangles.
    return Snapshot{state.scene, state.scenePath, state.fileCamera};
}

void UndoHistory::reset(const ViewerState& state) {
    undo_.clear();
    redo_.clear();
    committed_ = take(state);
    committedEdit_ = state.editRevision;
}

bool UndoHistory::commit(const ViewerState& state) {
    if (state.editRevision == committedEdit_) return false;
    undo_.push_back(std::move(committed_));
    if (undo_.size() > limit_) undo_.erase(undo_.begin());
    redo_.clear();
    committed_ = take(state);
    committedEdit_ = state.editRevision;
    return true;
}

void UndoHistory::restore(ViewerState& state, const Snapshot& s) {
    const bool sameFile = s.scenePath == state.scenePath && sameGeometry(s.scene, state.scene);
    const Camera camera = state.scene.camera;
    state.scene = s.scene;
    state.scenePath = s.scenePath;
    state.fileCamera = s.fileCamera;
    if (sameFile) {
        state.scene.camera = camera;  // navigation stays where it is
    } else {
        // Undoing an Open: the other file's meshes and its own view come back; a new geometry revision (never
        // an old one: the rasterizer keys its upload on it) makes the rasterizer upload them again.
        state.orbit = orbitFromCamera(state.scene.camera);
        state.selected = 0;
        state.probe = ProbeState{};
        ++state.geometryRevision;
    }
    if (state.selected > objectCount(state.scene)) state.selected = 0;
    markChanged(state);
    committed_ = take(state);
    committedEdit_ = state.editRevision;
}

bool UndoHistory::undo(ViewerState& state) {
    commit(state);
    if (undo_.empty()) return false;
    Snapshot s = std::move(undo_.back());
    undo_.pop_back();
    redo_.push_back(take(state));
    restore(state, s);
    return true;
}

bool UndoHistory::redo(ViewerState& state) {
    commit(state);
    if (redo_.empty()) return false;
    Snapshot s = std::move(redo_.back());
    redo_.pop_back();
    undo_.push_back(take(state));
    restore(state, s);
    return true;
}

}  // namespace shadelab::app
