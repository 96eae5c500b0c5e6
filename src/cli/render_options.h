// RenderOptions: everything `shadelab render` was asked to do, parsed and validated before any work.
#pragma once

#include "gl/headless_context.h"
#include "image/encode.h"
#include "scene/camera_choice.h"
#include "scene/raster_override.h"
#include "scene/scene.h"
#include "trace/path_settings.h"
#include "util/name_table.h"

#include <cstdint>
#include <optional>
#include <string>

namespace shadelab::cli {

enum class RendererChoice { Raster, Trace, Both, Path };

// The words of --renderer.
inline constexpr EnumName<RendererChoice> kRendererNames[] = {
    {RendererChoice::Raster, "raster"},
    {RendererChoice::Trace, "trace"},
    {RendererChoice::Both, "both"},
    {RendererChoice::Path, "path"},
};

inline const char* toString(RendererChoice r) { return nameOf(kRendererNames, r); }

struct RenderOptions {
    std::string input;                  // scene.json, model.gltf or model.glb
    std::string output;                 // PNG path
    int width = 1280, height = 720;     // pixels, 1..16384 each
    std::optional<ShadingModel> model;  // unset: the scene's
    std::optional<Terms> terms;         // unset: the scene's
    Encoding encoding = Encoding::Srgb;
    int spp = 1;                         // perfect square for raster, trace and both; any N >= 1 for path
    std::optional<CameraChoice> camera;  // --camera; unset: the scene's own (a bare model: fit)
    RendererChoice renderer = RendererChoice::Raster;
    int threads = 0;           // tracer worker threads; 0 = every core
    std::optional<int> depth;  // tracer secondary-ray depth; unset: the scene's maxDepth
    RasterOverride raster;     // --shadow-map-size, --pcf, ...: over the scene's "raster"
    // The path tracer (--renderer path): --time-limit seconds (0: none), --estimator, --light-paths.
    double timeLimit = 0.0;
    trace::PathEstimator estimator = trace::PathEstimator::Mis;
    trace::PathPart part = trace::PathPart::All;
    gl::GlBackend backend = gl::GlBackend::Auto;
    bool allowExternalPaths = false;  // glTF buffers may live outside the model's folder
    uint64_t maxMemory = 0;           // --max-memory, bytes; 0 = defaultMaxMemory() (memory_budget.h)
    bool verbose = false;
    bool timings = false;
    bool strict = false;  // a warning about the input is an error: exit 1, nothing written
    bool help = false;    // --help was given: print renderHelp() and do nothing else
};

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
