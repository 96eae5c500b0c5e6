// The data behind the viewer's directional-albedo plot: for each model, the fraction of light a
// white version of the selected material's lobe reflects, against the view angle, integrated numerically
// from the renderers' own shading functions (shading/directional_albedo.h). No ImGui: panels_lobe.cpp draws it.
#pragma once

#include "shading/directional_albedo.h"

#include <functional>
#include <string>
#include <vector>

namespace shadelab::app {

struct AlbedoPlotSettings {
    float phongExponent = 32.0f;  // Phong s; Blinn-Phong at equivalentBlinnExponent(s), as in the lobe plot
    float roughness = 0.5f;       // pbr, the GGX curve (a white metal: F0 = 1, no diffuse), and disney's
    float clearcoatGloss = 1.0f;  // disney, the clearcoat curve
    float sheenRoughness = 0.5f;  // pbr, glTF's sheen curve
    int angles = 20;              // view angles θv from 0 to 88°
    shading::AlbedoQuadrature quadrature{96, 48};

    bool operator==(const AlbedoPlotSettings& o) const {
        return phongExponent == o.phongExponent && roughness == o.roughness && clearcoatGloss == o.clearcoatGloss &&
               sheenRoughness == o.sheenRoughness && angles == o.angles && quadrature.theta == o.quadrature.theta &&
               quadrature.phi == o.quadrature.phi;
    }
};

struct AlbedoCurve {
    std::string label;
    std::vector<float> albedo;  // one value per view angle
    bool dashed = false;        // the energy-normalised lobes
};

struct AlbedoPlot {
    AlbedoPlotSettings settings;
    std::vector<float> viewAngles;  // θv in degrees
    std::vector<AlbedoCurve> curves;
};

// What one light of intensity 1 adds for (L, V) on a surface with normal (0, 0, 1): a shadeLight call.
using AlbedoShade = std::function<float(const shading::vec3& L, const shading::vec3& V)>;

// Lambert (white, the reference line at 1), Phong and Blinn-Phong with ms = 1, each as the lecture's lobe and
// normalised ((s+2)/2, (s+8)/8), GGX as a white metal without compensation and with it, then disney's lobes: its
// diffuse on white (with the retro-reflection that rises toward grazing), a white metal, and the clearcoat alone;
// then glTF's sheen lobe alone (white, pbr's layer), whose albedo the renderers read from their table.
// `previous`, the plot shown before, lends the curves whose inputs have not changed (the same values as
// integrating them again); the result never refers to it.
AlbedoPlot makeAlbedoPlot(const AlbedoPlotSettings& settings, const AlbedoPlot* previous = nullptr);

// Adds a curve integrated from `shade` at the plot's angles: the hook for curves this file does not know, e.g.
// GGX with multiple-scattering energy compensation once lighting.glsl has it.
void addAlbedoCurve(AlbedoPlot& plot, const std::string& label, const AlbedoShade& shade, bool dashed = false);

}  // namespace shadelab::app
