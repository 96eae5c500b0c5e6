// instancedTriangles: how many triangles a glTF node graph places once every shared node is expanded under
// each of its parents, counted from accessor counts alone, in O(nodes + primitives), before any vertex is
// read. A 3 KB file whose nodes form a DAG can place tens of millions of triangles; this is its price tag.
// Internal to the glTF importer.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab::gltf {

// Triangles placed by the nodes under `roots`, saturating at UINT64_MAX. A node on a cycle counts what it
// places before the cycle (the importer reports the cycle itself). Throws InputError for an accessor or
// mesh index out of range, naming `file`.
uint64_t instancedTriangles(const tinygltf::Model& model, const std::vector<int>& roots, const std::string& file);

}  // namespace shadelab::gltf
