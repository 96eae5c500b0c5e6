// Objects by coverage id: the lookups both ways and the label.
#include "scene/object_ref.h"

#include "scene/coverage.h"

#include <exception>

namespace shadelab {

ObjectRef objectRef(const Scene& scene, uint32_t id) {
    if (id == kBackgroundId) return {};
    size_t i = id - 1;
    if (i < scene.spheres.size()) return {ObjectKind::Sphere, i};
    i -= scene.spheres.size();
    if (i < scene.planes.size()) return {ObjectKind::Plane, i};
    i -= scene.planes.size();
    if (i < scene.meshes.size()) return {ObjectKind::Mesh, i};
    return {};
}

uint32_t objectCount(const Scene& scene) {
    return uint32_t(scene.spheres.size() + scene.planes.size() + scene.meshes.size());
}

std::string objectLabel(const Scene& scene, uint32_t id) {
    const ObjectRef r = objectRef(scene, id);
    const char* kind = r.kind == ObjectKind::Sphere ? "sphere" : r.kind == ObjectKind::Plane ? "plane" : "mesh";
    if (r.kind == ObjectKind::None) return "background";
    const std::string& name = r.kind == ObjectKind::Sphere  ? scene.spheres[r.index].name
                              : r.kind == ObjectKind::Plane ? scene.planes[r.index].name
                                                            : scene.meshes[r.index].name;
    const std::string where = std::string(kind) + " " + std::to_string(r.index + 1);
    return name.empty() ? where : name + " (" + where + ")";
}

std::optional<uint32_t> findObject(const Scene& scene, const std::string& nameOrId) {
    if (nameOrId.size() > 1 && nameOrId[0] == '#') {
        try {
            size_t used = 0;
            const unsigned long id = std::stoul(nameOrId.substr(1), &used);
            if (used + 1 == nameOrId.size() && id >= 1 && id <= objectCount(scene)) return uint32_t(id);
        } catch (const std::exception&) {}
        return std::nullopt;
    }
    for (size_t i = 0; i < scene.spheres.size(); ++i)
        if (scene.spheres[i].name == nameOrId) return sphereCoverageId(scene, i);
    for (size_t i = 0; i < scene.planes.size(); ++i)
        if (scene.planes[i].name == nameOrId) return planeCoverageId(scene, i);
    for (size_t i = 0; i < scene.meshes.size(); ++i)
        if (scene.meshes[i].name == nameOrId) return meshCoverageId(scene, i);
    return std::nullopt;
}

}  // namespace shadelab
