// Objects by coverage id (scene/coverage.h): which sphere, plane or mesh an id names, its label for people,
// and the id of an object named in a script or a test. One numbering for both renderers, the probe and the
// viewer: 1-based, spheres, then planes, then meshes, in scene order; 0 is the background.
#pragma once

#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace shadelab {

enum class ObjectKind { None, Sphere, Plane, Mesh };

struct ObjectRef {
    ObjectKind kind = ObjectKind::None;
    size_t index = 0;  // in scene.spheres, scene.planes or scene.meshes
};
ObjectRef objectRef(const Scene& scene, uint32_t id);
uint32_t objectCount(const Scene& scene);
// "red plastic (sphere 1)"; unnamed objects read "sphere 1". Indices in labels count from 1.
std::string objectLabel(const Scene& scene, uint32_t id);
// An object by exact name (the first one), or by "#<id>". nullopt when nothing matches.
std::optional<uint32_t> findObject(const Scene& scene, const std::string& nameOrId);

}  // namespace shadelab
