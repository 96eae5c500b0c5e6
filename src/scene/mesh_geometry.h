// MeshGeometry: one mesh part's triangles in world space, immutable once shared. Scenes hold it through
// std::shared_ptr<const MeshGeometry>, so copying a scene costs O(objects), never O(triangles), and an
// accelerator built over it (the tracer's MeshBvh) is matched to its scene by identity.
#pragma once

#include "scene/bounds.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

namespace shadelab {

struct MeshGeometry {
    std::vector<glm::vec3> positions;   // world units
    std::vector<glm::vec3> normals;     // one per position, unit length; empty = flat shading
    std::vector<glm::vec2> texcoords0;  // TEXCOORD_0, one per position (glTF's u, v: v = 0 is the image's top
                                        // row); empty = the primitive has none
    std::vector<glm::vec2> texcoords1;  // TEXCOORD_1, as texcoords0; empty = none
    std::vector<glm::vec4> tangents;    // one per position: unit xyz in world space, w = ±1 the handedness
                                        // (bitangent = w·cross(N, T)); empty = none (scene/mesh_tangents.h)
    std::vector<uint32_t> indices;      // three per triangle, each < positions.size()
    Bounds bounds;                      // of every position; set by shareGeometry

    size_t triangleCount() const { return indices.size() / 3; }
};

// Computes the bounds and hands the geometry out as shared, immutable data.
std::shared_ptr<const MeshGeometry> shareGeometry(MeshGeometry geometry);

}  // namespace shadelab
