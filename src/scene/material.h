// Material: the lecture's Phong coefficients, the glTF metallic-roughness fields of the pbr model (design.md
// §7) and the tracer's kr/kt/ior (design.md §1). Plain data. MaterialOverride lets a scene file replace any
// subset of a material imported from glTF, and carries one model's fields over to the other's when only one
// model's are given (docs/scene-format.md, "Materials under each model").
#pragma once

#include "scene/anisotropy.h"
#include "scene/clearcoat.h"
#include "scene/disney_params.h"
#include "scene/shading_model.h"
#include "scene/sheen.h"
#include "scene/specular_layer.h"
#include "scene/texture.h"
#include "scene/transmission.h"
#include "scene/volume.h"
#include "util/name_table.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
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
    float ior = 1.5f;           // index of refraction, > 0; under pbr also the dielectric's F0 (KHR_materials_ior)
    glm::vec3 baseColor{0.7f};  // pbr: base colour, linear RGB in [0, 1] (= md by default)
    float metallic = 0.0f;      // pbr: [0, 1], 0 dielectric (F0 = 0.04), 1 metal (F0 = baseColor)
    float roughness = 0.4925f;  // pbr: perceptual roughness in [0, 1], α = roughness²; ≈ s = 32's equivalent
    DisneyParams disney;        // disney: the principled BRDF's other eight parameters (baseColor, metallic and
                                // roughness are pbr's)
    Clearcoat clearcoat;        // pbr: glTF's clear coat layer over the base (KHR_materials_clearcoat); none by default
    SpecularLayer specular;     // pbr: glTF's dielectric F0 tint and weight (KHR_materials_specular), with ior's F0
    Sheen sheen;                // pbr: glTF's sheen layer over the base (KHR_materials_sheen); none by default
    Anisotropy anisotropy;      // pbr: glTF's anisotropic GGX lobe (KHR_materials_anisotropy); isotropic by default
    Transmission transmission;  // pbr: glTF's light through the surface (KHR_materials_transmission); none by default
    Volume volume;              // pbr: glTF's medium inside a transmitting surface (KHR_materials_volume); thin
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
    // KHR_materials_clearcoat's maps, imported only: clearcoatTexture's red multiplies the factor,
    // clearcoatRoughnessTexture's green the roughness, and clearcoatNormalTexture bends the coat's normal alone
    // (tangent space, strength = its scale); without it the coat follows the geometry, not the base's normal map.
    TextureBinding clearcoatTexture;
    TextureBinding clearcoatRoughnessTexture;
    TextureBinding clearcoatNormalTexture;
    // The material's own shading model, which every renderer shades it with; none: the scene's (Scene::model).
    // So Phong, Blinn-Phong and pbr can sit side by side in one picture.
    std::optional<ShadingModel> model;
    // Which of the fields the models share a meaning through (MaterialField) were derived from the other model's
    // by deriveFields (docs/scene-format.md, "Materials under each model") rather than given: in the file, by
    // an edit, in the panel. An edit re-derives these from what it changed; saving writes only the given ones.
    uint8_t derived = 0;
};

// The fields two models share a meaning through: Phong's ma, md, ms, s and pbr's baseColor, metallic, roughness.
enum MaterialField : uint8_t {
    kFieldMa = 1,
    kFieldMd = 2,
    kFieldMs = 4,
    kFieldS = 8,
    kFieldBaseColor = 16,
    kFieldMetallic = 32,
    kFieldRoughness = 64,
};
inline constexpr uint8_t kPhongFields = kFieldMa | kFieldMd | kFieldMs | kFieldS;
inline constexpr uint8_t kPbrFields = kFieldBaseColor | kFieldMetallic | kFieldRoughness;
inline constexpr EnumName<MaterialField> kMaterialFieldNames[] = {
    {kFieldMa, "ma"},
    {kFieldMd, "md"},
    {kFieldMs, "ms"},
    {kFieldS, "s"},
    {kFieldBaseColor, "baseColor"},
    {kFieldMetallic, "metallic"},
    {kFieldRoughness, "roughness"},
};

// The model `m` is shaded with in a scene whose model is `sceneModel`.
inline ShadingModel modelOf(const Material& m, ShadingModel sceneModel) { return m.model.value_or(sceneModel); }

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

// An edit of the `edited` fields (MaterialField bits) of `m`, already written: they count as given from now on,
// and the fields derived from them follow, each unless it was given itself: baseColor follows md (clamped: md
// may exceed 1, a base colour may not) and roughness follows s (Walter et al. 2007's equivalence); md =
// baseColor·(1 − metallic), ma = md, ms = mix(0.04, baseColor, metallic) and s follow the pbr fields (glTF 2.0
// Appendix B). metallic follows nothing. When only pbr fields changed, every derived Phong field follows them.
inline void deriveFields(Material& m, uint8_t edited) {
    m.derived = uint8_t(m.derived & ~edited);
    const bool phong = (edited & kPhongFields) != 0, pbr = (edited & kPbrFields) != 0;
    const auto follows = [&](MaterialField field, uint8_t sources) {
        return (m.derived & field) && (pbr && !phong ? true : (edited & sources) != 0);
    };
    if (phong) {
        if (follows(kFieldBaseColor, kFieldMd)) m.baseColor = glm::clamp(m.md, 0.0f, 1.0f);
        if (follows(kFieldRoughness, kFieldS)) m.roughness = roughnessFromShininess(m.s);
    }
    if (pbr) {
        if (follows(kFieldMd, kFieldBaseColor | kFieldMetallic)) m.md = m.baseColor * (1.0f - m.metallic);
        if (follows(kFieldMa, kFieldBaseColor | kFieldMetallic)) m.ma = m.md;
        if (follows(kFieldMs, kFieldBaseColor | kFieldMetallic))
            m.ms = glm::mix(glm::vec3(0.04f), m.baseColor, m.metallic);
        if (follows(kFieldS, kFieldRoughness)) m.s = shininessFromRoughness(m.roughness);
    }
}

// The linked fields in which `after` differs from `before` (MaterialField bits).
inline uint8_t editedFields(const Material& before, const Material& after) {
    return uint8_t((after.ma != before.ma ? kFieldMa : 0) | (after.md != before.md ? kFieldMd : 0) |
                   (after.ms != before.ms ? kFieldMs : 0) | (after.s != before.s ? kFieldS : 0) |
                   (after.baseColor != before.baseColor ? kFieldBaseColor : 0) |
                   (after.metallic != before.metallic ? kFieldMetallic : 0) |
                   (after.roughness != before.roughness ? kFieldRoughness : 0));
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
    std::optional<ShadingModel> model;
    DisneyOverride disney;
    ClearcoatOverride clearcoat;
    SpecularLayerOverride specular;
    SheenOverride sheen;
    AnisotropyOverride anisotropy;
    TransmissionOverride transmission;
    VolumeOverride volume;
    // Linked fields whose values were derived when written (a Python document's "derived" list): read, but not
    // given, so that they follow the given fields again.
    uint8_t derived = 0;

    bool empty() const {
        return !ma && !md && !ms && !s && !kr && !kt && !ior && !baseColor && !metallic && !roughness && !emission &&
               !model && disney.empty() && clearcoat.empty() && specular.empty() && sheen.empty() &&
               anisotropy.empty() && transmission.empty() && volume.empty();
    }
    // Writes the fields, then derives from the given ones what follows from them (deriveFields). Fields of both
    // models given, with no "derived" list: each as given and nothing derived (docs/scene-format.md).
    void applyTo(Material& m) const {
        applyValues(m);
        m.derived = uint8_t(m.derived | derived);
        const uint8_t given = uint8_t(linkedFields() & ~derived);
        if ((given & kPhongFields) && (given & kPbrFields) && !derived) {
            m.derived = uint8_t(m.derived & ~given);
            return;
        }
        deriveFields(m, given);
    }
    // The linked fields given (MaterialField bits).
    uint8_t linkedFields() const {
        return uint8_t((ma ? kFieldMa : 0) | (md ? kFieldMd : 0) | (ms ? kFieldMs : 0) | (s ? kFieldS : 0) |
                       (baseColor ? kFieldBaseColor : 0) | (metallic ? kFieldMetallic : 0) |
                       (roughness ? kFieldRoughness : 0));
    }
    // Writes the given fields and nothing else (an edit whose derivation the caller makes).
    void applyValues(Material& m) const {
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
        if (model) m.model = *model;
        disney.applyTo(m.disney);
        clearcoat.applyTo(m.clearcoat);
        specular.applyTo(m.specular);
        sheen.applyTo(m.sheen);
        anisotropy.applyTo(m.anisotropy);
        transmission.applyTo(m.transmission);
        volume.applyTo(m.volume);
    }
};

// Whether a pbr material is shaded by glTF's layered function (shadeLightPbrSpecular: Appendix B's dielectric and
// metal mix) rather than pbr's own: its specular layer or index are off their defaults, it is anisotropic, or it
// transmits.
inline bool usesLayeredPbr(const Material& m) {
    return hasSpecularLayer(m.specular, m.ior) || m.anisotropy.on() || m.transmission.on();
}

// The renderers' packing of glTF's transmission and volume (shaders/gltf_layers.glsl, transmissionLight): (factor,
// the roughness scale clamp(2·ior − 2, 0, 1) of the transmitted lobe, η = 1/ior into a volume or 0 through a thin
// wall, 0). The scale narrows the lobe as the index nears 1, where a slab no longer bends light (the Khronos
// Sample Viewer's applyIorToRoughness).
inline glm::vec4 transmissionPacked(const Material& m) {
    return {m.transmission.factor, std::clamp(2.0f * m.ior - 2.0f, 0.0f, 1.0f), m.volume.on() ? 1.0f / m.ior : 0.0f,
            0.0f};
}

// What a transmitting volume leaves of each colour over its thickness (the rasterizer's and the local lights'
// path length through it; the tracers follow the real path inside); 1 for a thin wall.
inline glm::vec3 transmissionTint(const Material& m) { return m.volume.transmittance(m.volume.thickness); }

}  // namespace shadelab
