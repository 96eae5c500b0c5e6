// RenderOptions: everything `shadelab render` was asked to do, parsed and validated before any work.
#pragma once

#include "gl/headless_context.h"
#include "image/exr.h"
#include "render/render_request.h"
#include "scene/camera_choice.h"
#include "scene/raster_override.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace shadelab::cli {

struct RenderOptions {
    std::string input;     // scene.json, model.gltf or model.glb
    std::string output;    // the image to write: .png, .exr (outputFormat), or - for a PNG on stdout
    std::string coverage;  // --coverage: the coverage ids as a PNG (compare/coverage_image.h); "" for none
    // --renderer, --size, --spp, --depth, --threads, --encoding, the path tracer's --time-limit, --estimator
    // and --light-paths, and --max-memory: the render itself, checked as every front end checks it
    // (render/render_request.h).
    render::RenderRequest request;
    std::optional<ShadingModel> model;           // unset: the scene's
    std::optional<Terms> terms;                  // unset: the scene's
    std::optional<CameraChoice> camera;          // --camera; unset: the scene's own (a bare model: fit)
    RasterOverride raster;                       // --shadow-map-size, --pcf, ...: over the scene's "raster"
    std::optional<ExrPrecision> exrPrecision;    // --exr-precision; unset: float (only with an .exr output)
    bool passes = false;                         // --passes: surface passes as EXR layers (only with an .exr output)
    std::optional<std::pair<int, int>> rayTree;  // --ray-tree X,Y: the Whitted ray tree of that pixel drawn on
                                                 // the PNG (probe/ray_tree_picture.h), its rays on stderr
    gl::GlBackend backend = gl::GlBackend::Auto;
    bool allowExternalPaths = false;  // glTF buffers may live outside the model's folder
    bool verbose = false;
    bool timings = false;
    bool strict = false;  // a warning about the input is an error: exit 1, nothing written
    bool help = false;    // --help was given: print renderHelp() and do nothing else
};

// What `-o` writes: a PNG of the 8-bit pixels, or an OpenEXR file of the linear floats before conversion.
enum class OutputFormat { Png, Exr };

// The format `-o` names by its extension (".png" or ".exr", any case; stdout is PNG). Throws UsageError for any
// other name ("-o: ... expected a name ending in .png or .exr"), and for --exr-precision with a PNG output.
OutputFormat outputFormat(const RenderOptions& o);

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
