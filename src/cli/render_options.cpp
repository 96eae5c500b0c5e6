// Parsing and validation of `shadelab render` options, and its --help text.
#include "cli/render_options.h"

#include "cli/args.h"
#include "cli/raster_flags.h"
#include "render/memory_budget.h"
#include "util/input_error.h"
#include "util/output_file.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

namespace shadelab::cli {

namespace {

const char* const kHelpHead =
    "usage: shadelab render <scene.json | model.gltf | model.glb> -o out.png|out.exr [options]\n"
    "\n"
    "Renders a scene headlessly and writes a PNG: with the OpenGL rasterizer (EGL or OSMesa, no X server),\n"
    "the CPU ray-traced reference, or both side by side with their difference heatmap. An .exr output holds\n"
    "the linear floats instead (OpenEXR: no clamp, no sRGB curve, values above 1 kept).\n"
    "\n"
    "options:\n"
    "  -o, --output PATH          image to write (required): .png, or .exr for linear OpenEXR; written\n"
    "                             atomically; - for a PNG on stdout. Refused when it is the scene or a file\n"
    "                             the scene loads, or exists and is not a regular file\n"
    "  --ray-tree X,Y             draw the Whitted ray tree of pixel X,Y (from the top left) on the PNG:\n"
    "                             the primary ray's hit, its shadow rays (yellow lit, red blocked) and\n"
    "                             reflected (blue) and refracted (green) rays; each ray in words on stderr\n"
    "  --coverage PATH            also write which object each pixel shows (design.md §4) as a PNG: the id\n"
    "                             in R + 256 G + 65536 B, 0 the background; raster or trace only. `shadelab\n"
    "                             compare --coverage-a/--coverage-b` then gates silhouettes as the tests do\n"
    "  --exr-precision NAME       .exr output: float (default, 32-bit, exact) | half (16-bit, 11 bits)\n"
    "  --passes                   .exr output: also the layers albedo (R G B), normal (X Y Z) and depth (Z)\n"
    "                             of the first hit at each pixel centre; path: variance (Y) of each\n"
    "                             pixel's luminance estimate, and with --denoise the raw estimate (raw)\n"
    "  --size WxH                 image size in pixels, each side 1..16384 (default 1280x720)\n"
    "  --renderer NAME            raster (default) | trace | both (raster | traced | heatmap in one PNG) |\n"
    "                             path (the path tracer: global illumination, docs/lighting.md)\n"
    "  --model NAME               phong | blinn-phong | pbr | disney, blinn-phong also written blinn (default:\n"
    "                             the scene's)\n"
    "  --terms LIST               comma-separated terms to switch on, the rest off:\n"
    "                             ambient,diffuse,specular,shadows,reflections or none (default: the scene's)\n"
    "  --spp N                    samples per pixel on a fixed k x k grid; N = 1, 4, 9, ..., 64 (default 1);\n"
    "                             --renderer path: any N from 1 (default 16)\n"
    "  --camera fit|file|N        fit: frame the scene's bounds (default for a .gltf/.glb); file: the scene\n"
    "                             file's camera (default for a .json) or a model's first glTF camera; N: the\n"
    "                             model's glTF camera N, from 0\n"
    "  --threads N                tracer threads, 0 = every core (default 0)\n"
    "  --depth N                  tracer secondary-ray depth, 0..64 (default: the scene's maxDepth; with\n"
    "                             --renderer both at most 1, the rasterizer's one bounce; path: bounces\n"
    "                             after the camera hit, 0 = direct light only)\n"
    "  --time-limit SECONDS       path: stop at the last whole sample pass begun within this time, and say\n"
    "                             how many samples it took (at most --spp)\n"
    "  --estimator NAME           path: mis (default) | bsdf | light: how emitters' light is sampled; all\n"
    "                             converge to the same image, with different noise\n"
    "  --light-paths NAME         path: all (default) | direct | indirect: indirect is the light scattered\n"
    "                             twice or more, what the lecture's ambient term stands in for\n"
    "  --denoise                  path: write the denoised preview (an edge-avoiding filter guided by the\n"
    "                             first hit's albedo, normal and depth) instead of the raw estimate\n"
    "  --sampler NAME             path: sobol (default) | independent: Owen-scrambled Sobol numbers,\n"
    "                             stratified in each pixel, or independent random ones (more noise)\n"
    "  --seed N                   path: the random numbers' variation, 0..4294967295 (default 0): the same\n"
    "                             seed gives the same bytes, another seed another noise\n";

const char* const kHelpTail =
    "  --encoding NAME            srgb (default) | linear: how linear colour becomes 8-bit\n"
    "  --exposure STOPS           multiply linear values by 2^STOPS before the view transform, -16..16\n"
    "                             (default: the scene's display.exposure, else 0); the PNG only\n"
    "  --view-transform NAME      standard (clamp to [0,1], the default) | filmic (Narkowicz's ACES fit:\n"
    "                             highlights roll off instead of clipping); default: the scene's\n"
    "  --gl-backend NAME          auto | egl-device | egl-surfaceless | osmesa\n"
    "                             (default auto; also the SHADELAB_GL_BACKEND environment variable)\n"
    "  --allow-external-paths     let glTF buffer URIs point outside the model's folder (../, absolute)\n"
    "  --strict                   a warning about the input (an image that cannot be read or decoded, an\n"
    "                             unknown field, a skipped feature) is an error: exit 1, nothing written\n"
    "  --max-memory SIZE          refuse a render (and an environment map's load) estimated to need\n"
    "                             more, e.g. 512M or 4G, a bare number in MiB; less than any render of\n"
    "                             the request needs is a usage error (default: half of physical memory,\n"
    "                             within ulimit -v)\n"
    "  --timings                  print a per-stage timing and memory breakdown to stderr\n"
    "  --verbose                  log the GL backend, GL_RENDERER and GL_VERSION to stderr\n"
    "  -h, --help                 show this help\n"
    "\n"
    "The tracer shows a progress bar on stderr when stderr is a terminal.\n"
    "exit codes: 0 written, 1 bad input or rendering failure (one line on stderr), 2 usage error\n";

}  // namespace

std::string flagOf(const std::string& field) {
    std::string flag = "--" + field;
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
}

OutputFormat outputFormat(const RenderOptions& o) {
    if (hasExrExtension(o.output) && !isStdout(o.output)) {
        if (o.rayTree) throw UsageError("--ray-tree: only for a PNG output (-o " + o.output + " writes linear EXR)");
        return OutputFormat::Exr;
    }
    const std::string& p = o.output;
    std::string ext = p.size() >= 4 ? p.substr(p.size() - 4) : std::string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const bool png = isStdout(p) || ext == ".png";
    if (!png)
        throw UsageError("-o: '" + p + "' names no image format; expected a name ending in .png or .exr (- for " +
                         "a PNG on stdout)");
    if (o.exrPrecision) throw UsageError("--exr-precision: only for an .exr output (-o " + p + " writes a PNG)");
    if (o.passes) throw UsageError("--passes: only for an .exr output (-o " + p + " writes a PNG)");
    return OutputFormat::Png;
}

std::string renderHelp() { return std::string(kHelpHead) + kRasterFlagsHelp + kHelpTail; }

Terms parseTerms(const std::string& list) {
    Terms t{false, false, false, false, false};
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        if (auto term = parseTerm(name))
            termFlag(t, *term) = true;
        else if (name != "none" && !name.empty())
            throw UsageError("--terms: unknown term '" + name + "'; expected " + nameChoices(kTermNames, "none"));
    }
    return t;
}

CameraChoice parseCameraFlag(const std::string& value) {
    if (auto c = parseCameraChoice(value)) return *c;
    throw UsageError("--camera: expected fit, file or a camera number 0..999, got '" + value + "'");
}

namespace {

// --seed: digits only; up to 18 of them fit an int64_t, and the request's range check words the rest.
int64_t parseSeed(const std::string& value) {
    if (value.empty() || value.size() > 18 || value.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError("--seed: expected a whole number from 0 to " + std::to_string(render::kMaxSeed) + ", got '" +
                         value + "'");
    return std::stoll(value);
}

// --ray-tree X,Y: a pixel of the image, column then row from the top left; a PNG of one renderer.
std::pair<int, int> parseRayTreePixel(const std::string& value, const render::RenderRequest& r) {
    const size_t comma = value.find(',');
    if (comma == std::string::npos)
        throw UsageError("--ray-tree: expected X,Y (a pixel, from the top left), got '" + value + "'");
    const int x = parseWhole("--ray-tree", value.substr(0, comma));
    const int y = parseWhole("--ray-tree", value.substr(comma + 1));
    if (x < 0 || y < 0 || x >= r.width || y >= r.height)
        throw UsageError("--ray-tree: pixel " + value + " is outside the " + std::to_string(r.width) + "x" +
                         std::to_string(r.height) + " image");
    if (r.engine == render::Engine::Both)
        throw UsageError("--ray-tree: only with --renderer raster, trace or path (both writes three images)");
    return {x, y};
}

}  // namespace

RenderOptions parseRenderOptions(int argc, char** argv) {
    std::vector<std::string> valued = {
        "-o",           "--output",        "--size",      "--model",       "--terms",         "--encoding",
        "--gl-backend", "--spp",           "--renderer",  "--threads",     "--depth",         "--max-memory",
        "--camera",     "--time-limit",    "--estimator", "--light-paths", "--exr-precision", "--sampler",
        "--exposure",   "--view-transform"};
    valued.emplace_back("--seed");
    valued.emplace_back("--coverage");
    valued.emplace_back("--ray-tree");
    std::vector<std::string> flags = {"-h",       "--help",   "--verbose", "--timings", "--allow-external-paths",
                                      "--strict", "--passes", "--denoise"};
    valued.insert(valued.end(), rasterValuedFlags().begin(), rasterValuedFlags().end());
    flags.insert(flags.end(), rasterSwitchFlags().begin(), rasterSwitchFlags().end());
    Args args(argc, argv, 2, valued, flags);
    RenderOptions o;
    if (args.flag("-h") || args.flag("--help")) {
        o.help = true;
        return o;
    }
    if (args.positionals().size() != 1)
        throw UsageError(args.positionals().empty()
                             ? "render needs a scene file (see --help)"
                             : "render takes one scene file, got " + std::to_string(args.positionals().size()));
    o.input = args.positionals()[0];
    if (auto v = args.value("-o")) o.output = *v;
    if (auto v = args.value("--output")) o.output = *v;
    if (o.output.empty()) throw UsageError("render needs -o out.png");
    if (auto v = args.value("--coverage")) o.coverage = *v;
    render::RenderRequest& r = o.request;
    if (auto v = args.value("--size")) std::tie(r.width, r.height) = parseSize(*v);
    if (auto v = args.value("--max-memory")) {
        try {
            r.maxMemory = render::parseMemorySize(*v);
        } catch (const SettingError& e) {
            throw UsageError(flagOf(e.field()) + ": " + e.reason());
        }
    }
    if (auto v = args.value("--model")) o.model = parseChoice("--model", *v, kShadingModelNames);
    if (auto v = args.value("--terms")) o.terms = parseTerms(*v);
    if (auto v = args.value("--encoding")) r.encoding = parseChoice("--encoding", *v, kEncodingNames);
    if (auto v = args.value("--exposure")) r.exposure = parseReal("--exposure", *v);
    if (auto v = args.value("--view-transform"))
        r.viewTransform = parseChoice("--view-transform", *v, kViewTransformNames);
    if (auto v = args.value("--renderer")) r.engine = parseChoice("--renderer", *v, render::kEngineNames);
    if (auto v = args.value("--spp")) r.spp = parseWhole("--spp", *v);
    if (auto v = args.value("--camera")) o.camera = parseCameraFlag(*v);
    if (auto v = args.value("--time-limit")) r.path.timeLimit = parseReal("--time-limit", *v);
    if (auto v = args.value("--estimator"))
        r.path.estimator = parseChoice("--estimator", *v, trace::kPathEstimatorNames);
    if (auto v = args.value("--light-paths")) r.path.part = parseChoice("--light-paths", *v, trace::kPathPartNames);
    r.path.denoise = args.flag("--denoise");
    if (auto v = args.value("--sampler")) r.path.sampler = parseChoice("--sampler", *v, trace::kPathSamplerNames);
    if (auto v = args.value("--seed")) r.path.seed = parseSeed(*v);
    if (auto v = args.value("--threads")) r.threads = parseWhole("--threads", *v);
    if (auto v = args.value("--depth")) r.depth = parseWhole("--depth", *v);
    if (!o.coverage.empty()) {
        if (r.engine != render::Engine::Raster && r.engine != render::Engine::Trace)
            throw UsageError(
                "--coverage: only with --renderer raster or trace (the path tracer keeps no coverage, "
                "and both would write two)");
        if (isStdout(o.coverage)) throw UsageError("--coverage: needs a file name (stdout carries the image)");
        if (o.coverage == o.output) throw UsageError("--coverage: '" + o.coverage + "' is also the -o image");
        r.coverage = true;
    }
    if (auto v = args.value("--ray-tree")) o.rayTree = parseRayTreePixel(*v, r);
    // The ranges are the request's, as every front end holds them; only the words are the command line's.
    if (std::optional<render::RequestProblem> p = render::check(r))
        throw UsageError(flagOf(p->field) + ": " + p->reason);
    if (auto v = args.value("--exr-precision")) o.exrPrecision = parseChoice("--exr-precision", *v, kExrPrecisionNames);
    if (auto v = args.value("--gl-backend")) o.backend = parseChoice("--gl-backend", *v, gl::kGlBackendNames);
    o.raster = parseRasterFlags(args);
    o.allowExternalPaths = args.flag("--allow-external-paths");
    o.verbose = args.flag("--verbose");
    o.timings = args.flag("--timings");
    o.strict = args.flag("--strict");
    o.passes = args.flag("--passes");
    return o;
}

}  // namespace shadelab::cli
