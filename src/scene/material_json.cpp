// Reading materials from a scene file (material_json.h).
#include "scene/material_json.h"

#include "scene/scene_json.h"
#include "scene/scene_limits.h"

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
    return m;
}

MaterialOverride parseMaterialFields(const JsonNode& n) {
    n.requireObject().warnUnknownKeys({"ma", "md", "ms", "s", "kr", "kt", "ior", "baseColor", "metallic", "roughness",
                                       "emission", "model", "disney", "clearcoat", "specular", "sheen", "anisotropy",
                                       "derived"});
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

}  // namespace shadelab
