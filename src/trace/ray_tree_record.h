// RayTreeRecord: the rays one camera sample of the Whitted tracer followed, as WhittedIntegrator walked
// them (recordPrimary): the primary ray, one shadow ray per light it tested, and the reflected, refracted
// and see-through rays, each with its hit. Written by the integrator itself, never re-traced, so what the
// ray view shows is exactly what the reference computed.
#pragma once

#include "trace/ray.h"
#include "trace/trace_scene.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace shadelab::trace {

enum class TreeRayKind : uint8_t {
    Primary,    // from the eye through the pixel
    Shadow,     // from a hit toward one light (vis_l)
    Reflected,  // the mirror direction 2N(N·V) − V, weighted by kr (and a pbr surface's mirror-level specular)
    Refracted,  // Snell's law through a surface with kt
    Behind,     // the same line continued behind an alphaMode BLEND surface, at the same depth
};

const char* treeRayKindName(TreeRayKind kind);

struct TreeRay {
    TreeRayKind kind = TreeRayKind::Primary;
    int parent = -1;         // index of the ray whose hit spawned this one; -1 for the primary
    int depth = 0;           // bounces from the camera (shadow rays: their parent's)
    Ray ray;                 // origin and unit direction exactly as traced (secondary origins offset by ε·N)
    float after = 0.0f;      // hits at t <= after were not looked for (a see-through ray starts behind the surface)
    std::optional<Hit> hit;  // the nearest visible hit; none when the ray escaped (or, for a shadow ray, was clear)
    uint32_t hitId = 0;      // coverage id of `hit` (scene/coverage.h); 0 none
    glm::vec3 weight{1.0f};  // how much of this ray's radiance reaches the pixel (1 for the primary)
    // Shadow rays only.
    int light = -1;        // index into the scene's lights
    float tMax = 0.0f;     // distance to the light (infinity for a directional light)
    bool blocked = false;  // the tracer's answer: vis_l = 0
};

struct RayTreeRecord {
    std::vector<TreeRay> rays;  // depth first, in the order the integrator traced them; rays[0] is the primary
};

}  // namespace shadelab::trace
