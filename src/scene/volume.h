// Volume: glTF's KHR_materials_volume on a transmitting pbr material, the medium inside the surface: light
// refracts into it by the material's index and is absorbed along its way (Beer–Lambert) toward the attenuation
// colour (docs/lighting.md, "glTF's transmission and volume"). Without it (thickness 0) a transmitting surface is
// a thin wall: light passes straight through. Plain data.
#pragma once

#include <cmath>
#include <glm/vec3.hpp>
#include <limits>
#include <optional>

namespace shadelab {

struct Volume {
    float thickness = 0.0f;  // thicknessFactor: the medium's thickness in scene units, >= 0; 0 is a thin wall
    // attenuationDistance: how far light travels in the medium before only attenuationColor of it is left, > 0;
    // infinite (the default) absorbs nothing.
    float attenuationDistance = std::numeric_limits<float>::infinity();
    glm::vec3 attenuationColor{1.0f};  // linear RGB in [0, 1]

    bool on() const { return thickness > 0.0f; }
    // What of each colour is left after `distance` in the medium: attenuationColor^(distance / attenuationDistance)
    // (Beer–Lambert with σ = −ln(attenuationColor) / attenuationDistance), in double so that every renderer reads
    // the same floats.
    glm::vec3 transmittance(float distance) const {
        if (!std::isfinite(attenuationDistance) || !(distance > 0.0f)) return glm::vec3(1.0f);
        const double x = double(distance) / double(attenuationDistance);
        return {float(std::pow(double(attenuationColor.r), x)), float(std::pow(double(attenuationColor.g), x)),
                float(std::pow(double(attenuationColor.b), x))};
    }
    bool operator==(const Volume& o) const {
        return thickness == o.thickness && attenuationDistance == o.attenuationDistance &&
               attenuationColor == o.attenuationColor;
    }
    bool operator!=(const Volume& o) const { return !(*this == o); }
};

// The largest thickness and attenuation distance a scene file takes (scene units).
inline constexpr float kMaxVolumeLength = 1e6f;

// Some of the fields, each replacing the same one of a material's (a scene file's "volume" object).
struct VolumeOverride {
    std::optional<float> thickness, attenuationDistance;
    std::optional<glm::vec3> attenuationColor;

    bool empty() const { return !thickness && !attenuationDistance && !attenuationColor; }
    void applyTo(Volume& v) const {
        if (thickness) v.thickness = *thickness;
        if (attenuationDistance) v.attenuationDistance = *attenuationDistance;
        if (attenuationColor) v.attenuationColor = *attenuationColor;
    }
    bool operator==(const VolumeOverride& o) const {
        return thickness == o.thickness && attenuationDistance == o.attenuationDistance &&
               attenuationColor == o.attenuationColor;
    }
};

}  // namespace shadelab
