// Anisotropy: glTF's KHR_materials_anisotropy on a pbr material, the GGX lobe stretched along a direction in the
// tangent plane, as brushed metal or a turned part shows it (docs/lighting.md, "glTF's anisotropy"). Plain data.
#pragma once

#include <cmath>
#include <glm/vec3.hpp>
#include <optional>

namespace shadelab {

struct Anisotropy {
    float strength = 0.0f;  // anisotropyStrength: [0, 1], 0 the isotropic lobe; αt = mix(α, 1, strength²)
    float rotation = 0.0f;  // anisotropyRotation: radians, counter-clockwise from the tangent in the tangent plane

    // The renderers' packing (shaders/gltf_layers.glsl, anisotropyDirection): (strength, cos rotation, sin rotation),
    // the cosine and sine computed here once, in double, so that every renderer reads the same floats.
    glm::vec3 packed() const {
        return {strength, float(std::cos(double(rotation))), float(std::sin(double(rotation)))};
    }
    bool on() const { return strength > 0.0f; }
    bool operator==(const Anisotropy& o) const { return strength == o.strength && rotation == o.rotation; }
    bool operator!=(const Anisotropy& o) const { return !(*this == o); }
};

// The largest |rotation| a scene file takes, in radians (any angle is one of these turned by whole turns).
inline constexpr float kMaxAnisotropyRotation = 100.0f;

// Some of the fields, each replacing the same one of a material's (a scene file's "anisotropy" object).
struct AnisotropyOverride {
    std::optional<float> strength, rotation;

    bool empty() const { return !strength && !rotation; }
    void applyTo(Anisotropy& a) const {
        if (strength) a.strength = *strength;
        if (rotation) a.rotation = *rotation;
    }
    bool operator==(const AnisotropyOverride& o) const { return strength == o.strength && rotation == o.rotation; }
};

}  // namespace shadelab
