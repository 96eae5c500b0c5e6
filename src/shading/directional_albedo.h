// Directional albedo: the fraction of light a surface reflects toward V, integrated numerically from the same
// shading functions the renderers run (shaders/lighting.glsl). For the viewer's albedo plot and the energy
// tests (docs/lighting.md, "Directional albedo: where each model's energy goes"). No GL and no scene types.
#pragma once

#include "shading/lighting.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab::shading {

struct AlbedoQuadrature {
    int theta = 128;  // rings about the lobe axis, packed toward it (θ' = π t³)
    int phi = 64;     // sectors around it
};

// ρ(V) = (1/π) ∫_sphere shade(L) dω_L for a surface with normal (0, 0, 1) and V at `NoV` in the xz plane, where
// shade(L, V) returns what one light of intensity 1 adds (shadeLight: π·f·N·L, zero below the horizon), so
// ρ = ∫ f·N·L dω, the albedo of design.md §7's π-scaled lights. A white Lambertian surface gives 1.
// The rings are centred on the mirror direction of V and packed toward it, so lobes as narrow as s = 10000
// (Phong) or roughness 0.05 are resolved by the same 8k samples as Lambert. Midpoint rule in (t, φ).
// `shade` is any callable float(vec3 L, vec3 V): the hook for a curve this file does not know (e.g. a
// BRDF with multiple-scattering compensation).
template <typename Shade>
float directionalAlbedo(Shade shade, float NoV, AlbedoQuadrature q = {}) {
    const float cosV = glm::clamp(NoV, 0.0f, 1.0f);
    const vec3 V(std::sqrt(1.0f - cosV * cosV), 0.0f, cosV);
    const vec3 A(-V.x, 0.0f, V.z);  // the mirror direction of V about N
    // An orthonormal basis (T, B, A); A lies in the xz plane, so B = y works for every V.
    const vec3 B(0.0f, 1.0f, 0.0f);
    const vec3 T = cross(B, A);
    const double pi = 3.14159265358979323846;
    // The sectors' directions in the (T, B) plane, the same for every ring: computed once, not per sample.
    std::vector<vec3> sector(size_t(std::max(q.phi, 0)));
    for (int j = 0; j < q.phi; ++j) {
        const double phi = 2.0 * pi * (double(j) + 0.5) / double(q.phi);
        sector[size_t(j)] = float(std::cos(phi)) * T + float(std::sin(phi)) * B;
    }
    double sum = 0.0;
    for (int i = 0; i < q.theta; ++i) {
        const double t = (double(i) + 0.5) / double(q.theta);
        const double theta = pi * t * t * t;
        const double weight = std::sin(theta) * 3.0 * pi * t * t;  // sin θ' dθ'/dt
        const float ct = float(std::cos(theta)), st = float(std::sin(theta));
        double ring = 0.0;
        for (const vec3& d : sector) ring += double(shade(ct * A + st * d, V));
        sum += ring * weight;
    }
    return float(sum / double(q.theta) * (2.0 * pi / double(q.phi)) / pi);
}

// The albedo of one model's terms for a material in shadeLight's slots (md, ms, s; for SL_MODEL_PBR the
// diffuse colour, F0 and the roughness), as the mean of its RGB.
inline float modelAlbedo(int model, float NoV, vec3 md, vec3 ms, float s, bool diffuse, bool specular,
                         AlbedoQuadrature q = {}) {
    const vec3 N(0.0f, 0.0f, 1.0f);
    return directionalAlbedo(
        [&](vec3 L, vec3 V) {
            const vec3 I = shadeLight(N, L, V, vec3(1.0f), md, ms, s, model, diffuse, specular);
            return (I.x + I.y + I.z) / 3.0f;
        },
        NoV, q);
}

}  // namespace shadelab::shading
