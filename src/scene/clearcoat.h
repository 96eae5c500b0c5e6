// Clearcoat: glTF's KHR_materials_clearcoat on a pbr material, a thin clear dielectric layer (F0 = 0.04, index
// 1.5) with its own GGX roughness over the base (docs/lighting.md, "glTF's clearcoat layer"). Plain data with
// one name table, so that the scene file, scripts, the viewer and Python name its fields alike.
#pragma once

#include "scene/param_table.h"

#include <glm/vec2.hpp>

namespace shadelab {

struct Clearcoat {
    float factor = 0.0f;     // clearcoatFactor: how much of the coat there is, [0, 1]; 0 is the base alone
    float roughness = 0.0f;  // clearcoatRoughnessFactor: the coat's perceptual roughness, [0, 1], α = roughness²

    // The renderers' packing (shaders/lighting.glsl, clearcoatLight): (factor, roughness).
    glm::vec2 packed() const { return {factor, roughness}; }
    bool operator==(const Clearcoat& o) const { return packed() == o.packed(); }
    bool operator!=(const Clearcoat& o) const { return !(*this == o); }
};

// Each field's name (scene files, scripts, Python: glTF's names without "clearcoat" and "Factor"), all in [0, 1].
inline constexpr ParamField<Clearcoat> kClearcoatFields[] = {
    {"factor", &Clearcoat::factor},
    {"roughness", &Clearcoat::roughness},
};

// Some of the fields, each replacing the same one of a material's (a scene file's "clearcoat" object).
using ClearcoatOverride = ParamOverride<Clearcoat, kClearcoatFields>;

}  // namespace shadelab
