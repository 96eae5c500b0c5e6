// Tangents for normal maps when a glTF primitive has none (design.md §9): generated in the MikkTSpace
// convention from one texture-coordinate set. Not the import of the file's TANGENT (gltf_import.cpp).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace shadelab {

// One tangent per position: each triangle's tangent T = ∂P/∂u and bitangent B = −∂P/∂v from its edges and
// (u, v) differences (Lengyel 2001; glTF's v grows downwards, so the image's up is −v), summed per vertex,
// then T Gram-Schmidt orthogonalised against the vertex normal and normalised, w = the handedness sign of
// (N × T)·B (±1), as MikkTSpace and glTF's TANGENT store it. A vertex whose triangles have no usable (u, v)
// area gets a unit vector perpendicular to its normal and w = 1. `uvs` and `normals` have one entry per
// position; normals are unit.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& indices);

}  // namespace shadelab
