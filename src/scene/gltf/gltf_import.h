// glTF 2.0 import (.gltf, .glb, embedded buffers) through tinygltf: triangles in world space, lights
// from KHR_lights_punctual, cameras, and the documented metallic-roughness → Phong mapping
// (docs/gltf-import.md). Not a general glTF viewer: skins, morphs and animation are ignored.
#pragma once

#include "scene/camera.h"
#include "scene/gltf/gltf_limits.h"
#include "scene/light.h"
#include "scene/objects.h"

#include <glm/mat4x4.hpp>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

struct GltfImport {
    std::vector<MeshPart> parts;        // one per triangle primitive, world space
    std::vector<Light> lights;          // KHR_lights_punctual, world space
    std::vector<Camera> cameras;        // every perspective camera, in node-walk order
    std::vector<std::string> warnings;  // things skipped (points, lines, unsupported extensions)
};

struct GltfImportOptions {
    bool allowExternalPaths = false;  // let buffer URIs point outside the model's folder (../, absolute)
    GltfLimits limits;                // sizes past which a model is refused (gltf_limits.h)
    uint64_t trianglesBefore = 0;     // triangles the scene's earlier models placed: limits.maxTriangles
                                      // bounds the whole scene, not each model
};

// Imports `path`, placing everything under `transform`. Throws InputError naming the file, the place
// (e.g. "accessors[3]") and the reason. Buffer files outside the model's folder are refused unless
// options.allowExternalPaths: a model from elsewhere must not read arbitrary files.
GltfImport importGltf(const std::string& path, const glm::mat4& transform = glm::mat4(1.0f),
                      const GltfImportOptions& options = {});

// Imports glTF text (binary = false) or GLB bytes held in memory, with every external file refused. For the
// fuzzer and tests; `name` stands for the file in errors.
GltfImport importGltfBytes(const std::string& bytes, bool binary, const std::string& name,
                           const GltfLimits& limits = {});

// Metallic-roughness → Phong (docs/gltf-import.md).
Material phongFromMetallicRoughness(const glm::vec3& baseColor, float metallic, float roughness);

}  // namespace shadelab
