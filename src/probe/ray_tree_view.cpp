// The ray view: the tree recorded at the reference's own depth, limits and texture footprint, and its
// segments and words.
#include "probe/ray_tree_view.h"

#include "scene/object_ref.h"
#include "scene/view.h"
#include "trace/integrator.h"
#include "trace/ray_algebra.h"
#include "trace/tile_renderer.h"
#include "trace/trace_settings.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

namespace shadelab {
namespace {

// As the reference traces a pixel (trace_job.cpp): the scene's depth, the default limits, the view's footprint.
void record(const trace::TraceScene& scene, RayTreeView& view) {
    trace::WhittedIntegrator integrator(scene, scene.scene().maxDepth, trace::RayTreeLimits{});
    integrator.setPixelFootprint(trace::pixelFootprint(makeViewSetup(scene.scene(), view.width, view.height)));
    integrator.recordPrimary(view.primary, view.record);
}

std::string number(float t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", double(t));
    return buf;
}

std::string lightName(const Scene& scene, int light) {
    const std::string n = "L" + std::to_string(light + 1);
    const std::string& name = scene.lights[size_t(light)].name;
    return name.empty() ? n : n + " " + name;
}

}  // namespace

RayTreeView recordRayTree(const trace::TraceScene& scene, int width, int height, int x, int y) {
    RayTreeView view;
    view.width = width, view.height = height, view.x = x, view.y = y;
    view.camera = scene.scene().camera;
    view.primary = trace::sampleRay(makeViewSetup(scene.scene(), width, height), 1, x, y, 0, 0);
    record(scene, view);
    return view;
}

void rerecordRayTree(const trace::TraceScene& scene, RayTreeView& view) { record(scene, view); }

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.target == b.target && a.up == b.up && a.fovY == b.fovY;
}

std::vector<RayTreeSegment> rayTreeSegments(const Scene& scene, const trace::RayTreeRecord& rec, float escape) {
    using trace::TreeRayKind;
    std::vector<RayTreeSegment> out;
    for (size_t k = 0; k < rec.rays.size(); ++k) {
        const trace::TreeRay& r = rec.rays[k];
        RayTreeSegment s;
        s.ray = int(k);
        s.from = r.ray.origin;
        switch (r.kind) {
            case TreeRayKind::Primary: s.color = glm::vec3(1.0f); break;
            case TreeRayKind::Reflected: s.color = glm::vec3(0.3f, 0.75f, 1.0f); break;
            case TreeRayKind::Refracted: s.color = glm::vec3(0.35f, 1.0f, 0.5f); break;
            case TreeRayKind::Behind: s.color = glm::vec3(0.7f); break;
            case TreeRayKind::Shadow:
                s.color = r.blocked ? glm::vec3(1.0f, 0.25f, 0.2f) : glm::vec3(1.0f, 0.85f, 0.2f);
                break;
        }
        if (r.kind == TreeRayKind::Shadow) {
            const std::string name = lightName(scene, r.light);
            if (r.blocked && r.hit) {
                s.to = r.ray.origin + r.hit->t * r.ray.dir;
                s.label = name + ": blocked by " + objectLabel(scene, r.hitId) + " at t " + number(r.hit->t);
            } else if (std::isfinite(r.tMax)) {
                s.to = r.ray.origin + r.tMax * r.ray.dir;
                s.label = name + (r.blocked ? ": blocked" : ": lit") + ", t " + number(r.tMax);
            } else {
                s.to = r.ray.origin + escape * r.ray.dir;
                s.label = name + (r.blocked ? ": blocked" : ": lit (directional)");
            }
        } else if (r.hit) {
            s.to = r.ray.origin + r.hit->t * r.ray.dir;
            s.label = "t " + number(r.hit->t);
        } else {
            s.to = r.ray.origin + escape * r.ray.dir;
            s.label = "escapes";
        }
        out.push_back(s);
    }
    return out;
}

std::string rayTreeRayLine(const Scene& scene, const trace::RayTreeRecord& rec, size_t k) {
    const trace::TreeRay& r = rec.rays[k];
    std::string line = std::to_string(k) + " " + trace::treeRayKindName(r.kind);
    if (r.kind != trace::TreeRayKind::Primary && r.kind != trace::TreeRayKind::Shadow)
        line += " (depth " + std::to_string(r.depth) + ")";
    if (r.kind == trace::TreeRayKind::Shadow) {
        line += " to " + lightName(scene, r.light);
        line += r.blocked ? (r.hit ? ": blocked by " + objectLabel(scene, r.hitId) + ", t " + number(r.hit->t)
                                   : std::string(": blocked"))
                          : ": lit";
    } else if (r.hit) {
        line += " -> " + objectLabel(scene, r.hitId) + ", t " + number(r.hit->t);
    } else {
        line += ": escapes, reads the background";
    }
    return line;
}

std::vector<std::string> rayTreeAlgebra(const trace::TraceScene& scene, const trace::RayTreeRecord& rec, size_t k) {
    const trace::TreeRay& r = rec.rays[k];
    if (r.hit) {
        std::vector<std::string> lines = trace::rayAlgebraLines(scene, r.ray, *r.hit);
        if (r.kind == trace::TreeRayKind::Shadow)
            lines.push_back("t < " + number(r.tMax) + " (the light's distance): the light is blocked");
        if (r.after > 0.0f) lines.push_back("(hits before t " + number(r.after) + " were behind the surface)");
        return lines;
    }
    std::vector<std::string> lines;
    char buf[160];
    std::snprintf(buf, sizeof buf, "o = (%.4g, %.4g, %.4g), d = (%.4g, %.4g, %.4g)", double(r.ray.origin.x),
                  double(r.ray.origin.y), double(r.ray.origin.z), double(r.ray.dir.x), double(r.ray.dir.y),
                  double(r.ray.dir.z));
    lines.push_back(buf);
    if (r.kind == trace::TreeRayKind::Shadow)
        lines.push_back(std::isfinite(r.tMax) ? "no surface at 0 < t < " + number(r.tMax) + ": the light is visible"
                                              : "no surface at t > 0: the directional light is visible");
    else
        lines.push_back("no surface at t > 0: the ray escapes and reads the background");
    return lines;
}

}  // namespace shadelab
