// A glTF node's perspective camera and its KHR_lights_punctual light, in world space (docs/gltf-import.md):
// cameras look down their node's −Z with +Y up, lights shine as the extension says, and values out of range
// are clamped with a warning or rejected with an InputError. Internal to the glTF importer.
#pragma once

#include "scene/camera.h"
#include "scene/light.h"

#include <tiny_gltf.h>

#include <functional>
#include <glm/mat4x4.hpp>
#include <optional>
#include <string>

namespace shadelab::gltf {

using Warn = std::function<void(const std::string&)>;

// The node's camera (`node.camera` >= 0), or none for a camera that is not perspective (warned). `place` names
// the node in errors; `file` the file.
std::optional<Camera> importCamera(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& file,
                                   const std::string& place, const glm::dmat4& world, const Warn& warn);

struct ImportedLight {
    Light light;
    float intensity = 1.0f;  // glTF's raw intensity: the importer scales the colours by it relative to the brightest
};

// The node's KHR_lights_punctual light, or none for an unknown type (warned).
std::optional<ImportedLight> importLight(const tinygltf::Model& model, const tinygltf::Node& node,
                                         const std::string& file, const std::string& place, const glm::dmat4& world,
                                         const Warn& warn);

}  // namespace shadelab::gltf
