// `shadelab render`: load the scene (on a worker thread while the GL context starts), render it with the
// rasterizer, the tracer or both, convert once to 8-bit, write the PNG atomically (or to stdout for `-o -`).
// --timings prints the per-stage breakdown.
#include "cli/render_command.h"

#include "cli/progress_bar.h"
#include "cli/render_options.h"
#include "cli/stage_timer.h"
#include "compare/compare_report.h"
#include "compare/comparison.h"
#include "compare/difference_sites.h"
#include "compare/image_compare.h"
#include "gl/headless_context.h"
#include "image/encode.h"
#include "image/png.h"
#include "raster/offscreen.h"
#include "render/memory_budget.h"
#include "scene/scene_load.h"
#include "trace/path/path_render.h"
#include "trace/trace_image.h"
#include "util/input_error.h"
#include "util/messages.h"
#include "util/output_file.h"

#include <algorithm>
#include <cstdio>
#include <future>
#include <memory>
#include <optional>
#include <string>

namespace shadelab::cli {
namespace {

std::unique_ptr<gl::HeadlessContext> startContext(const RenderOptions& o, StageTimer& timer) {
    std::vector<std::string> log;
    std::unique_ptr<gl::HeadlessContext> context = gl::createHeadlessContext(o.backend, o.verbose ? &log : nullptr);
    timer.stage("context creation");
    for (const std::string& l : log) std::fprintf(stderr, "shadelab: %s\n", l.c_str());
    if (o.verbose) {
        const gl::ContextInfo& info = context->info();
        std::fprintf(stderr, "shadelab: gl backend %s (%s)\nshadelab: GL_RENDERER %s\nshadelab: GL_VERSION %s\n",
                     gl::toString(info.backend), info.device.c_str(), info.renderer.c_str(), info.version.c_str());
    }
    return context;
}

// `display`: what the pixels are encoded with (render::displayOf, or Standard for a comparison); `linear`, when
// given, receives the float image too.
Rendered rasterize(const Scene& scene, const render::RenderRequest& request, const DisplaySettings& display,
                   StageTimer& timer, ImageF* linear = nullptr) {
    raster::RasterRenderer renderer;
    timer.stage("shader compile");
    renderer.uploadMeshes(scene);
    timer.stage("mesh upload");
    raster::OffscreenOptions options = render::toOffscreen(request, scene);
    options.display = display;
    options.keepLinear = linear != nullptr;
    raster::OffscreenResult r = raster::renderOffscreen(renderer, scene, options);
    timer.stageSplit("draw, " + std::to_string(r.bands) + " band(s) (incl. lazy shader compile)", r.drawMs,
                     "readback + conversion", r.readMs);
    if (linear) *linear = std::move(r.linear);
    return {std::move(r.pixels), std::move(r.coverage), r.nonFinite};
}

Rendered traceReference(const Scene& scene, const render::RenderRequest& request, const DisplaySettings& display,
                        StageTimer& timer, ImageF* linear = nullptr) {
    const trace::TraceSettings settings = render::toTrace(request, scene);
    trace::TraceOutput out;
    {
        ProgressBar bar("tracing");
        out = trace::traceImage(scene, settings, [&bar](float f) { bar.update(f); });
    }
    timer.stage("trace");
    Rendered r;
    r.pixels = toImage8(out.color, request.encoding, display, &r.nonFinite);
    r.coverage = std::move(out.coverage);
    timer.stage("conversion");
    if (linear) *linear = std::move(out.color);
    return r;
}

// The path tracer (design.md §8): settings from the request, a progress bar, and one line saying how many
// samples it took and how noisy the image is.
Rendered pathTrace(const Scene& scene, const render::RenderRequest& request, StageTimer& timer) {
    const trace::PathSettings settings = render::toPath(request, scene);
    auto traced = std::make_shared<const trace::TraceScene>(scene);
    timer.stage("BVH build");
    trace::PathOutput out;
    {
        ProgressBar bar("path tracing");
        out = trace::pathTraceImage(traced, settings, [&bar](float f) { bar.update(f); });
    }
    timer.stage("path trace");
    const double paths = double(settings.width) * double(settings.height) * double(out.spp);
    std::fprintf(stderr,
                 "shadelab: path traced %d samples per pixel%s in %.2f s (%.2f M paths/s, %d bounces); mean "
                 "standard error %.2f (8-bit sRGB units)\n",
                 out.spp, settings.timeLimit > 0.0 && out.spp < settings.spp ? " (time limit)" : "", out.seconds,
                 paths / std::max(out.seconds, 1e-9) * 1e-6, settings.maxDepth, out.meanStandardError8);
    Rendered r;
    r.pixels = toImage8(out.color, request.encoding, render::displayOf(request, scene), &r.nonFinite);
    timer.stage("conversion");
    return r;
}

// --strict: a warning about the input ends the render with that line as the error (exit 1), before anything
// is written.
void failOnWarning(const std::string& text) { throw InputError("", text + " (an error under --strict)"); }

// The render itself; `doing` names the stage in progress, for an out-of-memory message.
int render(const RenderOptions& o, std::string& doing) {
    const render::RenderRequest& request = o.request;
    const bool needRaster = request.engine == render::Engine::Raster || request.engine == render::Engine::Both;
    StageTimer timer;
    // The scene loads on a worker thread while this one creates the GL context (both take tens of ms).
    GltfImportOptions gltf;
    gltf.allowExternalPaths = o.allowExternalPaths;
    // The environment map's load is held to --max-memory from its header, before its pixels are decoded.
    const MemoryLimit memory{render::memoryLimit(request), "--max-memory"};
    auto sceneFuture = std::async(
        std::launch::async, [&] { return loadScene(o.input, o.strict ? failOnWarning : printWarning, gltf, memory); });
    std::unique_ptr<gl::HeadlessContext> context;
    if (needRaster) {
        try {
            context = startContext(o, timer);
        } catch (...) {
            sceneFuture.wait();
            throw;
        }
    }
    Scene scene = sceneFuture.get();
    doing = "rendering";
    timer.stage(needRaster ? "scene load (beyond context creation)" : "scene load");
    refuseInputAsOutput(o.output, "-o", scene.inputs.paths());
    if (o.camera) scene.camera = chooseCamera(scene, *o.camera, o.input);
    if (o.model) scene.model = *o.model;
    if (o.terms) scene.terms = *o.terms;
    o.raster.applyTo(scene.raster);
    if (needRaster && scene.lights.size() > size_t(kMaxLights))
        throw InputError(o.input, "lights", "the rasterizer takes at most " + std::to_string(kMaxLights) + " lights");
    if (std::optional<std::string> over = render::memoryProblem(scene, request))
        throw InputError(o.input, *over + " (--max-memory)");

    // A pixel with no finite value is said out loud (an error under --strict), before anything is written.
    auto report = [&](const char* renderer, const Rendered& r) {
        if (r.nonFinite == 0) return;
        const uint64_t pixels = uint64_t(r.pixels.width) * uint64_t(r.pixels.height);
        (o.strict ? failOnWarning
                  : printWarning)(o.input + ": " + renderer + ": " + nonFiniteMessage(r.nonFinite, pixels));
    };
    Image8 output;
    const DisplaySettings display = render::displayOf(request, scene);
    if (request.engine == render::Engine::Raster) {
        Rendered r = rasterize(scene, request, display, timer);
        report("raster", r);
        output = std::move(r.pixels);
    } else if (request.engine == render::Engine::Trace) {
        Rendered r = traceReference(scene, request, display, timer);
        report("trace", r);
        output = std::move(r.pixels);
    } else if (request.engine == render::Engine::Path) {
        Rendered r = pathTrace(scene, request, timer);
        report("path", r);
        output = std::move(r.pixels);
    } else {
        // The comparison and its heatmap read the Standard bytes, whatever the display: the numbers are the
        // renderers', not the view's. The two images beside the heatmap are shown through the display.
        const bool shown = !display.isStandard();
        ImageF linearA, linearB;
        Rendered a = rasterize(scene, request, DisplaySettings{}, timer, shown ? &linearA : nullptr);
        Rendered b = traceReference(scene, request, DisplaySettings{}, timer, shown ? &linearB : nullptr);
        report("raster", a);
        report("trace", b);
        CompareResult cmp = compareImages(a.pixels, b.pixels, a.coverage, b.coverage);
        Image8 heat = diffHeatmap(a.pixels, b.pixels, cmp.bandMask);
        std::fprintf(stderr, "shadelab: raster | traced (depth %d) | heatmap; raster vs reference:\n%s",
                     render::traceDepth(request, scene), compareSummary(cmp).c_str());
        // The verdict is under the strict gates of design.md §4; say in words where the images differ and why.
        const DifferenceSites sites = differenceSites(a.pixels, b.pixels, a.coverage, cmp);
        std::fprintf(stderr, "%s\n", describeDifference(scene, sites, cmp.gates.threshold).c_str());
        if (shown) {
            a.pixels = toImage8(linearA, request.encoding, display, nullptr);
            b.pixels = toImage8(linearB, request.encoding, display, nullptr);
        }
        output = sideBySide({&a.pixels, &b.pixels, &heat});
        timer.stage("compare + heatmap");
    }
    doing = "encoding the PNG";
    std::vector<uint8_t> png = encodePng(output);
    timer.stage("PNG encode");
    writeOutput(o.output, png.data(), png.size());
    timer.stage("write");

    if (o.timings) timer.print(stderr);
    if (o.verbose)
        std::fprintf(stderr, "shadelab: wrote %s (%dx%d, %s%s%s, %zu bytes)\n",
                     isStdout(o.output) ? "stdout" : o.output.c_str(), output.width, output.height,
                     toString(request.encoding), display.isStandard() ? "" : ", ", describe(display).c_str(),
                     png.size());
    return 0;
}

}  // namespace

int renderCommand(int argc, char** argv) {
    const RenderOptions o = parseRenderOptions(argc, argv);
    if (o.help) {
        std::fputs(renderHelp().c_str(), stdout);
        return 0;
    }
    // Before any work: a render that cannot be written, or would replace its own scene, is refused now.
    checkOutput(o.output, "-o", {o.input});

    // std::bad_alloc names no file and no stage; say both (an allocation the budget did not foresee).
    std::string doing = "loading the scene";
    try {
        return render(o, doing);
    } catch (const SettingError& e) {
        // A limit only a renderer knows (the GL's widest target): worded as the flag it names, exit 2.
        throw UsageError(flagOf(e.field()) + ": " + e.reason());
    } catch (const std::bad_alloc&) {
        throw InputError(o.input, "out of memory while " + doing + " (see --max-memory and --size)");
    }
}

}  // namespace shadelab::cli
