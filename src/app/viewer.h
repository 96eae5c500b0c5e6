// Viewer: the GLFW window, Dear ImGui, the rasterizer and the reference, driven by ViewerState. This
// header is the window's private interface shared by viewer*.cpp; callers use runViewer() in app.h.
//   viewer_setup.cpp    window, GL and ImGui setup and teardown
//   viewer.cpp          the frame loop, layout and composition
//   viewer_input.cpp    mouse, keys, drag and drop
//   viewer_actions.cpp  script actions, captures (screenshots, probe report), open/save, shader reload
//   viewer_probe.cpp    the probe, its ray tree and the rendering equation, updated each frame
//   viewer_overlays.cpp what is drawn over the image: arrow labels, the ray tree, light markers, captions, toast
#pragma once

#include "app/accumulation.h"
#include "app/app.h"
#include "app/arrow_overlay.h"
#include "app/frame_stats.h"
#include "app/global_renderer.h"
#include "app/image_view.h"
#include "app/panel_cache.h"
#include "app/panels.h"
#include "app/probe_window_place.h"
#include "app/reference_renderer.h"
#include "app/script.h"
#include "app/script_player.h"
#include "app/undo_history.h"
#include "app/viewer_layout.h"
#include "app/viewer_state.h"
#include "compare/image_compare.h"
#include "probe/ray_tree_view.h"
#include "probe/rendering_equation.h"
#include "raster/raster_renderer.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;
struct ImFont;
struct ImVec2;

namespace shadelab::app {

class Viewer : public PanelServices, public ScriptWindow {
public:
    Viewer(const ViewerOptions& options, ViewerState state, std::optional<Script> script);
    ~Viewer() override;
    int run();

    // PanelServices
    void openScene(const std::string& path) override;
    void saveScene(const std::string& path) override;
    void screenshot(const std::string& path) override;
    void reloadShaders(const std::string& dir) override;
    void undo() override;
    void redo() override;
    void queueDrop(const std::string& path);  // from GLFW's drop callback
    void queueKey(int key, int mods);         // from GLFW's key callback: presses only

    // ScriptWindow (viewer_actions.cpp)
    void perform(const ScriptAction& action) override { performAction(action); }
    bool referenceComplete() override;
    bool writeSmoothFrame(const std::string& path) override;
    double seconds() override;

private:
    // viewer_setup.cpp
    void initWindow();
    void initImGui();
    void shutdown();
    // viewer.cpp
    bool frame();
    void waitForWork();
    void computeLayout();
    // True when it drew; the target then holds the centre sample. `preview`: the camera is moving and the
    // scene's raster.movingPreview is on, so a half-size image will do (a full-size one is never redrawn for
    // it); without it a preview image counts as stale and the full one is drawn.
    bool ensureRasterCurrent(bool force, bool preview = false);
    bool cameraMoved();  // whether the scene's camera changed since the last call (once per frame)
    bool accumulate();   // two more jittered samples while still; true when it drew
    void updateReference();
    // Whether the Global modes show the path tracer's denoised preview now (asked for, and one has arrived).
    bool showsDenoised() const;
    void updateProbe();
    void updateRayTree(const trace::TraceScene& traced, bool clicked);
    void drawRayTree();
    void updateEquation();
    void drawArrowLabels(const std::vector<ArrowLabel>& labels);
    void compose();
    void drawCaptions();
    // The status message (saved, refused, an error) over the bottom of the visible image while it is fresh.
    void drawToast();
    void logProbeWindow(const ProbeWindowSpace& space, const ProbeWindowPlace& place, glm::vec2 size);
    void drawLightMarkers();
    ImVec2 windowPoint(glm::vec2 imagePixel) const;
    glm::vec2 imagePixelF(float windowX, float windowY) const;
    float markerPickRadius() const;
    float visibleLeft() const;
    // The current mode's wipe as a fraction of the image width: as set, else the middle of the visible image.
    float wipeFraction() const;
    bool finished() const;
    // viewer_input.cpp
    void handleMouse();
    void handleKeys();
    void handleDrops();
    glm::ivec2 imagePixelAt(float windowX, float windowY) const;
    void clickAt(float windowX, float windowY);
    // viewer_actions.cpp
    void runScript();
    void feedSyntheticMouse();
    void performAction(const ScriptAction& action);
    Image8 captureRaster();
    // A float image in the state's encoding; a pixel with no finite value is reported (warnNonFinite).
    Image8 toPixels(const ImageF& image, const char* what);
    // Prints and shows (status line, as an error) how many pixels of `image` had no finite value, if any.
    void warnNonFinite(const char* what, uint64_t nonFinite, const Image8& image);
    uint32_t coverageAt(int x, int y);
    void writeProbeReport(const std::string& path);
    void writeWindowScreenshot(const std::string& path);
    void updateMetrics();
    void setStatus(const std::string& message, bool error);

    ViewerOptions options_;
    ViewerState state_;
    UndoHistory history_;
    std::optional<ScriptPlayer> player_;  // --script

    struct Window {
        GLFWwindow* handle = nullptr;
        bool imguiReady = false;
        ImFont* captionFont = nullptr;  // larger than the panel's, for a projector
    } window_;
    std::unique_ptr<raster::RasterRenderer> raster_;
    std::unique_ptr<ImageView> imageView_;
    std::unique_ptr<ArrowOverlay> arrows_;
    std::unique_ptr<ReferenceRenderer> reference_;
    std::unique_ptr<GlobalRenderer> global_;  // after reference_: it borrows reference_'s mesh BVH cache
    std::unique_ptr<Accumulation> accumulation_;
    std::unique_ptr<PanelCache> panelCache_;

    // Layout, in window (logical) units unless named fb*.
    LayoutInput shape_;    // the window, the UI scale, the panel's switches and --size
    ViewerLayout layout_;  // laid out from shape_ each frame

    // What the raster target holds.
    struct RasterShown {
        uint64_t revision = 0, geometry = 0, meshGeometry = 0;
        int width = 0, height = 0;         // the image's full size (a preview is about half of it)
        bool preview = false;              // the target holds the half-size preview of a moving camera
        std::optional<Camera> lastCamera;  // the camera of the previous frame, for cameraMoved()
        double lastChange = 0.0;           // glfwGetTime() of the last change of the image (for --verbose)
    } shown_;

    // The probe, recomputed when the state or pixel changes.
    struct ProbeCache {
        std::optional<ProbeResult> result;
        uint64_t revision = 0;
        int x = -1, y = -1, width = 0, height = 0;
    } probe_;
    // The probe's ray tree (key T), traced from where the camera was at the click and kept while it orbits,
    // so that the class can walk around it; its rays in words and algebra for the probe window.
    struct RayTreeCache {
        std::optional<RayTreeView> view;
        RayTreePanel panel;
        glm::vec3 anchor{0.0f};  // the anchor point it was recorded for: another click records afresh
    } rayTree_;
    // The rendering equation at the probed point, while its section of the probe window is open: computed
    // when the probe or the mode changes and no mouse button is held (a path-traced one takes ~0.1 s).
    struct EquationCache {
        std::optional<RenderingEquation> result;
        uint64_t revision = 0;
        int x = -1, y = -1;
        bool global = false;
    } equation_;
    // Difference metrics for a complete reference.
    struct MetricsCache {
        std::optional<CompareResult> result;
        std::string words;  // where they differ, in plain words (compare/difference_sites.h)
        uint64_t revision = 0;
        uint64_t finiteChecked = 0;  // the reference revision whose finished image was checked for NaN
    } metrics_;

    // Input.
    static constexpr float kMarkerPickRadius = 12.0f;  // window units at UI scale 1
    struct Pointer {
        int light = -1;       // a light marker being dragged
        bool aiming = false;  // ... by a spot's arrow tip: the drag aims it
        bool leftDown = false, dragged = false, panning = false, splitting = false;
        float pressX = 0, pressY = 0;
    } pointer_;
    struct KeyPress {
        int key = 0, mods = 0;
    };
    struct Queued {  // from GLFW's callbacks, handled at the next frame
        std::vector<std::string> drops;
        std::vector<KeyPress> keys;  // presses since the last frame
    } queued_;

    UiFields fields_;
    std::string shaderError_;
    struct Status {  // the status line: saved, refused, an error
        std::string message;
        bool error = false;
        double time = 0.0;  // glfwGetTime() when it was set
    } status_;
    std::string lastProbeWindowLog_;
    std::string pendingWindowShot_;

    int frame_ = 0;
    static constexpr int kSettleFrames = 3;
    static constexpr double kStatusSeconds = 8.0;
    struct Idle {  // waitForWork's: the state revision last drawn, and frames to run before sleeping
        uint64_t revision = 0;
        int settleFrames = kSettleFrames;
    } idle_;
    struct Stats {                                         // for --stats and the panel's frame time
        FrameStats frames, idle, raster;                   // all frames, those without a raster redraw, with
        size_t previewDraws = 0;                           // raster draws at half size (camera moving)
        size_t partialDraws = 0;                           // raster draws that redrew only some objects
        size_t shadowRenders = 0, environmentRenders = 0;  // raster draws that re-rendered those
        std::array<double, 64> recentMs{};
        // The panel's frame time, held for half a second: a figure that changed every frame would be unreadable,
        // and would make every frame's panel differ from the last (PanelCache).
        double shownMs = 0.0, shownAt = -1.0;
    } stats_;
    double recentFrameMs() const;
};

}  // namespace shadelab::app
