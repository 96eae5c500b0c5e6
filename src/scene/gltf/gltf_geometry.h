// glTF geometry helpers for the importer (gltf_import.cpp): a node's local transform, the normal matrix of a
// world transform, triangle lists from any triangle topology, and area-weighted vertex normals.
#pragma once

#include "scene/mesh_geometry.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Node;
}

namespace shadelab {

// glTF 2.0 spec, "Transformations": the node's matrix, or T * R * S. Throws InputError (naming `file` and
// `place`) on a wrong number count or a non-finite value; a zero rotation quaternion is identity, with a warning.
glm::dmat4 localMatrix(const tinygltf::Node& node, const std::string& place, const std::string& file,
                       std::vector<std::string>& warnings);

// The inverse transpose of m, oriented as m and defined when m is singular (zero scales flatten normals).
glm::mat3 normalMatrix(const glm::dmat3& m);

// Triangle-list indices `out` from the vertices `v` of a TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN primitive;
// returns how many trailing indices of a TRIANGLES list formed no whole triangle.
size_t triangulate(int mode, const std::vector<uint32_t>& v, std::vector<uint32_t>& out);

// Area-weighted vertex normals of g; vertices whose faces have no area get +Y.
void generateNormals(const MeshGeometry& g, std::vector<glm::vec3>& out);

}  // namespace shadelab
