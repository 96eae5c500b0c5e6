// Materials in scene files (material_json.h): reading them, and writing a material or an override back.
#include "scene/material_json.h"

#include "scene/json_write.h"
#include "scene/scene_json.h"
#include "scene/scene_limits.h"

#include <cmath>
#include <limits>

namespace shadelab {

namespace {

// A nested object of parameters named by O's table, each in [0, 1] ("disney", "clearcoat").
template <class O>
O parseParamOverride(const JsonNode& n) {
    std::vector<const char*> names;
    for (const auto& field : O::fields()) names.push_back(field.name);
    n.requireObject().warnUnknownKeys(names);
    O o;
    for (int i = 0; i < O::kCount; ++i)
        if (auto f = n.find(O::fields()[i].name)) o.value[i] = f->inRange(0.0f, 1.0f, false, false);
    return o;
}

}  // namespace

DisneyOverride parseDisneyOverride(const JsonNode& n) { return parseParamOverride<DisneyOverride>(n); }

ClearcoatOverride parseClearcoatOverride(const JsonNode& n) { return parseParamOverride<ClearcoatOverride>(n); }

SpecularLayerOverride parseSpecularLayerOverride(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"factor", "color"});
    SpecularLayerOverride o;
    if (auto f = n.find("factor")) o.factor = f->inRange(0.0f, 1.0f, false, false);
    if (auto f = n.find("color")) o.color = f->rgbUpTo(kMaxSpecularColor);
    return o;
}

SheenOverride parseSheenOverride(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"color", "roughness"});
    SheenOverride o;
    if (auto f = n.find("color")) o.color = f->unitRgb();
    if (auto f = n.find("roughness")) o.roughness = f->inRange(0.0f, 1.0f, false, false);
    return o;
}

AnisotropyOverride parseAnisotropyOverride(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"strength", "rotation"});
    AnisotropyOverride o;
    if (auto f = n.find("strength")) o.strength = f->inRange(0.0f, 1.0f, false, false);
    if (auto f = n.find("rotation"))
        o.rotation = f->inRange(-kMaxAnisotropyRotation, kMaxAnisotropyRotation, false, false);
    return o;
}

TransmissionOverride parseTransmissionOverride(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"factor"});
    TransmissionOverride o;
    if (auto f = n.find("factor")) o.factor = f->inRange(0.0f, 1.0f, false, false);
    return o;
}

VolumeOverride parseVolumeOverride(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"thickness", "attenuationDistance", "attenuationColor"});
    VolumeOverride o;
    if (auto f = n.find("thickness")) o.thickness = f->inRange(0.0f, kMaxVolumeLength, false, false);
    // null: infinite, absorbing nothing (what an absent distance means in a material, said where it must replace
    // a finite one: a mesh's override of its glTF material).
    if (auto f = n.find("attenuationDistance"))
        o.attenuationDistance = f->json().is_null() ? std::numeric_limits<float>::infinity()
                                                    : f->inRange(0.0f, kMaxVolumeLength, true, false);
    if (auto f = n.find("attenuationColor")) o.attenuationColor = f->unitRgb();
    return o;
}

MaterialOverride parseMaterialOverride(const JsonNode& n) {
    n.requireObject();
    MaterialOverride m;
    if (auto f = n.find("ma")) m.ma = f->rgb();
    if (auto f = n.find("md")) m.md = f->rgb();
    if (auto f = n.find("ms")) m.ms = f->rgb();
    if (auto f = n.find("s")) m.s = f->inRange(0.0f, kMaxShininess, false, false);
    if (auto f = n.find("kr")) m.kr = f->rgb();
    if (auto f = n.find("kt")) m.kt = f->rgb();
    if (auto f = n.find("ior")) m.ior = f->positive();
    if (auto f = n.find("baseColor")) m.baseColor = f->unitRgb();
    if (auto f = n.find("metallic")) m.metallic = f->inRange(0.0f, 1.0f, false, false);
    if (auto f = n.find("roughness")) m.roughness = f->inRange(0.0f, 1.0f, false, false);
    if (auto f = n.find("emission")) m.emission = f->rgbUpTo(kMaxRadiance);
    if (auto f = n.find("model")) m.model = f->oneOf(kShadingModelNames, "shading model");
    if (auto f = n.find("disney")) m.disney = parseDisneyOverride(*f);
    if (auto f = n.find("clearcoat")) m.clearcoat = parseClearcoatOverride(*f);
    if (auto f = n.find("specular")) m.specular = parseSpecularLayerOverride(*f);
    if (auto f = n.find("sheen")) m.sheen = parseSheenOverride(*f);
    if (auto f = n.find("anisotropy")) m.anisotropy = parseAnisotropyOverride(*f);
    if (auto f = n.find("transmission")) m.transmission = parseTransmissionOverride(*f);
    if (auto f = n.find("volume")) m.volume = parseVolumeOverride(*f);
    return m;
}

MaterialOverride parseMaterialFields(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"ma",       "md",         "ms",           "s",         "kr",
                                       "kt",       "ior",        "baseColor",    "metallic",  "roughness",
                                       "emission", "model",      "disney",       "clearcoat", "specular",
                                       "sheen",    "anisotropy", "transmission", "volume",    "derived"});
    MaterialOverride o = parseMaterialOverride(n);
    // "derived": the fields listed were derived from the other model's when the document was written (Python's
    // documents list them): read, but not given, so that they follow the given fields again.
    if (auto f = n.find("derived"))
        for (size_t i = 0; i < f->arraySize(); ++i)
            o.derived = uint8_t(o.derived | (*f)[i].oneOf(kMaterialFieldNames, "material field"));
    return o;
}

MaterialOverride parseMaterialRef(const JsonNode& n, const NamedMaterials& named) {
    if (!n.json().is_string()) return parseMaterialFields(n);
    std::string name = n.string();
    auto it = named.find(name);
    if (it != named.end()) return it->second;
    // The first few names only: a file may define thousands (the message stays one short line).
    constexpr size_t kListed = 8;
    std::string known;
    size_t listed = 0;
    for (const auto& entry : named)
        if (listed++ < kListed) known += (known.empty() ? "" : ", ") + entry.first;
    if (named.size() > kListed) known += " and " + std::to_string(named.size() - kListed) + " more";
    n.fail("unknown material '" + name + "'; " +
           (known.empty() ? std::string("the file has no \"materials\"") : "named materials are: " + known));
}

Material parseMaterial(const JsonNode& object, const NamedMaterials& named) {
    Material m;
    if (auto f = object.find("material")) {
        const MaterialOverride o = parseMaterialRef(*f, named);
        // A material that gives one model's fields only has the other's derived from them (docs/scene-format.md,
        // "Materials under each model"); one that gives some of both has each as given.
        const uint8_t given = uint8_t(o.linkedFields() & ~o.derived);
        if ((given & kPhongFields) && !(given & kPbrFields)) m.derived = kPbrFields;
        if ((given & kPbrFields) && !(given & kPhongFields)) m.derived = kPhongFields;
        o.applyTo(m);
    }
    return m;
}

// ---- Writing -----------------------------------------------------------------------------------------------

namespace {

using OJson = nlohmann::ordered_json;
using json_write::exact;
using json_write::vec;

// A group of parameters (the principled BRDF's, the clear coat's): those that are set (an override).
template <class O>
OJson paramsJson(const O& o) {
    OJson j = OJson::object();
    for (int i = 0; i < O::kCount; ++i)
        if (o.value[i]) j[O::fields()[i].name] = exact(*o.value[i]);
    return j;
}

// glTF's specular layer: the fields that are set.
OJson specularJson(const SpecularLayerOverride& o) {
    OJson j = OJson::object();
    if (o.factor) j["factor"] = exact(*o.factor);
    if (o.color) j["color"] = vec(*o.color);
    return j;
}

// glTF's sheen layer: the fields that are set.
OJson sheenJson(const SheenOverride& o) {
    OJson j = OJson::object();
    if (o.color) j["color"] = vec(*o.color);
    if (o.roughness) j["roughness"] = exact(*o.roughness);
    return j;
}

// glTF's anisotropy: the fields that are set.
OJson anisotropyJson(const AnisotropyOverride& o) {
    OJson j = OJson::object();
    if (o.strength) j["strength"] = exact(*o.strength);
    if (o.rotation) j["rotation"] = exact(*o.rotation);
    return j;
}

// glTF's transmission: its factor when set.
OJson transmissionJson(const TransmissionOverride& o) {
    OJson j = OJson::object();
    if (o.factor) j["factor"] = exact(*o.factor);
    return j;
}

// glTF's volume: the fields that are set. An infinite attenuation distance (absorbing nothing) is left out of a
// material, where that is its default, and written as null in an override, where it replaces a finite one.
OJson volumeJson(const VolumeOverride& o, bool override) {
    OJson j = OJson::object();
    if (o.thickness) j["thickness"] = exact(*o.thickness);
    if (o.attenuationDistance && std::isfinite(*o.attenuationDistance))
        j["attenuationDistance"] = exact(*o.attenuationDistance);
    else if (o.attenuationDistance && override)
        j["attenuationDistance"] = nullptr;
    if (o.attenuationColor) j["attenuationColor"] = vec(*o.attenuationColor);
    return j;
}

}  // namespace

OJson materialJson(const Material& m, bool withDerived) {
    OJson j = OJson::object();
    // A material that gives fields of both models reads back with nothing derived: then every value is written,
    // so that it reads back exactly.
    const bool both = (~m.derived & kPhongFields) && (~m.derived & kPbrFields);
    const auto put = [&](MaterialField field, OJson value) {
        if (withDerived || both || !(m.derived & field)) j[nameOf(kMaterialFieldNames, field)] = std::move(value);
    };
    put(kFieldMa, vec(m.ma));
    put(kFieldMd, vec(m.md));
    put(kFieldMs, vec(m.ms));
    put(kFieldS, exact(m.s));
    j["kr"] = vec(m.kr);
    j["kt"] = vec(m.kt);
    j["ior"] = exact(m.ior);
    put(kFieldBaseColor, vec(m.baseColor));
    put(kFieldMetallic, exact(m.metallic));
    put(kFieldRoughness, exact(m.roughness));
    if (m.emission != glm::vec3(0.0f)) j["emission"] = vec(m.emission);  // written only for emitters
    if (m.model) j["model"] = toString(*m.model);                        // only a material's own
    // The principled BRDF's parameters where they matter: a disney material, or any left off their defaults; in
    // Python's documents always, so that they can be edited in place.
    if (withDerived || m.model == ShadingModel::Disney || m.disney != DisneyParams{})
        j["disney"] = paramsJson(DisneyOverride::all(m.disney));
    // The clear coat where there is one (Python's documents always, to be edited in place).
    if (withDerived || m.clearcoat != Clearcoat{}) j["clearcoat"] = paramsJson(ClearcoatOverride::all(m.clearcoat));
    // glTF's specular layer where it is off its defaults (Python's documents always).
    if (withDerived || m.specular != SpecularLayer{})
        j["specular"] = specularJson(SpecularLayerOverride{m.specular.factor, m.specular.color});
    // glTF's sheen where there is one (Python's documents always).
    if (withDerived || m.sheen != Sheen{}) j["sheen"] = sheenJson(SheenOverride{m.sheen.color, m.sheen.roughness});
    // glTF's anisotropy where there is any (Python's documents always).
    if (withDerived || m.anisotropy != Anisotropy{})
        j["anisotropy"] = anisotropyJson(AnisotropyOverride{m.anisotropy.strength, m.anisotropy.rotation});
    // glTF's transmission and volume where there are any (Python's documents always).
    if (withDerived || m.transmission != Transmission{})
        j["transmission"] = transmissionJson(TransmissionOverride{m.transmission.factor});
    if (withDerived || m.volume != Volume{})
        j["volume"] = volumeJson(
            VolumeOverride{m.volume.thickness, m.volume.attenuationDistance, m.volume.attenuationColor}, false);
    if (withDerived && m.derived) {
        OJson names = OJson::array();
        for (const auto& entry : kMaterialFieldNames)
            if (m.derived & entry.value) names.push_back(entry.name);
        j["derived"] = std::move(names);
    }
    return j;
}

OJson overrideJson(const MaterialOverride& m) {
    OJson j = OJson::object();
    if (m.ma) j["ma"] = vec(*m.ma);
    if (m.md) j["md"] = vec(*m.md);
    if (m.ms) j["ms"] = vec(*m.ms);
    if (m.s) j["s"] = exact(*m.s);
    if (m.kr) j["kr"] = vec(*m.kr);
    if (m.kt) j["kt"] = vec(*m.kt);
    if (m.ior) j["ior"] = exact(*m.ior);
    if (m.baseColor) j["baseColor"] = vec(*m.baseColor);
    if (m.metallic) j["metallic"] = exact(*m.metallic);
    if (m.roughness) j["roughness"] = exact(*m.roughness);
    if (m.emission) j["emission"] = vec(*m.emission);
    if (m.model) j["model"] = toString(*m.model);
    if (!m.disney.empty()) j["disney"] = paramsJson(m.disney);
    if (!m.clearcoat.empty()) j["clearcoat"] = paramsJson(m.clearcoat);
    if (!m.specular.empty()) j["specular"] = specularJson(m.specular);
    if (!m.sheen.empty()) j["sheen"] = sheenJson(m.sheen);
    if (!m.anisotropy.empty()) j["anisotropy"] = anisotropyJson(m.anisotropy);
    if (!m.transmission.empty()) j["transmission"] = transmissionJson(m.transmission);
    if (!m.volume.empty()) j["volume"] = volumeJson(m.volume, true);
    return j;
}

}  // namespace shadelab
