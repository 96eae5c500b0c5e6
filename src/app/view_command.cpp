// `shadelab view`: command-line parsing for the viewer, the display check, and loading the scene and
// script before the window opens (so bad input fails fast with exit code 1, usage errors with 2).
#include "app/app.h"

#include "cli/args.h"
#include "cli/raster_flags.h"
#include "scene/scene_load.h"
#include "util/input_error.h"
#include "util/warning.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <tuple>

namespace shadelab::app {
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
    "  --stats                    redraw the image every other frame; print median and 95th-percentile\n"
    "                             frame times with and without a redraw\n"
    "  --ui-scale F               UI scale, 0.5..4 (default: the monitor's content scale)\n";

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

std::string shaderSourceDir() {
    if (const char* env = std::getenv("SHADELAB_SHADER_DIR"); env && *env) return env;
#ifdef SHADELAB_SOURCE_DIR
    return std::string(SHADELAB_SOURCE_DIR) + "/shaders";
#else
    return "shaders";
#endif
}

int viewCommand(int argc, char** argv) {
    ViewerOptions options;
    std::vector<std::string> positionals;
    std::string scriptPath, encoding;
    RasterOverride raster;
    std::vector<std::string> valued = {"--size", "--frames", "--screenshot", "--window-screenshot",
                                       "--script", "--probe-report", "--encoding", "--ui-scale"};
    valued.insert(valued.end(), cli::rasterValuedFlags().begin(), cli::rasterValuedFlags().end());
    const std::vector<std::string>& switches = cli::rasterSwitchFlags();
    bool help = false;
    for (int i = 2; i < argc; ++i) {
        std::string a = argv[i], value;
        if (a == "-h" || a == "--help") {
            help = true;
            continue;
        }
        if (a.size() < 2 || a[0] != '-') {
            positionals.push_back(a);
            continue;
        }
        if (a == "--stats" || a == "--verbose") {
            (a == "--stats" ? options.stats : options.verbose) = true;
            continue;
        }
        if (std::find(switches.begin(), switches.end(), a) != switches.end()) {
            cli::parseRasterFlag(a, "", raster);
            continue;
        }
        const size_t eq = a.find('=');
        const std::string name = a.substr(0, eq);
        if (std::find(valued.begin(), valued.end(), name) == valued.end())
            throw UsageError("unknown option '" + a + "' (see shadelab view --help)");
        if (eq != std::string::npos) value = a.substr(eq + 1);
        else if (i + 1 < argc) value = argv[++i];
        else throw UsageError(name + " needs a value");
        if (name == "--size") std::tie(options.width, options.height) = cli::parseSize(value);
        else if (name == "--frames") options.frames = cli::parseInt(name, value, 0, 99999999);
        else if (name == "--screenshot") options.screenshot = value;
        else if (name == "--window-screenshot") options.windowScreenshot = value;
        else if (name == "--script") scriptPath = value;
        else if (name == "--probe-report") options.probeReport = value;
        else if (name == "--encoding") encoding = value;
        else if (name == "--ui-scale") options.uiScale = cli::parseNumber(name, value, 0.5f, 4.0f);
        else cli::parseRasterFlag(name, value, raster);
    }
    if (help) {
        std::fputs((std::string(kViewHelpHead) + cli::kRasterFlagsHelp + kViewHelpTail).c_str(), stdout);
        return 0;
    }
    if (positionals.size() > 1)
        throw UsageError("view takes at most one scene file, got " + std::to_string(positionals.size()));
    Encoding enc = Encoding::Srgb;
    if (!encoding.empty()) enc = cli::parseChoice("--encoding", encoding, kEncodingNames);

    std::optional<Script> script;
    if (!scriptPath.empty()) script = loadScript(scriptPath);

    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland))
        throw std::runtime_error("view needs a display, but neither DISPLAY nor WAYLAND_DISPLAY is set; "
                                 "use 'shadelab render <scene> -o out.png' for images without one");

    const std::string path = positionals.empty() ? defaultScenePath() : positionals[0];
    Scene scene;
    if (!path.empty()) scene = loadScene(path, printWarning);
    raster.applyTo(scene.raster);
    ViewerState state = makeViewerState(std::move(scene), path);
    setEncoding(state, enc);
    return runViewer(options, std::move(state), std::move(script));
}

}  // namespace shadelab::app
