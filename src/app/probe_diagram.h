// The probe's 2D diagram: the textbook figure of the plane of incidence, in which every vector is
// drawn at its true angle from N and full length, so none collapses to a dot the way V (pointing at the
// camera) and N (near a sphere's centre) do in the 3D overlay. N points up; L is drawn to the left and R to
// the right of N, as in the lecture's figure; V and H on the side their component along the surface takes
// relative to R's. How far V leaves the plane of incidence is given as an angle, since the figure is flat.
// Plain geometry, no ImGui: the probe window draws it and the tests read it.
#pragma once

#include "probe/probe.h"

#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace shadelab::app {

struct DiagramArrow {
    std::string name;       // "N", "L", "R", "V", "H"
    glm::vec2 dir{0.0f};    // unit, x right, y up; the surface is the line y = 0
    float angleDeg = 0.0f;  // angle from N, degrees
};

struct ProbeDiagram {
    std::vector<DiagramArrow> arrows;  // N, then L, R, H of the chosen light, then V
    float vOutOfPlaneDeg = 0.0f;       // angle between V and the plane of N and L
    bool lit = false;                  // N·L > 0
};

// For light `light` of the probe (its first when out of range); empty without a hit or without lights
// (then only N and V).
ProbeDiagram probeDiagram(const ProbeResult& probe, size_t light);

}  // namespace shadelab::app
