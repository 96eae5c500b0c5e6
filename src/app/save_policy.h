// Where the viewer may save the scene (a mis-aimed click once replaced a .gltf with scene JSON).
// Save writes scene JSON, so the name must end in ".json": a glTF model, an image or any other file is never
// replaced by it. An existing .json is replaced only after the user confirms (panels_scene.cpp), and never a
// file the open scene reads (its own .json included: util/input_files.h).
#pragma once

#include <string>

namespace shadelab::app {

// Why `path` must not receive the scene, as the end of a message ("... : <why>"), or empty when it may.
std::string saveRefusal(const std::string& path);

}  // namespace shadelab::app
