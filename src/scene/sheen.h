// Sheen: glTF's KHR_materials_sheen on a pbr material, a layer of fibres over the base that reflects toward
// grazing angles (velvet, cloth, dust): Conty & Kulla's "Charlie" distribution with Estevez & Kulla's
// visibility, the base dimmed by what the sheen reflects (docs/lighting.md, "glTF's sheen layer"). Plain data.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>

namespace shadelab {

struct Sheen {
    glm::vec3 color{0.0f};   // sheenColorFactor: the fibres' reflectance, linear RGB in [0, 1]; 0 is the base alone
    float roughness = 0.0f;  // sheenRoughnessFactor: the fibres' perceptual roughness, [0, 1], α = roughness²

    // The renderers' packing (shaders/gltf_layers.glsl, sheenLight): (color, roughness).
    glm::vec4 packed() const { return {color, roughness}; }
    // Whether there is any sheen: a colour of 0 reflects nothing and leaves the base exactly as it is.
    bool on() const { return color.r > 0.0f || color.g > 0.0f || color.b > 0.0f; }
    bool operator==(const Sheen& o) const { return packed() == o.packed(); }
    bool operator!=(const Sheen& o) const { return !(*this == o); }
};

// Some of the layer's fields, each replacing the same one of a material's (a scene file's "sheen" object).
struct SheenOverride {
    std::optional<glm::vec3> color;
    std::optional<float> roughness;

    bool empty() const { return !color && !roughness; }
    void applyTo(Sheen& s) const {
        if (color) s.color = *color;
        if (roughness) s.roughness = *roughness;
    }
    bool operator==(const SheenOverride& o) const { return color == o.color && roughness == o.roughness; }
};

}  // namespace shadelab
