// A scene file's materials (docs/scene-format.md, "Materials"): reading an object's inline fields or the name of
// one of the file's "materials", the "derived" list, and the rule by which one model's fields derive the other's;
// writing a material or a mesh's override back.
// parseMaterialOverride (the fields alone, which scripts share) is declared in scene_json.h.
#pragma once

#include "scene/json_reader.h"
#include "scene/material.h"

#include <map>
#include <string>

namespace shadelab {

using NamedMaterials = std::map<std::string, MaterialOverride>;

// A material's "disney" object: some of the principled BRDF's parameters, each in [0, 1].
DisneyOverride parseDisneyOverride(const JsonNode& n);
// A material's "clearcoat" object: some of glTF's clear coat fields (factor, roughness), each in [0, 1].
ClearcoatOverride parseClearcoatOverride(const JsonNode& n);
// A material's "specular" object: glTF's specular layer, `factor` in [0, 1] and `color` (RGB, each in [0, 100]).
SpecularLayerOverride parseSpecularLayerOverride(const JsonNode& n);
// A material's "sheen" object: glTF's sheen layer, `color` (RGB, each in [0, 1]) and `roughness` in [0, 1].
SheenOverride parseSheenOverride(const JsonNode& n);
// A material's "anisotropy" object: glTF's anisotropy, `strength` in [0, 1] and `rotation` in radians.
AnisotropyOverride parseAnisotropyOverride(const JsonNode& n);
// A material's "transmission" object: glTF's transmission, `factor` in [0, 1].
TransmissionOverride parseTransmissionOverride(const JsonNode& n);
// A material's "volume" object: glTF's volume, `thickness` >= 0, `attenuationDistance` > 0 (absent or null: infinite)
// and `attenuationColor` (RGB, each in [0, 1]).
VolumeOverride parseVolumeOverride(const JsonNode& n);
// The largest specularColor a scene file takes (glTF allows more than 1; F0 is clamped to 1 after the tint).
inline constexpr float kMaxSpecularColor = 100.0f;
// A material object of the file: its fields (unknown keys warned about) and its "derived" list.
MaterialOverride parseMaterialFields(const JsonNode& n);
// An object's "material": inline fields, or a string naming an entry of the top-level "materials".
MaterialOverride parseMaterialRef(const JsonNode& n, const NamedMaterials& named);
// The material of `object` (its "material", when it has one), with what its given fields derive.
Material parseMaterial(const JsonNode& object, const NamedMaterials& named);

// A material as a scene file holds it: its given fields (a derived one is derived again on loading); `withDerived`
// writes the derived ones too, listed under "derived", as Python's documents hold them.
nlohmann::ordered_json materialJson(const Material& m, bool withDerived);
// A mesh's material override as a scene file holds it: the fields it sets.
nlohmann::ordered_json overrideJson(const MaterialOverride& m);

}  // namespace shadelab
