// loadScene: the one entry point that turns a path into a ready Scene. A .json file is parsed and its
// meshes imported; a .gltf/.glb file becomes a scene of its own with a camera framing its bounds
// (or its own glTF camera) and a default light rig (or its own KHR_lights_punctual lights).
#pragma once

#include "scene/bounds.h"
#include "scene/environment_load.h"
#include "scene/gltf/gltf_import.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>
#include <string>

namespace shadelab {

// Throws InputError naming the file and problem. `gltf` applies to every model the scene loads; `memory`, when
// set, to the environment map (loadEnvironment, scene/environment_load.h: refused from its header).
Scene loadScene(const std::string& path, void (*warn)(const std::string& line) = nullptr,
                const GltfImportOptions& gltf = {}, const MemoryLimit& memory = {});

// Imports every mesh's glTF source (relative to `baseDir`) into its parts, applying the override.
void importSceneMeshes(Scene& scene, const std::string& baseDir, const GltfImportOptions& gltf = {});

// Bounds of spheres and mesh triangles (planes are unbounded and ignored).
Bounds sceneBounds(const Scene& scene);

// A camera looking at `b` from the front and slightly above, with the whole box in view.
Camera frameBounds(const Bounds& b, float fovY = 45.0f);

// Two lights for a model with no lights of its own: a warm key and a cool fill, placed from `b`.
std::vector<Light> defaultLightRig(const Bounds& b);

}  // namespace shadelab
