// Material: the lecture's Phong coefficients, the glTF metallic-roughness fields of the pbr model (design.md
// §7) and the tracer's kr/kt/ior (design.md §1). Plain data. MaterialOverride lets a scene file replace any
// subset of a material imported from glTF, and carries one model's fields over to the other's when only one
// model's are given (docs/scene-format.md, "Materials under each model").
#pragma once

#include "scene/texture.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <optional>

namespace shadelab {

enum class AlphaMode : int { Opaque = 0, Mask = 1, Blend = 2 };

struct Material {
    glm::vec3 ma{0.1f};         // ambient coefficient, linear RGB
    glm::vec3 md{0.7f};         // diffuse coefficient, linear RGB
    glm::vec3 ms{0.3f};         // specular coefficient, linear RGB
    float s = 32.0f;            // shininess exponent, [0, 10000]
    glm::vec3 kr{0.0f};         // reflectivity, RGB (tracer and raster reflections)
    glm::vec3 kt{0.0f};         // transmission, RGB
    float ior = 1.5f;           // index of refraction, > 0
    glm::vec3 baseColor{0.7f};  // pbr: base colour, linear RGB in [0, 1] (= md by default)
    float metallic = 0.0f;      // pbr: [0, 1], 0 dielectric (F0 = 0.04), 1 metal (F0 = baseColor)
    float roughness = 0.4925f;  // pbr: perceptual roughness in [0, 1], α = roughness²; ≈ s = 32's equivalent
    glm::vec3 emission{0.0f};   // emitted radiance, linear RGB, >= 0, from both sides: an area light under the
                                // path tracer; the other renderers add it to the surface's colour (design.md §8)
    // glTF baseColorTexture (linear RGBA after sRGB decoding): multiplies baseColor under pbr and md, ma under
    // Phong (docs/gltf-import.md). Imported only; a scene file cannot set it.
    TextureBinding baseColorTexture;
    // The other glTF maps (docs/gltf-import.md, "Textures"), all linear and imported only. Metallic-roughness:
    // blue multiplies metallic, green roughness, and the model's coefficients are re-derived per texel.
    // Normal: tangent space, strength = the normal scale, tangents from MeshGeometry::tangents. Occlusion:
    // red, 1 + strength·(R − 1), scales the indirect (ambient, environment) light only.
    TextureBinding metallicRoughnessTexture;
    TextureBinding normalTexture;
    TextureBinding occlusionTexture;
    // glTF alphaMode with the base colour factor's alpha (times the base-colour texture's): Opaque ignores it,
    // Mask keeps what reaches alphaCutoff, Blend composites over what lies behind (docs/gltf-import.md).
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alpha = 1.0f;        // baseColorFactor[3], [0, 1]
    float alphaCutoff = 0.5f;  // MASK only, >= 0
    // glTF emissiveTexture (linear RGB after sRGB decoding): multiplies `emission` in the rasterizer and the
    // Whitted tracer (docs/gltf-import.md). Imported only.
    TextureBinding emissiveTexture;
};

inline constexpr float kMaxShininess = 10000.0f;

// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 33: a Blinn-Phong
// exponent s = 2/α² − 2 matches a microfacet lobe of width α; glTF's α = roughness². Clamped to [1, 10000].
inline float shininessFromRoughness(float roughness) {
    const float alpha = roughness * roughness;
    const float alpha2 = std::max(alpha * alpha, 1e-12f);
    return std::clamp(2.0f / alpha2 - 2.0f, 1.0f, kMaxShininess);
}

// The inverse of shininessFromRoughness: roughness = (2 / (s + 2))^(1/4), in [0, 1].
inline float roughnessFromShininess(float s) {
    return std::clamp(std::sqrt(std::sqrt(2.0f / (std::max(s, 0.0f) + 2.0f))), 0.0f, 1.0f);
}

// Each set field replaces the same field of the material it is applied to. A field of one model that is not
// set follows the other model's set fields: pbr without baseColor / roughness reads md and s; Phong without
// md / ma / ms / s reads baseColor, metallic and roughness (docs/scene-format.md).
struct MaterialOverride {
    std::optional<glm::vec3> ma, md, ms;
    std::optional<float> s;
    std::optional<glm::vec3> kr, kt;
    std::optional<float> ior;
    std::optional<glm::vec3> baseColor;
    std::optional<float> metallic, roughness;
    std::optional<glm::vec3> emission;

    bool empty() const {
        return !ma && !md && !ms && !s && !kr && !kt && !ior && !baseColor && !metallic && !roughness && !emission;
    }
    void applyTo(Material& m) const {
        if (ma) m.ma = *ma;
        if (md) m.md = *md;
        if (ms) m.ms = *ms;
        if (s) m.s = *s;
        if (kr) m.kr = *kr;
        if (kt) m.kt = *kt;
        if (ior) m.ior = *ior;
        if (baseColor) m.baseColor = *baseColor;
        if (metallic) m.metallic = *metallic;
        if (roughness) m.roughness = *roughness;
        if (emission) m.emission = *emission;
        const bool phong = ma || md || ms || s, pbr = baseColor || metallic || roughness;
        if (phong && !pbr) {
            if (md) m.baseColor = glm::clamp(*md, 0.0f, 1.0f);  // md may exceed 1; a base colour may not
            if (s) m.roughness = roughnessFromShininess(*s);
        }
        if (pbr && !phong) {
            // glTF 2.0 Appendix B, as gltf_materials.cpp maps glTF materials: diffuse colour, F0, exponent.
            m.md = m.baseColor * (1.0f - m.metallic);
            m.ma = m.md;
            m.ms = glm::mix(glm::vec3(0.04f), m.baseColor, m.metallic);
            m.s = shininessFromRoughness(m.roughness);
        }
    }
};

}  // namespace shadelab
