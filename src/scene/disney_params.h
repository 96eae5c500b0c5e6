// DisneyParams: the principled BRDF's parameters beyond baseColor, metallic and roughness, which it shares with
// pbr (Burley 2012, "Physically Based Shading at Disney", §5.1; docs/lighting.md, "The Disney principled BRDF").
// Plain data with one name table, so that the scene file, scripts, the viewer and Python name them alike.
#pragma once

#include "scene/param_table.h"

#include <glm/vec4.hpp>

namespace shadelab {

struct DisneyParams {
    float subsurface = 0.0f;      // blends the Lambert-like diffuse toward Hanrahan-Krueger's flattened shape
    float specular = 0.5f;        // the dielectric's normal-incidence reflectance, 0.08·specular (0.5: F0 = 0.04)
    float specularTint = 0.0f;    // tints that reflectance toward the base colour's hue
    float anisotropic = 0.0f;     // stretches the highlight along the surface's tangent (aspect √(1 − 0.9·a))
    float sheen = 0.0f;           // a grazing retro-reflective layer for cloth
    float sheenTint = 0.5f;       // tints the sheen toward the base colour's hue
    float clearcoat = 0.0f;       // a second, fixed-index specular lobe (GTR1) on top: lacquer, car paint
    float clearcoatGloss = 1.0f;  // 0 a satin coat, 1 a gloss coat

    // The renderers' packing (shaders/lighting.glsl, shadeLightDisney): (subsurface, specular, specularTint,
    // anisotropic) and (sheen, sheenTint, clearcoat, clearcoatGloss).
    glm::vec4 lobes0() const { return {subsurface, specular, specularTint, anisotropic}; }
    glm::vec4 lobes1() const { return {sheen, sheenTint, clearcoat, clearcoatGloss}; }
    bool operator==(const DisneyParams& o) const { return lobes0() == o.lobes0() && lobes1() == o.lobes1(); }
    bool operator!=(const DisneyParams& o) const { return !(*this == o); }
};

// Each parameter's name (scene files, scripts, Python) and member, all in [0, 1].
using DisneyField = ParamField<DisneyParams>;
inline constexpr DisneyField kDisneyFields[] = {
    {"subsurface", &DisneyParams::subsurface},
    {"specular", &DisneyParams::specular},
    {"specularTint", &DisneyParams::specularTint},
    {"anisotropic", &DisneyParams::anisotropic},
    {"sheen", &DisneyParams::sheen},
    {"sheenTint", &DisneyParams::sheenTint},
    {"clearcoat", &DisneyParams::clearcoat},
    {"clearcoatGloss", &DisneyParams::clearcoatGloss},
};
inline constexpr int kDisneyFieldCount = int(sizeof kDisneyFields / sizeof kDisneyFields[0]);

// Some of the parameters, each replacing the same one of a material's (a scene file's "disney" object).
using DisneyOverride = ParamOverride<DisneyParams, kDisneyFields>;

}  // namespace shadelab
