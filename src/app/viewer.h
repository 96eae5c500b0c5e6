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
#include "app/panels.h"
#include "app/probe_window_place.h"
#include "app/reference_renderer.h"
#include "app/script.h"
#include "app/undo_history.h"
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

inline constexpr float kViewerPanelWidth = 440.0f;  // side panel, window units at UI scale 1

class Viewer : public PanelServices {
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
    std::optional<Script> script_;
    std::optional<ScriptCursor> cursor_;
    const ScriptAction* waiting_ = nullptr;  // a waitReference action holding the script
    struct SyntheticDrag {
        actions::Drag drag;
        int frame = 0;
    };
    std::optional<SyntheticDrag> drag_;         // a scripted drag in progress
    const ScriptAction* smoothShot_ = nullptr;  // a smoothScreenshot waiting for the smooth frame
    double waitStarted_ = 0.0;

    GLFWwindow* window_ = nullptr;
    bool imguiReady_ = false;
    ImFont* captionFont_ = nullptr;  // larger than the panel's, for a projector
    std::unique_ptr<raster::RasterRenderer> raster_;
    std::unique_ptr<ImageView> imageView_;
    std::unique_ptr<ArrowOverlay> arrows_;
    std::unique_ptr<ReferenceRenderer> reference_;
    std::unique_ptr<GlobalRenderer> global_;  // after reference_: it borrows reference_'s mesh BVH cache
    std::unique_ptr<Accumulation> accumulation_;

    // Layout, in window (logical) units unless named fb*.
    int winW_ = 0, winH_ = 0, fbW_ = 0, fbH_ = 0;
    float fbScale_ = 1.0f, uiScale_ = 1.0f;
    float panelWidth_ = 0.0f;
    bool showPanel_ = true;
    bool overlayPanel_ = false;   // projector mode (key F11): the panel lies over a full-window image
    bool panelOverlays_ = false;  // as laid out this frame (also when the panel is too wide to sit beside)
    float imageX_ = 0, imageY_ = 0, imageW_ = 0, imageH_ = 0;  // where the image is shown
    ImageRect fbRect_;                                         // the same in framebuffer pixels (GL)
    int renderW_ = 0, renderH_ = 0;                            // rendered image size

    // What the raster target holds.
    uint64_t rasterRevision_ = 0, rasterGeometry_ = 0, meshGeometry_ = 0;
    int rasterW_ = 0, rasterH_ = 0;     // the image's full size (a preview is about half of it)
    bool rasterPreview_ = false;        // the target holds the half-size preview of a moving camera
    std::optional<Camera> lastCamera_;  // the camera of the previous frame, for cameraMoved()
    double lastChange_ = 0.0;           // glfwGetTime() of the last change of the image (for --verbose)

    // Probe, recomputed when the state or pixel changes.
    std::optional<ProbeResult> probe_;
    uint64_t probeRevision_ = 0;
    int probeX_ = -1, probeY_ = -1, probeW_ = 0, probeH_ = 0;
    // The probe's ray tree (key T), traced from where the camera was at the click and kept while it orbits,
    // so that the class can walk around it; its rays in words and algebra for the probe window.
    std::optional<RayTreeView> rayTree_;
    RayTreePanel rayTreePanel_;
    glm::vec3 rayTreeAnchor_{0.0f};  // the anchor point it was recorded for: another click records afresh
    // The rendering equation at the probed point, while its section of the probe window is open: computed
    // when the probe or the mode changes and no mouse button is held (a path-traced one takes ~0.1 s).
    std::optional<RenderingEquation> equation_;
    uint64_t equationRevision_ = 0;
    int equationX_ = -1, equationY_ = -1;
    bool equationGlobal_ = false;

    // Difference metrics for a complete reference.
    std::optional<CompareResult> metrics_;
    std::string metricsWords_;  // where they differ, in plain words (compare/difference_sites.h)
    uint64_t metricsRevision_ = 0;
    uint64_t finiteCheckedRevision_ = 0;  // the reference revision whose finished image was checked for NaN

    // Input.
    static constexpr float kMarkerPickRadius = 12.0f;  // window units at UI scale 1
    int draggingLight_ = -1;                           // a light marker being dragged
    bool aimingLight_ = false;                         // ... by a spot's arrow tip: the drag aims it
    bool leftDown_ = false, dragged_ = false, panning_ = false, splitting_ = false;
    float pressX_ = 0, pressY_ = 0;
    std::vector<std::string> drops_;
    struct KeyPress {
        int key = 0, mods = 0;
    };
    std::vector<KeyPress> keys_;  // presses since the last frame

    UiFields fields_;
    std::string shaderError_;
    std::string status_;
    std::string lastProbeWindowLog_;
    bool statusError_ = false;
    double statusTime_ = 0.0;
    std::string pendingWindowShot_;

    int frame_ = 0;
    static constexpr int kSettleFrames = 3;
    static constexpr double kStatusSeconds = 8.0;
    int settleFrames_ = kSettleFrames;
    uint64_t idleRevision_ = 0;
    FrameStats frameStats_, idleStats_, rasterStats_;    // frames with / without a raster redraw
    size_t previewDraws_ = 0;                            // raster draws at half size (camera moving)
    size_t partialDraws_ = 0;                            // raster draws that redrew only some objects
    size_t shadowRenders_ = 0, environmentRenders_ = 0;  // raster draws that re-rendered those (--stats)
    std::array<double, 64> recentMs_{};
    double recentFrameMs() const;
    std::vector<std::string> glInfo_;
};

}  // namespace shadelab::app
