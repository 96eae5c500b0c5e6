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
        probe_.result.reset();
        return;
    }
    ProbeState& p = state_.probe;
    if (probe_.result && probe_.revision == state_.revision && probe_.x == p.x && probe_.y == p.y &&
        probe_.width == layout_.renderWidth && probe_.height == layout_.renderHeight &&
        p.rayTree == rayTree_.view.has_value())
        return;
    const trace::TraceScene traced(state_.scene, reference_->meshBvh(state_.scene));
    const bool clicked = p.anchor.objectId == 0;
    if (clicked) {
        probe_.result = probePixel(traced, layout_.renderWidth, layout_.renderHeight, p.x, p.y);
        if (probe_.result->hit) p.anchor = ProbeAnchor{probe_.result->objectId, probe_.result->P};
    } else {
        probe_.result = probeAnchor(traced, layout_.renderWidth, layout_.renderHeight, p.anchor);
        if (!probe_.result->hit) {  // the anchored object is gone (undo, another file): let go of the probe
            clearProbe(state_);
            probe_.result.reset();
            return;
        }
        p.x = probe_.result->x;
        p.y = probe_.result->y;
    }
    probe_.revision = state_.revision;
    probe_.x = p.x, probe_.y = p.y, probe_.width = layout_.renderWidth, probe_.height = layout_.renderHeight;
    updateRayTree(traced, clicked);
}

// Local models: the lights and the ambient at the point; Global modes: the path tracer's hemisphere too.
void Viewer::updateEquation() {
    if (!fields_.equationOpen || !probe_.result || !probe_.result->hit) {
        equation_.result.reset();
        return;
    }
    const bool global = isGlobal(state_.mode);
    if (equation_.result && equation_.revision == state_.revision && equation_.x == probe_.result->x &&
        equation_.y == probe_.result->y && equation_.global == global)
        return;
    // Not while a drag orbits the camera or moves a light: the old figures stay until the hand stops.
    for (int b = 0; b < 3; ++b)
        if (ImGui::IsMouseDown(b) && equation_.result) return;
    const trace::TraceScene traced(state_.scene, reference_->meshBvh(state_.scene));
    equation_.result = renderingEquationAt(traced, layout_.renderWidth, layout_.renderHeight, probe_.result->x,
                                           probe_.result->y, global);
    equation_.revision = state_.revision;
    equation_.x = probe_.result->x, equation_.y = probe_.result->y;
    equation_.global = global;
}

// The tree is traced once from the camera of the click (or of the moment T is pressed) and traced again
// along the same primary ray when the scene changes, so orbiting walks around it rather than re-aiming it.
void Viewer::updateRayTree(const trace::TraceScene& traced, bool clicked) {
    const ProbeState& p = state_.probe;
    if (!p.rayTree || !probe_.result || !probe_.result->hit) {
        rayTree_.view.reset();
        return;
    }
    std::optional<trace::TraceScene> fromClick;  // the scene seen from the click's camera, once it has moved
    if (!rayTree_.view || clicked || rayTree_.anchor != p.anchor.point) {
        rayTree_.view = recordRayTree(traced, layout_.renderWidth, layout_.renderHeight, p.x, p.y);
        rayTree_.anchor = p.anchor.point;
        fields_.rayTreeRay = 0;
    } else if (sameCamera(rayTree_.view->camera, state_.scene.camera)) {
        rerecordRayTree(traced, *rayTree_.view);
    } else {
        Scene seen = state_.scene;
        seen.camera = rayTree_.view->camera;
        fromClick.emplace(seen, reference_->meshBvh(seen));
        rerecordRayTree(*fromClick, *rayTree_.view);
    }
    const trace::TraceScene& tracedFrom = fromClick ? *fromClick : traced;
    const trace::RayTreeRecord& rec = rayTree_.view->record;
    rayTree_.panel = {};
    for (size_t k = 0; k < rec.rays.size(); ++k) {
        rayTree_.panel.rays.push_back(rayTreeRayLine(state_.scene, rec, k));
        rayTree_.panel.algebra.push_back(rayTreeAlgebra(tracedFrom, rec, k));
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
