// The viewer's entry point: runViewer opens the window with a ready state and options. The `shadelab view`
// command line is parsed in cli/view_command.cpp; app/ knows nothing of cli/. See docs/viewer.md.
#pragma once

#include "app/script.h"
#include "app/viewer_state.h"
#include "image/encode.h"

#include <optional>
#include <string>

namespace shadelab::app {

struct ViewerOptions {
    int width = 0, height = 0;     // --size: fixed render size in pixels; 0 = follow the window
    int frames = -1;               // --frames: exit after this many frames; -1 = when closed
    std::string screenshot;        // --screenshot: the rendered image at exit (no UI)
    std::string windowScreenshot;  // --window-screenshot: the whole window at exit, UI included
    std::string probeReport;       // --probe-report: the probe's JSON at exit
    bool stats = false;            // --stats: redraw every other frame, print median and p95 frame times
    bool verbose = false;          // --verbose: GL_RENDERER, GL_VERSION, scene and shader sources
    float uiScale = 0.0f;          // --ui-scale: 0 = the monitor's content scale
    bool projector = false;        // --projector: UI scale 2 unless given, the panel over the image
};

// Opens the window and runs until it closes or the frames and script are done. Returns the exit code.
// Throws InputError for bad input (scene, script actions) and std::runtime_error for window/GL failures.
int runViewer(const ViewerOptions& options, ViewerState state, std::optional<Script> script);

// The folder hot reload reads shaders from: $SHADELAB_SHADER_DIR, else the source tree's shaders/.
std::string shaderSourceDir();

}  // namespace shadelab::app
