// `shadelab view`: command-line parsing for the viewer, the display check, and loading the scene and
// script before the window opens (so bad input fails fast with exit code 1, usage errors with 2).
#include "cli/view_command.h"

#include "app/app.h"
#include "cli/args.h"
#include "cli/raster_flags.h"
#include "cli/render_options.h"
#include "image/image.h"
#include "scene/scene_load.h"
#include "util/input_error.h"
#include "util/messages.h"
#include "util/output_file.h"
#include "util/warning_capture.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace shadelab::cli {
namespace {

const char* const kViewHelpHead =
    "usage: shadelab view [scene.json | model.gltf | model.glb] [options]\n"
    "\n"
    "Opens the interactive viewer (GLFW + Dear ImGui): live raster image, progressive ray-traced reference,\n"
    "lighting probe. Without a scene it opens assets/scenes/default.json. Needs a display; for images\n"
    "without one use 'shadelab render'. Controls and script format: docs/viewer.md\n"
    "\n"
    "options:\n"
    "  --size WxH                 render size in pixels, each side 1..16384 (default: follow the window)\n"
    "  --frames N                 exit after N frames (and after the script's last action)\n"
    "  --screenshot PATH          at exit, write the rendered image (no UI) as PNG, the same pixels\n"
    "                             'shadelab render' gives for that state and size\n"
    "  --window-screenshot PATH   at exit, write the whole window, UI included, as PNG\n"
    "  --script PATH              apply the actions in this JSON file between frames\n"
    "  --probe-report PATH        at exit, write the probe's numbers as JSON (set it with a 'probe' action)\n"
    "  --encoding NAME            srgb (default) | linear, for the display and the screenshots\n"
    "  --exposure STOPS           -16..16: linear values times 2^STOPS on screen and in screenshots\n"
    "                             (default: the scene's display.exposure, else 0)\n"
    "  --view-transform NAME      standard (clamp, the default) | filmic (Narkowicz's ACES fit), on screen\n"
    "                             and in screenshots (default: the scene's display.viewTransform)\n"
    "  --stats                    redraw the image every other frame; print median and 95th-percentile\n"
    "                             frame times with and without a redraw\n"
    "  --camera fit|file|N        the camera to open with, as for 'shadelab render' (default: a scene file's\n"
    "                             own, a model framed to fit); F and R switch between fit and file\n"
    "  --ui-scale F               UI scale, 0.5..4 (default: the monitor's content scale)\n"
    "  --projector                for a classroom projector: UI scale 2 (unless --ui-scale is given) and\n"
    "                             the panel laid over the image, which keeps the window's shape (key F11)\n";

// Then the raster flags (cli/raster_flags.h), which apply to the scene named on the command line.
const char* const kViewHelpTail =
    "  --verbose                  log GL_RENDERER, GL_VERSION and where shaders come from\n"
    "  -h, --help                 show this help\n"
    "\n"
    "The raster flags override the \"raster\" settings of the scene opened at start, not of scenes opened later.\n"
    "exit codes: 0 done, 1 bad input or no display (one line on stderr), 2 usage error\n";

std::string defaultScenePath() {
#ifdef SHADELAB_SOURCE_DIR
    const std::string p = std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/default.json";
    if (std::filesystem::exists(p)) return p;
#endif
    return "";
}

}  // namespace

int viewCommand(int argc, char** argv) {
    std::vector<std::string> valued = {"--size",   "--frames",       "--screenshot",    "--window-screenshot",
                                       "--script", "--probe-report", "--encoding",      "--ui-scale",
                                       "--camera", "--exposure",     "--view-transform"};
    std::vector<std::string> flags = {"-h", "--help", "--stats", "--verbose", "--projector"};
    valued.insert(valued.end(), rasterValuedFlags().begin(), rasterValuedFlags().end());
    flags.insert(flags.end(), rasterSwitchFlags().begin(), rasterSwitchFlags().end());
    const Args args(argc, argv, 2, valued, flags);
    if (args.flag("-h") || args.flag("--help")) {
        std::fputs((std::string(kViewHelpHead) + kRasterFlagsHelp + kViewHelpTail).c_str(), stdout);
        return 0;
    }
    if (args.positionals().size() > 1)
        throw UsageError("view takes at most one scene file, got " + std::to_string(args.positionals().size()));
    app::ViewerOptions options;
    if (auto v = args.value("--size")) {
        std::tie(options.width, options.height) = parseSize(*v);
        const int w = options.width, h = options.height;
        if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
            throw UsageError("--size: each side must be 1.." + std::to_string(kMaxImageSide) + " pixels, got " +
                             std::to_string(w) + "x" + std::to_string(h));
    }
    if (auto v = args.value("--frames")) options.frames = parseInt("--frames", *v, 0, 99999999);
    if (auto v = args.value("--screenshot")) options.screenshot = *v;
    if (auto v = args.value("--window-screenshot")) options.windowScreenshot = *v;
    if (auto v = args.value("--probe-report")) options.probeReport = *v;
    if (auto v = args.value("--ui-scale")) options.uiScale = parseNumber("--ui-scale", *v, 0.5f, 4.0f);
    options.projector = args.flag("--projector");
    options.stats = args.flag("--stats");
    options.verbose = args.flag("--verbose");
    Encoding encoding = Encoding::Srgb;
    if (auto v = args.value("--encoding")) encoding = parseChoice("--encoding", *v, kEncodingNames);
    // The display's fields given on the command line override the scene's, as for `render`.
    std::optional<double> exposure;
    std::optional<ViewTransform> viewTransform;
    if (auto v = args.value("--exposure")) {
        exposure = parseReal("--exposure", *v);
        if (std::optional<std::string> why = exposureProblem(*exposure)) throw UsageError("--exposure: " + *why);
    }
    if (auto v = args.value("--view-transform"))
        viewTransform = parseChoice("--view-transform", *v, kViewTransformNames);
    const RasterOverride raster = parseRasterFlags(args);
    std::optional<CameraChoice> camera;
    if (auto v = args.value("--camera")) camera = parseCameraFlag(*v);

    std::optional<app::Script> script;
    if (auto v = args.value("--script"); v && !v->empty()) script = app::loadScript(*v);

    const std::string path = args.positionals().empty() ? defaultScenePath() : args.positionals()[0];
    // The session's outputs, checked before any work: against the scene file and the script now (even
    // without a display), against every file the scene reads once it has loaded.
    const std::pair<const char*, const std::string&> outputs[] = {{"--screenshot", options.screenshot},
                                                                  {"--window-screenshot", options.windowScreenshot},
                                                                  {"--probe-report", options.probeReport}};
    auto checkOutputs = [&](std::vector<std::string> inputs) {
        if (script) inputs.push_back(script->file);
        for (const auto& [flag, output] : outputs)
            if (!output.empty()) checkOutput(output, flag, inputs);
    };
    checkOutputs({path});

    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland))
        throw std::runtime_error(
            "view needs a display, but neither DISPLAY nor WAYLAND_DISPLAY is set; "
            "use 'shadelab render <scene> -o out.png' for images without one");

    Scene scene;
    WarningCapture warnings;  // shown in the viewer's panel too
    if (!path.empty()) scene = loadScene(path, WarningCapture::warn);
    raster.applyTo(scene.raster);
    if (camera) scene.camera = chooseCamera(scene, *camera, path);
    checkOutputs(scene.inputs.paths());
    app::ViewerState state = app::makeViewerState(std::move(scene), path);
    state.loadWarnings = warnings.lines();
    app::setEncoding(state, encoding);
    DisplaySettings shown = state.scene.display;
    if (exposure) shown.exposure = *exposure;
    if (viewTransform) shown.transform = *viewTransform;
    app::setDisplay(state, shown);
    return app::runViewer(options, std::move(state), std::move(script));
}

}  // namespace shadelab::cli
