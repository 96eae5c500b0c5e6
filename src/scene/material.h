// Material: the lecture's Phong coefficients plus the tracer's kr/kt/ior (design.md §1). Plain data.
// MaterialOverride lets a scene file replace any subset of a material imported from glTF.
#pragma once

#include <glm/vec3.hpp>
#include <optional>

namespace shadelab {

struct Material {
    glm::vec3 ma{0.1f};  // ambient coefficient, linear RGB
    glm::vec3 md{0.7f};  // diffuse coefficient, linear RGB
    glm::vec3 ms{0.3f};  // specular coefficient, linear RGB
    float s = 32.0f;     // shininess exponent, [0, 10000]
    glm::vec3 kr{0.0f};  // reflectivity, RGB (tracer and issue-5 raster reflections)
    glm::vec3 kt{0.0f};  // transmission, RGB
    float ior = 1.5f;    // index of refraction, > 0
};

// Each set field replaces the same field of the material it is applied to.
struct MaterialOverride {
    std::optional<glm::vec3> ma, md, ms;
    std::optional<float> s;
    std::optional<glm::vec3> kr, kt;
    std::optional<float> ior;

    bool empty() const { return !ma && !md && !ms && !s && !kr && !kt && !ior; }
    void applyTo(Material& m) const {
        if (ma) m.ma = *ma;
        if (md) m.md = *md;
        if (ms) m.ms = *ms;
        if (s) m.s = *s;
        if (kr) m.kr = *kr;
        if (kt) m.kt = *kt;
        if (ior) m.ior = *ior;
    }
};

inline constexpr float kMaxShininess = 10000.0f;

}  // namespace shadelab
