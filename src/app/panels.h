// The Dear ImGui panels. Each draws widgets for part of ViewerState and changes it only through the
// actions in viewer_state.h; what needs the window (open, save, screenshot, reload) goes through
// PanelServices. One file per panel: panels_scene, panels_lighting, panels_material, panels_lights,
// panels_view, panels_raster, panels_probe; panels.cpp lays out the side panel.
#pragma once

#include "app/albedo_plot.h"
#include "app/file_list.h"
#include "app/global_renderer.h"
#include "app/viewer_state.h"
#include "compare/image_compare.h"
#include "probe/probe.h"
#include "probe/rendering_equation.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::app {

class PanelServices {
public:
    virtual ~PanelServices() = default;
    virtual void openScene(const std::string& path) = 0;
    virtual void saveScene(const std::string& path) = 0;
    virtual void screenshot(const std::string& path) = 0;
    // From `dir`, or shaderSourceDir() when empty.
    virtual void reloadShaders(const std::string& dir) = 0;
    virtual void undo() = 0;
    virtual void redo() = 0;
};

// Text fields and UI-only choices that are not part of the scene.
struct UiFields {
    std::string openPath;             // the Open field; the opened file's path after each open
    std::string savePath;             // the Save field; defaultSavePath of the opened file after each open
    std::string confirmReplace;       // an existing file Save waits to replace until the user confirms
    FileList files;                   // the file list's folder, as last read
    std::vector<std::string> recent;  // scenes opened in this session, newest first
    std::string screenshotPath = "shadelab-view.png";
    std::vector<ColorIntensity> lightSplits;  // per light: the colour and intensity as last edited
    bool captions = true;                     // the model, terms and mode written on the image (key C)
    bool lightMarkers = true;                 // a marker per light in the image, draggable
    bool smooth = true;                       // accumulate a supersampled still frame in Raster mode (accumulation.h)
    bool convertAllObjects = false;           // the equivalent-exponent buttons act on every object
    bool lessonFolded = false;                // the lesson window was folded for the probe
    bool probeWindowMoved = false;            // the user dragged the probe window: it stays put until the probe goes
    float probeWindowWidth = 0.0f;            // window units, as last drawn (for placing it inside the image)
    float probeWindowHeight = 0.0f;           // unfolded; its size folded is not what placing it needs
    bool probeWindowHadRoom = true;           // the last placement fitted beside the point (else it folded)
    int rayTreeRay = 0;                       // the ray of the tree whose algebra the probe window writes
    bool equationOpen = false;                // the probe window's rendering-equation section is open
    float lobeIncidence = 30.0f;              // degrees: the lobe plots' angle of incidence when no probe is set
    float lobeAxis = 90.0f;                   // degrees: the Cartesian lobe plot's axis, 0 to this (zoom)
    std::optional<AlbedoPlot> albedo;         // the albedo plot, recomputed when its settings change
};

// Where Save writes by default: "<stem>-saved.json" beside the opened file, so neither a lesson file (whose
// comments a save would drop) nor a .gltf/.glb model is overwritten, and relative mesh paths still resolve.
std::string defaultSavePath(const std::string& scenePath);

// The Whitted reference's progress, for the View panel (Traced, Split and Difference).
struct ReferenceInfo {
    bool active = false, complete = false;
    float progress = 0.0f;  // fraction of the tiles traced, [0, 1]
    double seconds = 0.0;   // since the current request, or its total once complete
    int threads = 0;
    std::string error;
};

// The path tracer's progress, for the View panel (Global and Local | Global).
struct GlobalInfo {
    bool active = false;
    int samples = 0, maxSamples = 0;  // per pixel, in the image shown; it refines until maxSamples
    float passProgress = 0.0f;        // of the sample pass under way
    double noise8 = 0.0;              // mean standard error, 8-bit sRGB units
    double seconds = 0.0;
    int threads = 0;
    std::string error;
    int denoisedSamples = 0;  // of the newest denoised preview; 0: none yet
};

// The probe's ray tree in words (probe/ray_tree_view.h): one line per ray, and each ray's algebra.
struct RayTreePanel {
    std::vector<std::string> rays;
    std::vector<std::vector<std::string>> algebra;
};

struct PanelContext {
    PanelContext(ViewerState& s, PanelServices& sv, UiFields& f) : state(s), services(sv), fields(f) {}
    ViewerState& state;
    PanelServices& services;
    UiFields& fields;
    const ProbeResult* probe = nullptr;           // null when no probe is set
    const RayTreePanel* rayTree = nullptr;        // the probe's ray tree, while it is drawn (ProbeState::rayTree)
    const RenderingEquation* equation = nullptr;  // at the probed point, while its section is open
    ReferenceInfo reference;
    GlobalInfo global;                          // the path tracer of Global and Local | Global
    std::optional<GlobalEstimate> probeGlobal;  // its estimate at the probed pixel, in those modes
    const CompareResult* metrics = nullptr;     // raster vs complete reference, when available
    std::string metricsWords;                   // the same, in plain words
    std::string shaderError;                    // why the last shader reload failed; empty after a good one
    std::string status;                         // the status line's message while it shows, else empty
    bool statusError = false;                   // the message is an error (drawn in red)
    double frameMs = 0.0;                       // median of the last frames
    int renderWidth = 0, renderHeight = 0;      // the rendered image, pixels
    float wipe = 0.5f;                          // the current mode's wipe, as drawn (Viewer::wipeFraction)
    float uiScale = 1.0f;                 // --ui-scale; 2 for --projector; else the monitor's content scale, 1 to 3
    bool compactProbe = false;            // the probe window shows its key rows, the tables a click away
    size_t undoSteps = 0, redoSteps = 0;  // how many steps Undo and Redo can take
};

// The left side panel, filling (0, 0, width, height) of the window.
// `overlay`: it lies over the image (projector mode), so its background is translucent. Beside the image
// Dear ImGui draws no background for it: the viewer clears the panel's rectangle to sidePanelBackground()
// first, the same colour in one clear instead of a blended quad of the panel's size every frame.
void drawSidePanel(PanelContext& ctx, float width, float height, bool overlay);
// The docked panel's background as Dear ImGui would blend it (the style's WindowBg, with its alpha) over
// `under`, the window's clear colour: linear RGB, 0..1.
std::array<float, 3> sidePanelBackground(const std::array<float, 3>& under);
// Sections of the side panel.
void drawSceneSection(PanelContext& ctx);
void drawLightingSection(PanelContext& ctx);
void drawMaterialSection(PanelContext& ctx);
void drawLightsSection(PanelContext& ctx);
void drawViewSection(PanelContext& ctx);
void drawRasterSection(PanelContext& ctx);
void drawHelpSection();
// Floating windows over the image area (x, y, width in window units).
// The lesson (title and notes) sits at the bottom left; it folds to its title bar while a probe is shown.
void drawLessonWindow(PanelContext& ctx, float x, float bottom, float width, bool folded);
// With its top left corner at (x, y) (probe_window_place.h), until the user drags it elsewhere. When the
// placement stops having room beside the point (`room`), the window folds to its title bar, and unfolds when
// it has room again; in between a click on its arrow is the user's to make.
void drawProbeWindow(PanelContext& ctx, float x, float y, bool room);
// The rendering equation at the probed point (panels_equation.cpp), inside the probe window.
void drawRenderingEquation(const RenderingEquation& re, float uiScale);
// The lobe plots of a material (panels_lobe.cpp): its specular lobe under each model against the angle
// between R and V and as a polar plot in the plane of incidence (with the probe's L, V, R), and the
// directional albedo of each model. `phongExponent` is the material's s as a Phong exponent.
void drawLobePlots(PanelContext& ctx, const Material& m, float phongExponent);

}  // namespace shadelab::app
