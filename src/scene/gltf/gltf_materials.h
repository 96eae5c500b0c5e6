// One glTF material as a shadelab Material (gltf_materials.cpp; the mapping is in docs/gltf-import.md and
// phongFromMetallicRoughness in gltf_import.h). Used by the importer, gltf_import.cpp.
#pragma once

#include "scene/material.h"

#include <string>
#include <vector>

namespace tinygltf {
struct Material;
class Model;
}  // namespace tinygltf

namespace shadelab {

// `place` names the material in warnings ("materials[3]"); out-of-range values are clamped or, for an
// unusable KHR_materials_ior, ignored with a warning appended to `warnings`.
Material materialFrom(const tinygltf::Material& gm, const std::string& place, std::vector<std::string>& warnings);

// One warning line per KHR_materials_* extension the model's materials use that materialFrom does not shade
// (clearcoat, sheen, transmission, ...), naming how many materials lose it: they render without it.
std::vector<std::string> unshadedMaterialExtensions(const tinygltf::Model& model);

}  // namespace shadelab
