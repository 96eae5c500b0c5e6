// Light: point, spot or directional, RGB intensity Il, optional attenuation 1/(kc + kl·d + kq·d²) (design.md §1),
// a spot light's cone and a positional light's range (KHR_lights_punctual, docs/lighting.md "Spot lights"), and
// the name table of its type (the words of a scene file's and a script's "type").
#pragma once

#include "util/name_table.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string>

namespace shadelab {

enum class LightType { Point, Directional, Spot };

inline constexpr EnumName<LightType> kLightTypeNames[] = {
    {LightType::Point, "point"},
    {LightType::Directional, "directional"},
    {LightType::Spot, "spot"},
};

// Point and spot lights sit at a position (and may have a range); a directional light has none.
constexpr bool hasPosition(LightType t) {
    switch (t) {
        case LightType::Point:
        case LightType::Spot: return true;
        case LightType::Directional: return false;
    }
    return false;
}

// A spot's cone angles, radians from its axis, within [0, kMaxConeAngle] with inner <= outer: full intensity
// inside the inner cone, none outside the outer one. The defaults are KHR_lights_punctual's.
inline constexpr float kMaxConeAngle = 1.57079632679489662f;  // π/2
inline constexpr float kDefaultInnerConeAngle = 0.0f;
inline constexpr float kDefaultOuterConeAngle = 0.785398163397448310f;  // π/4

inline const char* toString(LightType t) { return nameOf(kLightTypeNames, t); }
inline std::optional<LightType> parseLightType(std::string_view name) { return lookupName(kLightTypeNames, name); }

struct Light {
    LightType type = LightType::Point;
    std::string name;
    glm::vec3 position{0.0f, 5.0f, 5.0f};           // point and spot lights, world units
    glm::vec3 direction{0.0f, -1.0f, 0.0f};         // directional and spot lights: the direction light travels
    glm::vec3 color{1.0f};                          // Il, linear RGB intensity
    glm::vec3 attenuation{1.0f, 0.0f, 0.0f};        // (kc, kl, kq); point and spot lights only
    float innerConeAngle = kDefaultInnerConeAngle;  // spot lights, radians
    float outerConeAngle = kDefaultOuterConeAngle;  // spot lights, radians
    float range = 0.0f;  // point and spot lights: the distance where their light ends (> 0), or 0 for none

    bool positional() const { return hasPosition(type); }
};

// Each set field replaces the same field of the light it is applied to (a viewer script's addLight and
// setLight; a scene file's light reads the same fields the same way).
struct LightOverride {
    std::optional<glm::vec3> position;    // world units
    std::optional<glm::vec3> direction;   // unit vector, the direction light travels
    std::optional<glm::vec3> color;       // Il, linear RGB intensity
    std::optional<float> innerConeAngle;  // spot lights, radians in [0, π/2]
    std::optional<float> outerConeAngle;  // spot lights, radians in [0, π/2]
    std::optional<float> range;           // point and spot lights, > 0

    void applyTo(Light& l) const {
        if (position) l.position = *position;
        if (direction) l.direction = *direction;
        if (color) l.color = *color;
        if (innerConeAngle) l.innerConeAngle = *innerConeAngle;
        if (outerConeAngle) l.outerConeAngle = *outerConeAngle;
        if (range) l.range = *range;
    }
};

}  // namespace shadelab
