#include "app/probe_diagram.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace shadelab::app {
namespace {

float angleBetween(const glm::vec3& a, const glm::vec3& b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)));
}

// The unit 2D direction at `deg` from N (up), to the right when `right`.
glm::vec2 at(float deg, bool right) {
    const float r = glm::radians(deg);
    return {right ? std::sin(r) : -std::sin(r), std::cos(r)};
}

}  // namespace

ProbeDiagram probeDiagram(const ProbeResult& probe, size_t light) {
    ProbeDiagram d;
    if (!probe.hit) return d;
    const glm::vec3 N = probe.N, V = probe.V;
    d.arrows.push_back({"N", {0.0f, 1.0f}, 0.0f});
    // The surface direction toward R (away from L): it decides on which side V and H are drawn.
    glm::vec3 towardR(0.0f);
    if (!probe.lights.empty()) {
        const ProbeLight& l = probe.lights[std::min(light, probe.lights.size() - 1)];
        d.lit = l.NoL > 0.0f;
        towardR = l.R - N * glm::dot(N, l.R);
        const float thetaL = angleBetween(N, l.L), thetaR = angleBetween(N, l.R), thetaH = angleBetween(N, l.H);
        const bool hRight = glm::dot(l.H - N * glm::dot(N, l.H), towardR) >= 0.0f;
        d.arrows.push_back({"L", at(thetaL, false), thetaL});
        d.arrows.push_back({"R", at(thetaR, true), thetaR});
        d.arrows.push_back({"H", at(thetaH, hRight), thetaH});
        // V against the plane spanned by N and L (the plane of incidence).
        glm::vec3 normal = glm::cross(N, l.L);
        if (glm::length(normal) > 1e-6f)
            d.vOutOfPlaneDeg =
                glm::degrees(std::asin(std::clamp(std::fabs(glm::dot(glm::normalize(normal), V)), 0.0f, 1.0f)));
    }
    const float thetaV = angleBetween(N, V);
    const bool vRight = glm::length(towardR) < 1e-6f || glm::dot(V - N * glm::dot(N, V), towardR) >= 0.0f;
    d.arrows.push_back({"V", at(thetaV, vRight), thetaV});
    return d;
}

}  // namespace shadelab::app
