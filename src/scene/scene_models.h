// Which shading models a scene's objects are shaded with: the scene's own model (Scene::model) and any a
// material names for itself (Material::model). Renderers ask before they prepare what only one model reads
// (pbr's and disney's DFG table, their environment prefilter).
#pragma once

#include "scene/scene.h"

namespace shadelab {

// Whether any sphere, plane or mesh part of `scene` is shaded with `model`.
inline bool usesModel(const Scene& scene, ShadingModel model) {
    for (const Sphere& s : scene.spheres)
        if (modelOf(s.material, scene.model) == model) return true;
    for (const Plane& p : scene.planes)
        if (modelOf(p.material, scene.model) == model) return true;
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& part : m.parts)
            if (modelOf(part.material, scene.model) == model) return true;
    return false;
}

// Whether any object of `scene` is shaded with a microfacet model (pbr or disney): those read the DFG table and
// take the environment's light.
inline bool usesPhysicallyBased(const Scene& scene) {
    return usesModel(scene, ShadingModel::Pbr) || usesModel(scene, ShadingModel::Disney);
}

}  // namespace shadelab
