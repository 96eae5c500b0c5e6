#include "scene/camera_choice.h"

#include "scene/scene_load.h"
#include "util/input_error.h"

#include <charconv>

namespace shadelab {

std::optional<CameraChoice> parseCameraChoice(std::string_view word) {
    if (word == "fit") return CameraChoice{CameraChoice::Kind::Fit, 0};
    if (word == "file") return CameraChoice{CameraChoice::Kind::File, 0};
    int n = -1;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), n);
    if (ec != std::errc() || end != word.data() + word.size() || word.empty() || n < 0 || n > 999) return std::nullopt;
    return CameraChoice{CameraChoice::Kind::Index, n};
}

Camera chooseCamera(const Scene& scene, const CameraChoice& choice, const std::string& file) {
    switch (choice.kind) {
        case CameraChoice::Kind::Fit: {
            const Bounds b = sceneBounds(scene);
            return b.empty() ? scene.camera : frameBounds(b, scene.camera.fovY);
        }
        case CameraChoice::Kind::File: return scene.modelCameras.empty() ? scene.camera : scene.modelCameras.front();
        case CameraChoice::Kind::Index:
            if (size_t(choice.index) < scene.modelCameras.size()) return scene.modelCameras[size_t(choice.index)];
            break;
    }
    const size_t n = scene.modelCameras.size();
    throw InputError(file, "camera " + std::to_string(choice.index) + ": " +
                               (n == 0 ? std::string("the scene has no glTF camera")
                                       : "the model has " + std::to_string(n) + " camera" + (n == 1 ? "" : "s") +
                                             " (0" + (n > 1 ? " to " + std::to_string(n - 1) : std::string()) + ")"));
}

}  // namespace shadelab
