// shareGeometry: the one place mesh geometry becomes immutable, with its bounds computed once.
#include "scene/mesh_geometry.h"

#include <utility>

namespace shadelab {

std::shared_ptr<const MeshGeometry> shareGeometry(MeshGeometry geometry) {
    geometry.bounds = Bounds{};
    for (const glm::vec3& p : geometry.positions) geometry.bounds.extend(p);
    return std::make_shared<const MeshGeometry>(std::move(geometry));
}

}  // namespace shadelab
