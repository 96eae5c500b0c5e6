// --camera fit|file|N (render and view) and the viewer's camera menu: which camera a scene is shown through.
//   fit   frames the scene's bounds (scene_load.h frameBounds), the default for a bare glTF model;
//   file  the scene file's own camera, or a bare model's first glTF camera; the default for a scene file;
//   N     a bare model's glTF camera N, counting from 0 in node-walk order.
#pragma once

#include "scene/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace shadelab {

struct CameraChoice {
    enum class Kind { Fit, File, Index };
    Kind kind = Kind::File;
    int index = 0;  // Kind::Index
};

// "fit", "file" or a whole number 0..999; nullopt otherwise.
std::optional<CameraChoice> parseCameraChoice(std::string_view word);

// The camera `choice` picks in `scene`, whose own camera is the scene file's (or a bare model's framing).
// Throws InputError naming `file` when the scene has no such glTF camera, e.g.
// "engine.glb: --camera 3: the model has 1 camera (0)".
Camera chooseCamera(const Scene& scene, const CameraChoice& choice, const std::string& file);

}  // namespace shadelab
