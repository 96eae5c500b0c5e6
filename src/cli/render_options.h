// RenderOptions: everything `shadelab render` was asked to do, parsed and validated before any work.
#pragma once

#include "gl/headless_context.h"
#include "render/render_request.h"
#include "scene/camera_choice.h"
#include "scene/raster_override.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace shadelab::cli {

struct RenderOptions {
    std::string input;   // scene.json, model.gltf or model.glb
    std::string output;  // PNG path
    // --renderer, --size, --spp, --depth, --threads, --encoding, the path tracer's --time-limit, --estimator
    // and --light-paths, and --max-memory: the render itself, checked as every front end checks it
    // (render/render_request.h).
    render::RenderRequest request;
    std::optional<ShadingModel> model;   // unset: the scene's
    std::optional<Terms> terms;          // unset: the scene's
    std::optional<CameraChoice> camera;  // --camera; unset: the scene's own (a bare model: fit)
    RasterOverride raster;               // --shadow-map-size, --pcf, ...: over the scene's "raster"
    gl::GlBackend backend = gl::GlBackend::Auto;
    bool allowExternalPaths = false;  // glTF buffers may live outside the model's folder
    bool verbose = false;
    bool timings = false;
    bool strict = false;  // a warning about the input is an error: exit 1, nothing written
    bool help = false;    // --help was given: print renderHelp() and do nothing else
};

// The command line's name for a render request's field: "spp" -> "--spp", "time_limit" -> "--time-limit".
std::string flagOf(const std::string& field);

// --camera's value (scene/camera_choice.h); throws UsageError naming --camera.
CameraChoice parseCameraFlag(const std::string& value);

// The --help text.
std::string renderHelp();

// Parses argv[2..]; throws UsageError on anything wrong.
RenderOptions parseRenderOptions(int argc, char** argv);

// "ambient,diffuse" → those terms on and the rest off; "none" or "" → all off. Throws UsageError naming
// --terms and listing the term names.
Terms parseTerms(const std::string& list);

}  // namespace shadelab::cli
