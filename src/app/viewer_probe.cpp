// Viewer: the probe's state each frame: the probe itself (anchored to the clicked surface point), its ray tree
// (traced from the click's eye, kept while the camera orbits) and the rendering equation at the point, and the
// --verbose line that says where the probe window went.
#include "app/viewer.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace shadelab::app {

// A click probes its pixel and anchors the probe to the surface point it found; from then on the probe
// follows that point as the camera moves or the scene is edited (probe.h probeAnchor), and its pixel is
// where the point projects.
void Viewer::updateProbe() {
    if (!state_.probe.active) {
        probe_.reset();
        return;
    }
    ProbeState& p = state_.probe;
    if (probe_ && probeRevision_ == state_.revision && probeX_ == p.x && probeY_ == p.y && probeW_ == renderW_ &&
        probeH_ == renderH_ && p.rayTree == rayTree_.has_value())
        return;
    const trace::TraceScene traced(state_.scene, reference_->meshBvh(state_.scene));
    const bool clicked = p.anchor.objectId == 0;
    if (clicked) {
        probe_ = probePixel(traced, renderW_, renderH_, p.x, p.y);
        if (probe_->hit) p.anchor = ProbeAnchor{probe_->objectId, probe_->P};
    } else {
        probe_ = probeAnchor(traced, renderW_, renderH_, p.anchor);
        if (!probe_->hit) {  // the anchored object is gone (undo, another file): let go of the probe
            clearProbe(state_);
            probe_.reset();
            return;
        }
        p.x = probe_->x;
        p.y = probe_->y;
    }
    probeRevision_ = state_.revision;
    probeX_ = p.x, probeY_ = p.y, probeW_ = renderW_, probeH_ = renderH_;
    updateRayTree(traced, clicked);
}

// Local models: the lights and the ambient at the point; Global modes: the path tracer's hemisphere too.
void Viewer::updateEquation() {
    if (!fields_.equationOpen || !probe_ || !probe_->hit) {
        equation_.reset();
        return;
    }
    const bool global = isGlobal(state_.mode);
    if (equation_ && equationRevision_ == state_.revision && equationX_ == probe_->x && equationY_ == probe_->y &&
        equationGlobal_ == global)
        return;
    // Not while a drag orbits the camera or moves a light: the old figures stay until the hand stops.
    for (int b = 0; b < 3; ++b)
        if (ImGui::IsMouseDown(b) && equation_) return;
    const trace::TraceScene traced(state_.scene, reference_->meshBvh(state_.scene));
    equation_ = renderingEquationAt(traced, renderW_, renderH_, probe_->x, probe_->y, global);
    equationRevision_ = state_.revision;
    equationX_ = probe_->x, equationY_ = probe_->y;
    equationGlobal_ = global;
}

// The tree is traced once from the camera of the click (or of the moment T is pressed) and traced again
// along the same primary ray when the scene changes, so orbiting walks around it rather than re-aiming it.
void Viewer::updateRayTree(const trace::TraceScene& traced, bool clicked) {
    const ProbeState& p = state_.probe;
    if (!p.rayTree || !probe_ || !probe_->hit) {
        rayTree_.reset();
        return;
    }
    std::optional<trace::TraceScene> fromClick;  // the scene seen from the click's camera, once it has moved
    if (!rayTree_ || clicked || rayTreeAnchor_ != p.anchor.point) {
        rayTree_ = recordRayTree(traced, renderW_, renderH_, p.x, p.y);
        rayTreeAnchor_ = p.anchor.point;
        fields_.rayTreeRay = 0;
    } else if (sameCamera(rayTree_->camera, state_.scene.camera)) {
        rerecordRayTree(traced, *rayTree_);
    } else {
        Scene seen = state_.scene;
        seen.camera = rayTree_->camera;
        fromClick.emplace(seen, reference_->meshBvh(seen));
        rerecordRayTree(*fromClick, *rayTree_);
    }
    const trace::TraceScene& tracedFrom = fromClick ? *fromClick : traced;
    const trace::RayTreeRecord& rec = rayTree_->record;
    rayTreePanel_ = {};
    for (size_t k = 0; k < rec.rays.size(); ++k) {
        rayTreePanel_.rays.push_back(rayTreeRayLine(state_.scene, rec, k));
        rayTreePanel_.algebra.push_back(rayTreeAlgebra(tracedFrom, rec, k));
    }
    fields_.rayTreeRay = std::clamp(fields_.rayTreeRay, 0, std::max(int(rec.rays.size()) - 1, 0));
}

// --verbose: where the probe window went, once per change, so that a test can hold it to its rule.
void Viewer::logProbeWindow(const ProbeWindowSpace& space, const ProbeWindowPlace& place, glm::vec2 size) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "probe window %.0f %.0f %.0f %.0f point %.0f %.0f clearance %.0f visible %.0f %.0f %.0f %.0f%s",
                  place.topLeft.x, place.topLeft.y, size.x, size.y, space.point.x, space.point.y, space.clearance,
                  space.visibleMin.x, space.visibleMin.y, space.visibleMax.x, space.visibleMax.y,
                  place.fits ? "" : " (no room)");
    if (line == lastProbeWindowLog_) return;
    lastProbeWindowLog_ = line;
    std::fprintf(stderr, "shadelab: %s\n", line);
}

}  // namespace shadelab::app
