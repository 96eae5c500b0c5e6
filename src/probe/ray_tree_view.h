// The ray view (teaching): the Whitted ray tree the tracer follows from one pixel, recorded by the
// integrator itself (WhittedIntegrator::recordPrimary), as segments to draw in 3D and as the words and
// algebra of each ray. The viewer draws the segments over its image and lists the rays in the probe
// window; `render --ray-tree X,Y` draws them into the PNG. No GL.
#pragma once

#include "scene/scene.h"
#include "trace/ray_tree_record.h"
#include "trace/trace_scene.h"

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadelab {

struct RayTreeView {
    Camera camera;                            // the camera it was traced with (the secondary-ray ε depends on the eye)
    trace::Ray primary;                       // the ray through the pixel, from the eye it was probed from
    trace::RayTreeRecord record;              // what the tracer did with it
    int width = 0, height = 0, x = 0, y = 0;  // the pixel, in the image it was probed in
};

// Records the tree of pixel (x, y)'s centre ray in a width x height image of the scene's camera, at the
// scene's own depth and limits, exactly as the reference traces that pixel.
RayTreeView recordRayTree(const trace::TraceScene& scene, int width, int height, int x, int y);
// The same primary ray in a scene that has changed (a material, a light): the tree again, from the same eye.
// `scene` must have been built with view.camera (sameCamera), so that it is the tree the reference would trace.
void rerecordRayTree(const trace::TraceScene& scene, RayTreeView& view);
bool sameCamera(const Camera& a, const Camera& b);

struct RayTreeSegment {
    glm::vec3 from{0.0f}, to{0.0f};
    glm::vec3 color{1.0f};  // display colour (sRGB-ish), by kind; a blocked shadow ray is red
    std::string label;      // "t 4.12", "t 3.50 blocked by glass (sphere 1)", "escapes"
    int ray = 0;            // index into the record
};

// One segment per recorded ray: to its hit; a shadow ray to its light (a directional one, and a ray that
// escapes, for `escape` world units); a blocked shadow ray to its blocker.
std::vector<RayTreeSegment> rayTreeSegments(const Scene& scene, const trace::RayTreeRecord& record, float escape);

// "2 reflected (depth 1) → mirror (sphere 2), t 3.21": a ray of the record in words, for the probe window.
std::string rayTreeRayLine(const Scene& scene, const trace::RayTreeRecord& record, size_t ray);

// The lecture's algebra for ray `ray` of the record (trace/ray_algebra.h): a shadow ray's own test
// against the light's distance, or the hit's intersection; an escaped ray says it met nothing.
std::vector<std::string> rayTreeAlgebra(const trace::TraceScene& scene, const trace::RayTreeRecord& record, size_t ray);

}  // namespace shadelab
