// SpecularLayer: glTF's KHR_materials_specular on a pbr material, with KHR_materials_ior's index (Material::ior):
// the dielectric's reflectance at normal incidence ((ior − 1)/(ior + 1))² tinted by `color`, and the weight of
// the whole dielectric specular lobe (docs/lighting.md, "glTF's specular and ior"). Plain data.
#pragma once

#include <algorithm>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>

namespace shadelab {

struct SpecularLayer {
    float factor = 1.0f;    // specularFactor: the dielectric specular lobe's weight, [0, 1]
    glm::vec3 color{1.0f};  // specularColorFactor: tints the dielectric's F0, >= 0 (F0 is clamped to 1)

    bool operator==(const SpecularLayer& o) const { return factor == o.factor && color == o.color; }
    bool operator!=(const SpecularLayer& o) const { return !(*this == o); }

    // The renderers' packing (shaders/lighting.glsl, shadeLightPbrSpecular): the dielectric's F0 for index `ior`,
    // min(((ior − 1)/(ior + 1))² · color, 1), and the factor. Computed in double, so that ior 1.5 gives exactly
    // the float nearest 0.04, pbr's constant.
    glm::vec4 packed(float ior) const {
        const double r = (double(ior) - 1.0) / (double(ior) + 1.0);
        const double f0 = r * r;
        const auto tint = [&](float c) { return float(std::min(f0 * double(c), 1.0)); };
        return {tint(color.r), tint(color.g), tint(color.b), factor};
    }
};

// Whether a pbr material with this layer and index `ior` is shaded by the layered function (not pbr's own, whose
// dielectric F0 is 0.04 and weight 1): a layer off its defaults, or an index other than 1.5.
inline bool hasSpecularLayer(const SpecularLayer& layer, float ior) { return layer != SpecularLayer{} || ior != 1.5f; }

// Some of the layer's fields, each replacing the same one of a material's (a scene file's "specular" object).
struct SpecularLayerOverride {
    std::optional<float> factor;
    std::optional<glm::vec3> color;

    bool empty() const { return !factor && !color; }
    void applyTo(SpecularLayer& l) const {
        if (factor) l.factor = *factor;
        if (color) l.color = *color;
    }
    bool operator==(const SpecularLayerOverride& o) const { return factor == o.factor && color == o.color; }
};

}  // namespace shadelab
