// Which shading models a scene's objects are shaded with: the scene's own model (Scene::model) and any a
// material names for itself (Material::model). Renderers ask before they prepare what only one model reads
// (pbr's and disney's DFG table, their environment prefilter, the sheen's albedo table).
#pragma once

#include "scene/scene.h"

#include <string>

namespace shadelab {

// Whether any sphere, plane or mesh part of `scene` has a material for which `pred(material, model)` holds, the
// model being the one it is shaded with.
template <class Pred>
bool anyMaterial(const Scene& scene, Pred pred) {
    for (const Sphere& s : scene.spheres)
        if (pred(s.material, modelOf(s.material, scene.model))) return true;
    for (const Plane& p : scene.planes)
        if (pred(p.material, modelOf(p.material, scene.model))) return true;
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& part : m.parts)
            if (pred(part.material, modelOf(part.material, scene.model))) return true;
    return false;
}

// Whether any sphere, plane or mesh part of `scene` is shaded with `model`.
inline bool usesModel(const Scene& scene, ShadingModel model) {
    return anyMaterial(scene, [&](const Material&, ShadingModel own) { return own == model; });
}

// Whether any object of `scene` is shaded with pbr under glTF's sheen (those read the sheen's albedo table).
inline bool usesSheen(const Scene& scene) {
    return anyMaterial(scene,
                       [](const Material& m, ShadingModel own) { return own == ShadingModel::Pbr && m.sheen.on(); });
}

// Whether any object of `scene` is shaded with pbr under glTF's transmission (the tracers weigh the light through it
// by the DFG table, with or without an environment).
inline bool usesTransmission(const Scene& scene) {
    return anyMaterial(
        scene, [](const Material& m, ShadingModel own) { return own == ShadingModel::Pbr && m.transmission.on(); });
}

// Whether any object of `scene` is shaded with a microfacet model (pbr or disney): those read the DFG table and
// take the environment's light.
inline bool usesPhysicallyBased(const Scene& scene) {
    return usesModel(scene, ShadingModel::Pbr) || usesModel(scene, ShadingModel::Disney);
}

// The glTF layers that objects of `scene` carry but that their model does not shade (only pbr shades them): "clear
// coat", "specular layer", "sheen", "anisotropy", "transmission", those present, joined by ", "; empty when every layer
// shows. An index alone is not counted: it also sets the tracers' refraction under every model.
inline std::string layersNotShown(const Scene& scene) {
    bool coat = false, specular = false, sheen = false, anisotropy = false, transmission = false;
    anyMaterial(scene, [&](const Material& m, ShadingModel own) {
        if (own != ShadingModel::Pbr) {
            coat |= m.clearcoat.factor > 0.0f;
            specular |= m.specular != SpecularLayer{};
            sheen |= m.sheen.on();
            anisotropy |= m.anisotropy.on();
            transmission |= m.transmission.on();
        }
        return false;
    });
    std::string names;
    for (const auto& [on, name] : {std::pair{coat, "clear coat"},
                                   {specular, "specular layer"},
                                   {sheen, "sheen"},
                                   {anisotropy, "anisotropy"},
                                   {transmission, "transmission"}})
        if (on) names += std::string(names.empty() ? "" : ", ") + name;
    return names;
}

}  // namespace shadelab
