// Light: point or directional, RGB intensity Il, optional attenuation 1/(kc + kl·d + kq·d²) (design.md §1),
// and the name table of its type (the words of a scene file's and a script's "type").
#pragma once

#include "util/name_table.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string>

namespace shadelab {

enum class LightType { Point, Directional };

inline constexpr EnumName<LightType> kLightTypeNames[] = {
    {LightType::Point, "point"},
    {LightType::Directional, "directional"},
};

inline const char* toString(LightType t) { return nameOf(kLightTypeNames, t); }
inline std::optional<LightType> parseLightType(std::string_view name) { return lookupName(kLightTypeNames, name); }

struct Light {
    LightType type = LightType::Point;
    std::string name;
    glm::vec3 position{0.0f, 5.0f, 5.0f};     // point lights, world units
    glm::vec3 direction{0.0f, -1.0f, 0.0f};   // directional lights: the direction light travels
    glm::vec3 color{1.0f};                    // Il, linear RGB intensity
    glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // (kc, kl, kq); point lights only
};

// Each set field replaces the same field of the light it is applied to (a viewer script's addLight and
// setLight; a scene file's light reads the same fields the same way).
struct LightOverride {
    std::optional<glm::vec3> position;   // world units
    std::optional<glm::vec3> direction;  // unit vector, the direction light travels
    std::optional<glm::vec3> color;      // Il, linear RGB intensity

    void applyTo(Light& l) const {
        if (position) l.position = *position;
        if (direction) l.direction = *direction;
        if (color) l.color = *color;
    }
};

}  // namespace shadelab
