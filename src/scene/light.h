// Light: point or directional, RGB intensity Il, optional attenuation 1/(kc + kl·d + kq·d²) (design.md §1).
#pragma once

#include <glm/vec3.hpp>
#include <string>

namespace shadelab {

enum class LightType { Point, Directional };

struct Light {
    LightType type = LightType::Point;
    std::string name;
    glm::vec3 position{0.0f, 5.0f, 5.0f};    // point lights, world units
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // directional lights: the direction light travels
    glm::vec3 color{1.0f};                   // Il, linear RGB intensity
    glm::vec3 attenuation{1.0f, 0.0f, 0.0f}; // (kc, kl, kq); point lights only
};

}  // namespace shadelab
