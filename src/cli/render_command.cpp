// `shadelab render`: load the scene (on a worker thread, while the GL context starts), draw it with the
// rasterizer, convert once to 8-bit, write the PNG atomically. --timings prints the per-stage breakdown.
#include "cli/render_command.h"

#include "cli/args.h"
#include "cli/stage_timer.h"
#include "gl/headless_context.h"
#include "image/encode.h"
#include "image/png.h"
#include "raster/offscreen.h"
#include "raster/raster_renderer.h"
#include "scene/scene_load.h"
#include "util/atomic_file.h"
#include "util/input_error.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <sstream>
#include <string>

namespace shadelab::cli {

const char* const kRenderHelp =
    "usage: shadelab render <scene.json | model.gltf | model.glb> -o out.png [options]\n"
    "\n"
    "Renders a scene headlessly (EGL, or OSMesa) with the OpenGL rasterizer and writes a PNG.\n"
    "\n"
    "options:\n"
    "  -o, --output PATH        PNG to write (required); written atomically\n"
    "  --size WxH               image size in pixels, each side 1..16384 (default 1280x720)\n"
    "  --model NAME             phong | blinn-phong (default: the scene's)\n"
    "  --terms LIST             comma-separated terms to switch on, the rest off:\n"
    "                           ambient,diffuse,specular,shadows,reflections (default: the scene's)\n"
    "  --encoding NAME          srgb (default) | linear: how linear colour becomes 8-bit\n"
    "  --spp N                  samples per pixel on a fixed k x k grid; N = 1, 4, 9, 16, ... (default 1)\n"
    "  --gl-backend NAME        auto | egl-device | egl-surfaceless | osmesa\n"
    "                           (default auto; also the SHADELAB_GL_BACKEND environment variable)\n"
    "  --timings                print a per-stage timing breakdown to stderr\n"
    "  --verbose                log the GL backend, GL_RENDERER and GL_VERSION to stderr\n"
    "  -h, --help               show this help\n"
    "\n"
    "exit codes: 0 written, 1 bad input or rendering failure (one line on stderr), 2 usage error\n";

namespace {

Terms parseTerms(const std::string& list) {
    Terms t{false, false, false, false, false};
    std::stringstream in(list);
    std::string name;
    bool any = false;
    while (std::getline(in, name, ',')) {
        if (name == "ambient") t.ambient = true;
        else if (name == "diffuse") t.diffuse = true;
        else if (name == "specular") t.specular = true;
        else if (name == "shadows") t.shadows = true;
        else if (name == "reflections") t.reflections = true;
        else if (name == "none" || name.empty()) continue;
        else
            throw UsageError("--terms: unknown term '" + name +
                             "'; expected ambient, diffuse, specular, shadows, reflections or none");
        any = true;
    }
    (void)any;
    return t;
}

ShadingModel parseModel(const std::string& s) {
    if (s == "phong") return ShadingModel::Phong;
    if (s == "blinn-phong" || s == "blinn") return ShadingModel::BlinnPhong;
    throw UsageError("--model: expected phong or blinn-phong, got '" + s + "'");
}

void printWarning(const std::string& line) { std::fprintf(stderr, "shadelab: warning: %s\n", line.c_str()); }

}  // namespace

int renderCommand(int argc, char** argv) {
    Args args(argc, argv, 2, {"-o", "--output", "--size", "--model", "--terms", "--encoding", "--gl-backend", "--spp"},
              {"-h", "--help", "--verbose", "--timings"});
    if (args.flag("-h") || args.flag("--help")) {
        std::fputs(kRenderHelp, stdout);
        return 0;
    }
    if (args.positionals().size() != 1)
        throw UsageError(args.positionals().empty() ? "render needs a scene file (see --help)"
                                                    : "render takes one scene file, got " +
                                                          std::to_string(args.positionals().size()));
    const std::string input = args.positionals()[0];
    std::optional<std::string> output = args.value("-o");
    if (!output) output = args.value("--output");
    if (!output || output->empty()) throw UsageError("render needs -o out.png");

    // Parse every option before any work, so usage errors never cost a render.
    int width = 1280, height = 720;
    if (auto s = args.value("--size")) std::tie(width, height) = parseSize(*s);
    std::optional<ShadingModel> model;
    if (auto m = args.value("--model")) model = parseModel(*m);
    std::optional<Terms> terms;
    if (auto t = args.value("--terms")) terms = parseTerms(*t);
    Encoding encoding = Encoding::Srgb;
    if (auto e = args.value("--encoding")) encoding = parseEncoding(*e);
    int spp = 1;
    if (auto v = args.value("--spp")) spp = parseInt("--spp", *v, 1, 64);
    raster::samplesPerSide(spp);  // validates: a perfect square
    gl::GlBackend backend = gl::GlBackend::Auto;
    if (auto b = args.value("--gl-backend")) backend = gl::parseGlBackend(*b);
    const bool verbose = args.flag("--verbose");

    StageTimer timer;
    // The scene loads on a worker thread while this one creates the GL context (both take tens of ms).
    auto sceneFuture = std::async(std::launch::async, [&] { return loadScene(input, printWarning); });
    std::vector<std::string> log;
    std::unique_ptr<gl::HeadlessContext> context;
    try {
        context = gl::createHeadlessContext(backend, verbose ? &log : nullptr);
    } catch (...) {
        sceneFuture.wait();
        throw;
    }
    timer.stage("context creation");
    for (const std::string& l : log) std::fprintf(stderr, "shadelab: %s\n", l.c_str());
    if (verbose) {
        const gl::ContextInfo& info = context->info();
        std::fprintf(stderr, "shadelab: gl backend %s (%s)\nshadelab: GL_RENDERER %s\nshadelab: GL_VERSION %s\n",
                     gl::toString(info.backend), info.device.c_str(), info.renderer.c_str(), info.version.c_str());
    }
    Scene scene = sceneFuture.get();
    timer.stage("scene load (overlaps context)");
    if (model) scene.model = *model;
    if (terms) scene.terms = *terms;
    if (scene.lights.size() > size_t(kMaxLights))
        throw InputError(input, "lights", "the rasterizer takes at most " + std::to_string(kMaxLights) + " lights");

    raster::RasterRenderer renderer;
    timer.stage("shader compile");
    renderer.uploadMeshes(scene);
    timer.stage("mesh upload");
    // Large images are drawn in bands so the RGBA32F target stays small (raster/offscreen.h).
    raster::OffscreenOptions offscreen;
    offscreen.width = width;
    offscreen.height = height;
    offscreen.spp = spp;
    offscreen.encoding = encoding;
    raster::OffscreenResult result = raster::renderOffscreen(renderer, scene, offscreen);
    const Image8& pixels = result.pixels;
    timer.stageSplit("draw, " + std::to_string(result.bands) + " band(s) (incl. lazy shader compile)", result.drawMs,
                     "readback + conversion", result.readMs);
    std::vector<uint8_t> png = encodePng(pixels);
    timer.stage("PNG encode");
    writeFileAtomic(*output, png.data(), png.size());
    timer.stage("write");

    if (args.flag("--timings")) timer.print(stderr);
    if (verbose)
        std::fprintf(stderr, "shadelab: wrote %s (%dx%d, %s, %zu bytes)\n", output->c_str(), width, height,
                     toString(encoding), png.size());
    return 0;
}

}  // namespace shadelab::cli
