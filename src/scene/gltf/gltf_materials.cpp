// glTF materials → shadelab's Phong materials (docs/gltf-import.md): metallic-roughness by the documented
// mapping, KHR_materials_pbrSpecularGlossiness, KHR_materials_ior, KHR_materials_clearcoat,
// KHR_materials_specular, KHR_materials_sheen, KHR_materials_anisotropy, KHR_materials_transmission and
// KHR_materials_volume when present.
#include "scene/gltf/gltf_materials.h"

#include "scene/gltf/gltf_import.h"
#include "scene/gltf/gltf_values.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <map>
#include <optional>
#include <set>

namespace shadelab {
namespace {

glm::vec3 colorFrom(const std::vector<double>& v, glm::vec3 fallback) {
    if (v.size() < 3) return fallback;
    return {finiteClamp(v[0], 0.0f, 1.0f, fallback.r), finiteClamp(v[1], 0.0f, 1.0f, fallback.g),
            finiteClamp(v[2], 0.0f, 1.0f, fallback.b)};
}

}  // namespace

Material materialFrom(const tinygltf::Material& gm, const std::string& place, std::vector<std::string>& warnings) {
    const auto& pbr = gm.pbrMetallicRoughness;
    Material m = phongFromMetallicRoughness(colorFrom(pbr.baseColorFactor, glm::vec3(1.0f)),
                                            finiteClamp(pbr.metallicFactor, 0.0f, 1.0f, 1.0f),
                                            finiteClamp(pbr.roughnessFactor, 0.0f, 1.0f, 1.0f));
    // KHR_materials_pbrSpecularGlossiness is a Phong-like model already: diffuse → md, specular → ms.
    auto sg = gm.extensions.find("KHR_materials_pbrSpecularGlossiness");
    if (sg != gm.extensions.end()) {
        const float roughness = 1.0f - finiteClamp(numberOr(sg->second, "glossinessFactor", 1.0), 0.0f, 1.0f, 1.0f);
        const Material shape = phongFromMetallicRoughness(glm::vec3(1.0f), 0.0f, roughness);
        m.md = m.ma = colorFrom(numbersOf(sg->second, "diffuseFactor"), glm::vec3(1.0f));
        m.ms = colorFrom(numbersOf(sg->second, "specularFactor"), glm::vec3(1.0f));
        m.s = shape.s;
        // pbr reads the diffuse colour as a dielectric's base colour and 1 − glossiness as its roughness.
        m.baseColor = m.md;
        m.metallic = 0.0f;
        m.roughness = roughness;
    }
    // alphaMode: OPAQUE (the default) ignores alpha; MASK and BLEND read baseColorFactor[3] times the texture's.
    if (pbr.baseColorFactor.size() >= 4) m.alpha = finiteClamp(pbr.baseColorFactor[3], 0.0f, 1.0f, 1.0f);
    if (gm.alphaMode == "MASK") {
        m.alphaMode = AlphaMode::Mask;
        m.alphaCutoff = finiteClamp(gm.alphaCutoff, 0.0f, 1e6f, 0.5f);
    } else if (gm.alphaMode == "BLEND") {
        m.alphaMode = AlphaMode::Blend;
    } else if (!gm.alphaMode.empty() && gm.alphaMode != "OPAQUE") {
        warnings.push_back(place + ".alphaMode: unknown \"" + gm.alphaMode + "\"; treated as OPAQUE");
    }
    // emissiveFactor (linear RGB, >= 0) is the material's emitted radiance, times KHR_materials_emissive_strength.
    if (gm.emissiveFactor.size() >= 3) {
        auto channel = [&](size_t k) { return finiteClamp(gm.emissiveFactor[k], 0.0f, 1.0f, 0.0f); };
        m.emission = glm::vec3(channel(0), channel(1), channel(2));
        auto strength = gm.extensions.find("KHR_materials_emissive_strength");
        if (strength != gm.extensions.end())
            m.emission *= finiteClamp(numberOr(strength->second, "emissiveStrength", 1.0), 0.0f, 1e6f, 1.0f);
    }
    // KHR_materials_clearcoat: the coat's factor and roughness (its maps are bound with the other textures).
    auto coat = gm.extensions.find("KHR_materials_clearcoat");
    if (coat != gm.extensions.end()) {
        m.clearcoat.factor = finiteClamp(numberOr(coat->second, "clearcoatFactor", 0.0), 0.0f, 1.0f, 0.0f);
        m.clearcoat.roughness = finiteClamp(numberOr(coat->second, "clearcoatRoughnessFactor", 0.0), 0.0f, 1.0f, 0.0f);
    }
    // KHR_materials_specular: the dielectric's F0 tint and the weight of its specular lobe (pbr, with the ior's F0).
    // Its two textures are not read: the factors alone, said once per material.
    auto specular = gm.extensions.find("KHR_materials_specular");
    if (specular != gm.extensions.end()) {
        const tinygltf::Value& v = specular->second;
        m.specular.factor = finiteClamp(numberOr(v, "specularFactor", 1.0), 0.0f, 1.0f, 1.0f);
        const std::vector<double> color = numbersOf(v, "specularColorFactor");
        if (color.size() >= 3)
            m.specular.color = {finiteClamp(color[0], 0.0f, 100.0f, 1.0f), finiteClamp(color[1], 0.0f, 100.0f, 1.0f),
                                finiteClamp(color[2], 0.0f, 100.0f, 1.0f)};
        for (const char* key : {"specularTexture", "specularColorTexture"})
            if (v.IsObject() && v.Has(key))
                warnings.push_back(place + ".extensions.KHR_materials_specular." + key +
                                   ": not shaded yet; the factors alone are");
    }
    // KHR_materials_sheen: the fibres' colour and roughness (pbr). Its two textures are not read yet.
    auto sheen = gm.extensions.find("KHR_materials_sheen");
    if (sheen != gm.extensions.end()) {
        const tinygltf::Value& v = sheen->second;
        m.sheen.color = colorFrom(numbersOf(v, "sheenColorFactor"), glm::vec3(0.0f));
        m.sheen.roughness = finiteClamp(numberOr(v, "sheenRoughnessFactor", 0.0), 0.0f, 1.0f, 0.0f);
        for (const char* key : {"sheenColorTexture", "sheenRoughnessTexture"})
            if (v.IsObject() && v.Has(key))
                warnings.push_back(place + ".extensions.KHR_materials_sheen." + key +
                                   ": not shaded yet; the factors alone are");
    }
    // KHR_materials_anisotropy: the lobe's stretch and its direction's turn from the tangent (pbr). Its texture is
    // not read yet.
    auto aniso = gm.extensions.find("KHR_materials_anisotropy");
    if (aniso != gm.extensions.end()) {
        const tinygltf::Value& v = aniso->second;
        m.anisotropy.strength = finiteClamp(numberOr(v, "anisotropyStrength", 0.0), 0.0f, 1.0f, 0.0f);
        m.anisotropy.rotation =
            finiteClamp(numberOr(v, "anisotropyRotation", 0.0), -kMaxAnisotropyRotation, kMaxAnisotropyRotation, 0.0f);
        if (v.IsObject() && v.Has("anisotropyTexture"))
            warnings.push_back(place +
                               ".extensions.KHR_materials_anisotropy.anisotropyTexture: not shaded yet; the "
                               "factors alone are");
    }
    // KHR_materials_transmission: the share of the diffuse light that passes through (pbr). Its texture is not read
    // yet.
    auto transmission = gm.extensions.find("KHR_materials_transmission");
    if (transmission != gm.extensions.end()) {
        const tinygltf::Value& v = transmission->second;
        m.transmission.factor = finiteClamp(numberOr(v, "transmissionFactor", 0.0), 0.0f, 1.0f, 0.0f);
        if (v.IsObject() && v.Has("transmissionTexture"))
            warnings.push_back(place +
                               ".extensions.KHR_materials_transmission.transmissionTexture: not shaded yet; the "
                               "factor alone is");
    }
    // KHR_materials_volume: the medium's thickness for the rasterizer and its absorption (pbr, with transmission).
    // Its thickness texture is not read yet.
    auto volume = gm.extensions.find("KHR_materials_volume");
    if (volume != gm.extensions.end()) {
        const tinygltf::Value& v = volume->second;
        m.volume.thickness = finiteClamp(numberOr(v, "thicknessFactor", 0.0), 0.0f, kMaxVolumeLength, 0.0f);
        const double distance = numberOr(v, "attenuationDistance", -1.0);
        if (distance > 0.0 && distance <= double(kMaxVolumeLength)) m.volume.attenuationDistance = float(distance);
        m.volume.attenuationColor = colorFrom(numbersOf(v, "attenuationColor"), glm::vec3(1.0f));
        if (v.IsObject() && v.Has("thicknessTexture"))
            warnings.push_back(place +
                               ".extensions.KHR_materials_volume.thicknessTexture: not shaded yet; the factor alone "
                               "is");
    }
    auto ior = gm.extensions.find("KHR_materials_ior");
    if (ior != gm.extensions.end()) {
        const double value = numberOr(ior->second, "ior", 1.5);
        const std::optional<float> f = finiteFloat(value);
        if (f && *f > 0.0f)
            m.ior = *f;
        else
            warnings.push_back(place + ".extensions.KHR_materials_ior: ior " + std::to_string(value) +
                               " ignored (kept 1.5)");
    }
    return m;
}

Material phongFromMetallicRoughness(const glm::vec3& baseColor, float metallic, float roughness) {
    metallic = std::clamp(metallic, 0.0f, 1.0f);
    roughness = std::clamp(roughness, 0.0f, 1.0f);
    Material m;
    // glTF 2.0 Appendix B: dielectrics have F0 = 0.04 and a diffuse lobe; metals tint F0 and have none.
    m.md = baseColor * (1.0f - metallic);
    m.ms = glm::mix(glm::vec3(0.04f), baseColor, metallic);
    m.s = shininessFromRoughness(roughness);  // Walter et al. 2007, eq. 33
    m.ma = m.md;                              // ambient light shows the surface's own colour
    m.kr = glm::vec3(0.0f);
    m.kt = glm::vec3(0.0f);
    m.ior = 1.5f;
    // The pbr model reads the metallic-roughness values themselves, not the Phong conversion above.
    m.baseColor = baseColor;
    m.metallic = metallic;
    m.roughness = roughness;
    // The asset's fields, none given by the scene: a mesh's material override re-derives from what it gives.
    m.derived = kPhongFields | kPbrFields;
    return m;
}

std::vector<std::string> unshadedMaterialExtensions(const tinygltf::Model& model) {
    // The material extensions materialFrom reads; every other KHR_materials_* changes how a surface looks.
    static const std::set<std::string> kShaded = {"KHR_materials_pbrSpecularGlossiness",
                                                  "KHR_materials_emissive_strength",
                                                  "KHR_materials_ior",
                                                  "KHR_materials_clearcoat",
                                                  "KHR_materials_specular",
                                                  "KHR_materials_sheen",
                                                  "KHR_materials_anisotropy",
                                                  "KHR_materials_transmission",
                                                  "KHR_materials_volume"};
    std::map<std::string, size_t> users;  // extension → materials that use it, in name order
    for (const tinygltf::Material& gm : model.materials)
        for (const auto& [name, value] : gm.extensions)
            if (name.rfind("KHR_materials_", 0) == 0 && !kShaded.count(name)) ++users[name];
    std::vector<std::string> lines;
    for (const auto& [name, count] : users)
        lines.push_back(name + " is not shaded (" + std::to_string(count) +
                        (count == 1 ? " material uses it" : " materials use it") + "): rendered without it");
    return lines;
}

}  // namespace shadelab
