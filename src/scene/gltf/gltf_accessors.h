// Bounds-checked reading of glTF accessors (byteOffset, byteStride, sparse, quantized types) into
// plain arrays. Internal to gltf_import.cpp; every failure is an InputError naming "accessors[N]".
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace shadelab::gltf {

// Reads accessor `index` of `model` as VEC3 into `out` (resized to its count). FLOAT is read as is;
// BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT (KHR_mesh_quantization) are converted, honouring `normalized`.
// Values are not checked for finiteness; the caller decides what a non-finite value means.
// `file` names the glTF file in errors.
void readVec3(const tinygltf::Model& model, int index, const std::string& file, std::vector<glm::vec3>& out);

// Reads accessor `index` as VEC2 (TEXCOORD_n): FLOAT, or normalized UNSIGNED_BYTE / UNSIGNED_SHORT.
void readVec2(const tinygltf::Model& model, int index, const std::string& file, std::vector<glm::vec2>& out);

// Reads accessor `index` as VEC4 (TANGENT): FLOAT, or BYTE/SHORT as readVec3 reads them.
void readVec4(const tinygltf::Model& model, int index, const std::string& file, std::vector<glm::vec4>& out);

// The bytes of buffer view `view`, proven to lie inside its buffer (an image's encoded bytes). `where`
// names the referrer in errors, e.g. "images[0]".
std::string bufferViewBytes(const tinygltf::Model& model, int view, const std::string& file, const std::string& where);

// Reads index accessor `index` (SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT) into `out`.
void readIndices(const tinygltf::Model& model, int index, const std::string& file, std::vector<uint32_t>& out);

// Number of elements of accessor `index`; throws when the index is out of range. `what` names the
// referrer in the error, e.g. "meshes[2].primitives[0].attributes.POSITION".
size_t accessorCount(const tinygltf::Model& model, int index, const std::string& file, const std::string& what);

}  // namespace shadelab::gltf
