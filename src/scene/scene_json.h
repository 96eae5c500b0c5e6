// Scene files: JSON load and save (docs/scene-format.md). Loading parses the description only;
// meshes' glTF geometry is imported by loadScene() in scene_load.h.
#pragma once

#include "scene/scene.h"

#include <string>

namespace shadelab {

// Parses scene JSON text. `file` names the source in errors. Throws InputError whose message names the
// file, the JSON path and the problem, e.g. "a.json: lights[2].color: expected 3 numbers, got 2".
// Unknown fields are reported through `warn` (one line each), never as errors.
Scene parseSceneJson(const std::string& text, const std::string& file,
                     void (*warn)(const std::string& line) = nullptr);

// Serialises every described field (not imported geometry). parse(save(s)) == s, field by field.
std::string sceneToJson(const Scene& scene);

// Writes atomically (util/atomic_file.h).
void saveSceneJson(const Scene& scene, const std::string& path);

}  // namespace shadelab
