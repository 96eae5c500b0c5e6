// Transmission: glTF's KHR_materials_transmission on a pbr material, the share of the dielectric's diffuse light
// that passes through the surface instead (thin glass, plastic film, a lamp shade), along a GGX lobe of the
// material's roughness (docs/lighting.md, "glTF's transmission and volume"). Plain data.
#pragma once

#include <optional>

namespace shadelab {

struct Transmission {
    float factor = 0.0f;  // transmissionFactor: [0, 1], the share of the diffuse lobe replaced; 0 is pbr's own

    bool on() const { return factor > 0.0f; }
    bool operator==(const Transmission& o) const { return factor == o.factor; }
    bool operator!=(const Transmission& o) const { return !(*this == o); }
};

// A scene file's "transmission" object: its field, replacing the material's when set.
struct TransmissionOverride {
    std::optional<float> factor;

    bool empty() const { return !factor; }
    void applyTo(Transmission& t) const {
        if (factor) t.factor = *factor;
    }
    bool operator==(const TransmissionOverride& o) const { return factor == o.factor; }
};

}  // namespace shadelab
