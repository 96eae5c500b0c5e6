// `shadelab render`: load the scene (on a worker thread while the GL context starts), render it with the
// rasterizer, the tracer or both, convert once to 8-bit, write the PNG atomically (or to stdout for `-o -`), or
// write the linear floats before that conversion as OpenEXR (`-o x.exr`). --timings prints the per-stage breakdown.
#include "cli/render_command.h"

#include "cli/progress_bar.h"
#include "cli/render_options.h"
#include "cli/stage_timer.h"
#include "compare/compare_report.h"
#include "compare/comparison.h"
#include "compare/coverage_image.h"
#include "compare/difference_sites.h"
#include "compare/image_compare.h"
#include "gl/headless_context.h"
#include "image/encode.h"
#include "image/exr.h"
#include "image/png.h"
#include "probe/ray_tree_picture.h"
#include "raster/offscreen.h"
#include "render/memory_budget.h"
#include "scene/scene_load.h"
#include "scene/scene_models.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_render.h"
#include "trace/trace_image.h"
#include "util/heap_warmup.h"
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

// One renderer's image: the 8-bit pixels (and coverage) and, for an EXR output, the linear floats they came from.
struct Frame {
    Rendered rendered;
    ImageF linear;                 // empty unless asked for
    std::vector<ExrLayer> passes;  // --passes: what this renderer adds of its own (path: variance, raw)
    SurfacePasses surface;         // path with --denoise: the first-hit passes it traced already
};

// One layer of `channels` floats per pixel from an interleaved buffer.
ExrLayer layerOf(const std::string& name, std::vector<std::string> channels, std::vector<float> samples) {
    ExrLayer l;
    l.name = name;
    l.channels = std::move(channels);
    l.samples = std::move(samples);
    return l;
}

// --passes: the first hit's albedo, normal and depth at each pixel centre (trace/first_hit_passes.h).
std::vector<ExrLayer> surfaceLayers(SurfacePasses p) {
    std::vector<ExrLayer> out;
    out.push_back(layerOf("albedo", {"R", "G", "B"}, std::move(p.albedo)));
    out.push_back(layerOf("normal", {"X", "Y", "Z"}, std::move(p.normal)));
    out.push_back(layerOf("depth", {"Z"}, std::move(p.depth)));
    return out;
}

// `display`: what the pixels are encoded with (render::displayOf, or Standard for a comparison).
Frame rasterize(const Scene& scene, const render::RenderRequest& request, const DisplaySettings& display,
                bool keepLinear, StageTimer& timer) {
    // One render: each program is compiled by the draw that needs it (a shader error is reported from there).
    raster::RasterRenderer renderer(gl::ShaderLibrary(), raster::ProgramCheck::OnFirstUse);
    renderer.setTriangleBatches(true);
    timer.stage("renderer set-up");
    renderer.uploadMeshes(scene);
    timer.stage("mesh upload");
    raster::OffscreenOptions options = render::toOffscreen(request, scene);
    options.display = display;
    options.keepLinear = keepLinear;
    raster::OffscreenResult r = raster::renderOffscreen(renderer, scene, options);
    timer.stageSplit("draw, " + std::to_string(r.bands) + " band(s) (incl. lazy shader compile)", r.drawMs,
                     "readback + conversion", r.readMs);
    return {{std::move(r.pixels), std::move(r.coverage), r.nonFinite}, std::move(r.linear), {}, {}};
}

Frame traceReference(const Scene& scene, const render::RenderRequest& request, const DisplaySettings& display,
                     bool keepLinear, StageTimer& timer) {
    const trace::TraceSettings settings = render::toTrace(request, scene);
    // An 8-bit output is converted tile by tile as the tracer delivers (no float image); EXR keeps the floats.
    const trace::TraceEncoding encoding{request.encoding, display};
    trace::TraceOutput out;
    {
        ProgressBar bar("tracing");
        out = trace::traceImage(
            scene, settings, [&bar](float f) { bar.update(f); }, keepLinear ? nullptr : &encoding);
    }
    timer.stage("trace");
    Frame f;
    if (keepLinear) {
        f.rendered.pixels = toImage8(out.color, request.encoding, display, &f.rendered.nonFinite);
        f.linear = std::move(out.color);
        timer.stage("conversion");
    } else {
        f.rendered.pixels = std::move(out.pixels);
        f.rendered.nonFinite = out.nonFinite;
    }
    f.rendered.coverage = std::move(out.coverage);
    return f;
}

// The path tracer (design.md §8): settings from the request, a progress bar, and one line saying how many
// samples it took and how noisy the image is.
Frame pathTrace(const Scene& scene, const render::RenderRequest& request, bool keepLinear, StageTimer& timer) {
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
    Frame f;
    if (settings.denoise && keepLinear) {
        // The passes that guided the denoiser serve --passes; the estimate before it is layer "raw".
        f.surface = std::move(out.passes);
        f.passes.push_back(colourLayer(out.raw));
        f.passes.back().name = "raw";
    }
    if (keepLinear) f.passes.push_back(layerOf("variance", {"Y"}, std::move(out.variance)));
    f.rendered.pixels = toImage8(out.color, request.encoding, render::displayOf(request, scene), &f.rendered.nonFinite);
    if (keepLinear) f.linear = std::move(out.color);
    timer.stage("conversion");
    return f;
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
    // On the software rasterizer, the pages of the render targets are made ready on another core while this
    // one creates the context, instead of one page fault per 4 KiB as llvmpipe zero-fills them. Raster renders
    // only: the tracer's large blocks are better off in mappings of their own, which go back when freed.
    std::optional<HeapWarmup> warmup;
    if (request.engine == render::Engine::Raster && gl::softwareContextExpected(o.backend))
        warmup.emplace(render::softwareRasterHeapBytes(request));
    auto sceneFuture = std::async(std::launch::async, [&] {
        Scene loaded = loadScene(o.input, o.strict ? failOnWarning : printWarning, gltf, memory);
        if (warmup) warmup->populate();  // the input is good: the render will use that memory
        return loaded;
    });
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
    if (warmup) warmup->releaseFreedElsewhere();  // the loader's buffers, before the draw's peak
    doing = "rendering";
    timer.stage(needRaster ? "scene load (beyond context creation)" : "scene load");
    refuseInputAsOutput(o.output, "-o", scene.inputs.paths());
    if (!o.coverage.empty()) refuseInputAsOutput(o.coverage, "--coverage", scene.inputs.paths());
    // The format is the output's extension. Checked after the input refusals, so that an output naming an input
    // (scene.json, a model's .bin) is reported as that, whatever its extension.
    const OutputFormat format = outputFormat(o);
    if (o.camera) scene.camera = chooseCamera(scene, *o.camera, o.input);
    if (o.model) scene.model = *o.model;
    if (o.terms) scene.terms = *o.terms;
    // A glTF file is a scene of its own under the lecture's phong: its layers would vanish without a word.
    if (const std::string layers = layersNotShown(scene); !layers.empty())
        (o.strict ? failOnWarning : printWarning)(
            o.input + ": glTF's " + layers + (layers.find(',') == std::string::npos ? " shades" : " shade") +
            " only under pbr, not under the model this render gives the objects that carry it (--model pbr shows it)");
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
    const bool exr = format == OutputFormat::Exr;
    const DisplaySettings display = render::displayOf(request, scene);
    Image8 output;    // the PNG's pixels
    Image8 coverage;  // --coverage: the ids as pixels
    ExrImage linear;  // the EXR's layers: the colour before conversion (--renderer both: the raster's, and
                      // the reference's as layer "trace")
    auto keep = [&](Frame& f, const char* layer) {
        if (!exr) return;
        if (linear.layers.empty()) {
            linear = exrFromImage(f.linear);
        } else {
            linear.layers.push_back(colourLayer(f.linear));
            linear.layers.back().name = layer;
        }
        f.linear = ImageF();
        // The surface passes once (--renderer both: its two images show the same surfaces).
        if (!o.passes || *layer) return;
        if (f.surface.width == 0) {
            const trace::TraceScene traced(scene);
            f.surface = trace::firstHitPasses(traced, request.width, request.height, request.threads);
            timer.stage("surface passes");
        }
        for (ExrLayer& l : surfaceLayers(std::move(f.surface))) linear.layers.push_back(std::move(l));
        for (ExrLayer& l : f.passes) linear.layers.push_back(std::move(l));
    };
    if (request.engine == render::Engine::Raster) {
        Frame f = rasterize(scene, request, display, exr, timer);
        report("raster", f.rendered);
        keep(f, "");
        output = std::move(f.rendered.pixels);
        if (!o.coverage.empty()) coverage = coverageToImage(f.rendered.coverage, output.width, output.height);
    } else if (request.engine == render::Engine::Trace) {
        Frame f = traceReference(scene, request, display, exr, timer);
        report("trace", f.rendered);
        keep(f, "");
        output = std::move(f.rendered.pixels);
        if (!o.coverage.empty()) coverage = coverageToImage(f.rendered.coverage, output.width, output.height);
    } else if (request.engine == render::Engine::Path) {
        Frame f = pathTrace(scene, request, exr, timer);
        report("path", f.rendered);
        keep(f, "");
        output = std::move(f.rendered.pixels);
    } else {
        // The comparison and its heatmap read the Standard bytes, whatever the display: the numbers are the
        // renderers', not the view's. The two images beside the heatmap are shown through the display.
        const bool shown = !display.isStandard() && !exr;
        Frame fa = rasterize(scene, request, DisplaySettings{}, exr || shown, timer);
        Frame fb = traceReference(scene, request, DisplaySettings{}, exr || shown, timer);
        Rendered &a = fa.rendered, &b = fb.rendered;
        report("raster", a);
        report("trace", b);
        CompareResult cmp = compareImages(a.pixels, b.pixels, a.coverage, b.coverage);
        std::fprintf(stderr, "shadelab: raster | traced (depth %d) | heatmap; raster vs reference:\n%s",
                     render::traceDepth(request, scene), compareSummary(cmp).c_str());
        // The verdict is under the strict gates of design.md §4; say in words where the images differ and why.
        const DifferenceSites sites = differenceSites(a.pixels, b.pixels, a.coverage, cmp);
        std::fprintf(stderr, "%s\n", describeDifference(scene, sites, cmp.gates.threshold).c_str());
        if (!exr) {
            Image8 heat = diffHeatmap(a.pixels, b.pixels, cmp.bandMask);
            if (shown) {
                a.pixels = toImage8(fa.linear, request.encoding, display, nullptr);
                b.pixels = toImage8(fb.linear, request.encoding, display, nullptr);
            }
            output = sideBySide({&a.pixels, &b.pixels, &heat});
        } else {
            output = a.pixels;
        }
        keep(fa, "");
        keep(fb, "trace");
        timer.stage("compare + heatmap");
    }
    if (o.rayTree) {
        // The tree the reference traces at this pixel, at the render's depth, drawn over whichever renderer's
        // image; its rays in words on stderr (stdout may carry the PNG).
        Scene traced = scene;
        traced.maxDepth = render::traceDepth(request, scene);
        const trace::TraceScene ts(traced);
        const RayTreeView tree = recordRayTree(ts, request.width, request.height, o.rayTree->first, o.rayTree->second);
        drawRayTreePicture(output, traced, tree);
        std::fprintf(stderr, "shadelab: the ray tree of pixel %d,%d (depth %d):\n", tree.x, tree.y, traced.maxDepth);
        for (size_t k = 0; k < tree.record.rays.size(); ++k)
            std::fprintf(stderr, "  %s\n", rayTreeRayLine(traced, tree.record, k).c_str());
        timer.stage("ray tree");
    }
    size_t written = 0;
    if (exr) {
        doing = "encoding the EXR";
        const std::string bytes = encodeExr(linear, o.exrPrecision.value_or(ExrPrecision::Float));
        timer.stage("EXR encode");
        writeOutput(o.output, bytes.data(), bytes.size());
        written = bytes.size();
    } else {
        doing = "encoding the PNG";
        std::vector<uint8_t> png = encodePng(output);
        timer.stage("PNG encode");
        writeOutput(o.output, png.data(), png.size());
        written = png.size();
    }
    if (!o.coverage.empty()) {
        doing = "encoding the coverage PNG";
        const std::vector<uint8_t> png = encodePng(coverage);
        writeOutput(o.coverage, png.data(), png.size());
    }
    timer.stage("write");

    if (o.timings) timer.print(stderr);
    if (o.verbose)
        std::fprintf(
            stderr, "shadelab: wrote %s (%dx%d, %s, %zu bytes)\n", isStdout(o.output) ? "stdout" : o.output.c_str(),
            output.width, output.height,
            format == OutputFormat::Exr
                ? (std::string("linear EXR, ") + toString(o.exrPrecision.value_or(ExrPrecision::Float))).c_str()
                : toString(request.encoding),
            written);
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
    if (!o.coverage.empty()) checkOutput(o.coverage, "--coverage", {o.input});

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
