// Scene: everything both renderers need to draw one image, as plain data (design.md §1, §5).
// Loading and saving live in scene_json.h; glTF import in gltf_import.h.
#pragma once

#include "image/view_transform.h"
#include "scene/camera.h"
#include "scene/environment.h"
#include "scene/light.h"
#include "scene/objects.h"
#include "scene/raster_settings.h"
#include "scene/shading_model.h"
#include "scene/terms.h"
#include "util/input_files.h"

#include <optional>
#include <string>
#include <vector>

namespace shadelab {

struct Scene {
    std::string title;  // shown by the viewer
    std::string notes;  // free text for a lesson
    Camera camera;
    ShadingModel model = ShadingModel::Phong;
    bool normalized = false;  // Phong / Blinn-Phong lobes times (s+2)/2, (s+8)/8 (design.md §7); pbr: no effect
    Terms terms;
    glm::vec3 ambient{0.2f};     // Ia, linear RGB intensity
    glm::vec3 background{0.0f};  // colour of rays that leave the scene, linear RGB
    int maxDepth = 5;            // secondary-ray depth for the tracer, >= 0
    RasterSettings raster;       // the rasterizer's shadow-map and reflection settings
    // How the images of this scene are shown and encoded (exposure, view transform); never what is rendered.
    DisplaySettings display;

    // What escaping rays see and what lights pbr surfaces besides the lights (none: `background`),
    // and pbr's multiple-scattering compensation (Filament), for lights and the environment.
    std::optional<Environment> environment;
    bool energyCompensation = false;

    std::vector<Light> lights;
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Mesh> meshes;
    // A bare glTF model's own perspective cameras (node-walk order), for --camera file|N and the viewer's
    // camera menu. Never serialised: a saved scene keeps the camera in use.
    std::vector<Camera> modelCameras;
    // The files the scene was read from (its file, models, buffers, images, environment map): while any copy
    // of the scene lives, no output replaces them (util/input_files.h). Never serialised.
    InputFiles inputs;
};

// Largest number of lights either renderer accepts (the rasterizer's uniform block size).
inline constexpr int kMaxLights = 32;

}  // namespace shadelab
