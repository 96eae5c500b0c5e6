// Which shading models a scene's objects are shaded with: the scene's own model (Scene::model) and any a
// material names for itself (Material::model). Renderers ask before they prepare what only one model reads
// (pbr's and disney's DFG table, their environment prefilter, the sheen's albedo table).
#pragma once

#include "scene/scene.h"

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

// Whether any object of `scene` is shaded with a microfacet model (pbr or disney): those read the DFG table and
// take the environment's light.
inline bool usesPhysicallyBased(const Scene& scene) {
    return usesModel(scene, ShadingModel::Pbr) || usesModel(scene, ShadingModel::Disney);
}

}  // namespace shadelab
