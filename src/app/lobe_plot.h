// The data behind the viewer's lobe plots: each model's specular lobe in the plane of
// incidence for one material and one angle of incidence, as plain curves, so tests read exactly what the
// panel draws. No ImGui: panels_lobe.cpp draws these. The values come from shaders/lighting.glsl's functions.
#pragma once

#include "scene/material.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace shadelab::app {

// One material's lobe parameters and the view of it. Angles in degrees.
struct LobePlotSettings {
    float phongExponent = 32.0f;  // Phong s; Blinn-Phong is drawn at s and at equivalentBlinnExponent(s)
    float roughness = 0.5f;       // pbr: perceptual roughness, α = roughness²
    float metallic = 0.0f;        // pbr
    glm::vec3 baseColor{0.7f};    // pbr: F0 = mix(0.04, baseColor, metallic)
    // disney: the material's parameters (DisneyParams::lobes0, lobes1), Burley's defaults unless set
    glm::vec4 disney0{0.0f, 0.5f, 0.0f, 0.0f}, disney1{0.0f, 0.5f, 0.0f, 1.0f};
    // pbr under glTF's layers, packed as the renderers pack them (scene/material.h): `layered` (usesLayeredPbr) with
    // the specular layer and index (SpecularLayer::packed) and the anisotropy (Anisotropy::packed); the clear coat
    // (Clearcoat::packed; factor 0: none) and the transmission (transmissionPacked; factor 0: none).
    bool layered = false;
    glm::vec4 specLayer{0.04f, 0.04f, 0.04f, 1.0f};
    glm::vec3 aniso{0.0f};
    glm::vec2 coat{0.0f};
    glm::vec4 transmission{0.0f};
    float incidence = 30.0f;  // θi: the angle between N and L, [0, 89]
    float axis = 90.0f;       // the Cartesian plot's angle axis runs from 0 to this (zoom), (0, 90]
    int samples = 361;        // points per Cartesian curve, first at 0, last at `axis`
    int polarSamples = 1441;  // points per polar curve, over outgoing angles −90..90
};

enum class LobeModel { Phong, BlinnSame, BlinnEquivalent, Pbr, Disney };
inline constexpr int kLobeModels = 5;

struct LobeCurve {
    LobeModel model = LobeModel::Phong;
    std::string label;         // e.g. "(R·V)^32  Phong"
    float parameter = 0.0f;    // the exponent, or the roughness for pbr
    float peak = 0.0f;         // the largest value over the plane of incidence (the curve is scaled by 1/peak)
    std::vector<float> value;  // Cartesian: lobe / peak at the angle between R and V, `samples` points
    std::vector<float> polar;  // polar: lobe / peak at outgoing angle θo, `polarSamples` points
    // pbr under glTF's transmission only: the lobe through the surface seen from below at θo (measured from −N),
    // `polarSamples` points; then `polar` and this share one scale, the larger of the two peaks. Empty otherwise.
    std::vector<float> through;
};

// Both views of the five lobes. In the plane of incidence L lies at −θi from N and R at +θi. The Cartesian
// view follows V from R toward N and beyond: θo = θi − a for the angle a between R and V, so a runs over a
// fixed axis [0, axis] whatever the material (so that as s grows the lobe visibly narrows). The polar view
// sweeps V over θo ∈ [−90°, 90°] (the textbook figure: radius = lobe value). Each lobe is the specular term
// the renderers add for one light of intensity 1 (Phong/Blinn-Phong: the lecture's term; pbr: π·f_spec·N·L,
// the mean of its RGB, under glTF's specular layer, anisotropy and clear coat when the material has them; disney: its
// specular and clearcoat lobes, π·f·N·L, V in the tangent's plane), divided by its peak so the shapes compare;
// `peak` keeps the scale. A transmitting pbr material's light through the surface is drawn below it (`through`).
struct LobePlot {
    LobePlotSettings settings;
    std::vector<LobeCurve> curves;    // kLobeModels curves, in LobeModel order
    float angleAt(int i) const;       // the Cartesian sample's angle a between R and V, degrees
    float polarAngleAt(int i) const;  // the polar sample's outgoing angle θo, degrees (−90 at i = 0)
};

LobePlot makeLobePlot(const LobePlotSettings& settings);

// The settings for material `m`'s lobes: its roughness, metallic, base colour, disney's parameters and glTF's layers,
// packed as the renderers pack them; the exponent, the incidence and the view left at their defaults.
LobePlotSettings lobeSettingsOf(const Material& m);

// The half-width at half maximum of a Cartesian curve read from its data: the angle (degrees) where `value`
// first falls below half of value[0], linearly interpolated between samples spread evenly over [0, axis].
// `axis` when it never does.
float halfWidthAtHalfMaximum(const std::vector<float>& value, float axis);

// A direction in the plane of incidence as the polar plot draws it: x toward R's side, y along N.
glm::vec2 polarDirection(float degrees);

// Where a probe's vectors fall in the plane of incidence of (N, L): x along the tangent toward R's side, y
// along N, and the angle (degrees) by which the vector leaves that plane. For L = N any tangent will do.
struct PlaneOfIncidence {
    glm::vec2 L{0.0f}, V{0.0f}, R{0.0f};  // unit 2D directions (the projections, renormalised)
    float incidence = 0.0f;               // θi = angle between N and L, degrees
    float vOutOfPlane = 0.0f;             // angle between V and the plane, degrees
};
PlaneOfIncidence planeOfIncidence(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V);

}  // namespace shadelab::app
