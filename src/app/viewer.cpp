// Viewer: the frame loop (events → script → UI → raster → compose → swap), the layout of the side panel
// and the image area, and --stats. Setup and teardown are in viewer_setup.cpp.
#include "app/viewer.h"

#include "compare/comparison.h"
#include "image/png.h"
#include "raster/raster_limits.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace shadelab::app {

int Viewer::run() {
    while (frame()) {}
    if (!options_.screenshot.empty()) writePng(options_.screenshot, captureRaster());
    if (!options_.probeReport.empty()) writeProbeReport(options_.probeReport);
    if (options_.stats) {
        std::printf("shadelab: view stats: %zu frames, image %dx%d in a %dx%d window (framebuffer %dx%d)\n",
                    frameStats_.count() + idleStats_.count(), renderW_, renderH_, winW_, winH_, fbW_, fbH_);
        std::printf("shadelab:   frame, raster redrawn  median %6.2f ms   p95 %6.2f ms   (%zu frames)\n",
                    frameStats_.median(), frameStats_.percentile(95.0), frameStats_.count());
        std::printf("shadelab:   raster draw alone      median %6.2f ms   p95 %6.2f ms   (draw + glFinish)\n",
                    rasterStats_.median(), rasterStats_.percentile(95.0));
        std::printf(
            "shadelab:   partial redraws        %zu of %zu (a material edit: only its objects); shadow maps "
            "re-rendered in %zu, environment cubes in %zu\n",
            partialDraws_, rasterStats_.count(), shadowRenders_, environmentRenders_);
        std::printf("shadelab:   half-size previews     %zu of %zu (the camera moving, raster.movingPreview %s)\n",
                    previewDraws_, rasterStats_.count(), state_.scene.raster.movingPreview ? "on" : "off");
        if (idleStats_.count())
            std::printf("shadelab:   frame, nothing changed median %6.2f ms   p95 %6.2f ms   (%zu frames)\n",
                        idleStats_.median(), idleStats_.percentile(95.0), idleStats_.count());
        if (reference_->active())
            std::printf("shadelab:   reference    %.0f%% of tiles in %.1f s on %d thread(s)%s\n",
                        100.0 * reference_->progress(), reference_->seconds(), reference_->threads(),
                        reference_->complete() ? ", complete" : ", still running");
    }
    return 0;
}

bool Viewer::finished() const {
    if (options_.frames < 0 || frame_ < options_.frames) return false;
    return !cursor_ || (cursor_->done() && !waiting_ && !drag_ && !smoothShot_);
}

// An idle viewer uses no CPU (docs/viewer.md, "Idle"): when nothing is animating it sleeps in glfwWaitEvents until
// input, a drop or a resize arrives, or until the next thing it must show (a status message expiring, a reference
// tile). A few frames after any input let ImGui settle its hover and focus state before sleeping again.
void Viewer::waitForWork() {
    const bool scripted =
        options_.frames >= 0 || options_.stats || drag_ || smoothShot_ || (cursor_ && (!cursor_->done() || waiting_));
    const bool changed = state_.revision != idleRevision_ ||
                         (fields_.smooth && state_.mode == ViewMode::Raster && !accumulation_->converged());
    idleRevision_ = state_.revision;
    if (scripted || changed || settleFrames_ > 0) {
        if (settleFrames_ > 0) --settleFrames_;
        if (changed) settleFrames_ = kSettleFrames;
        glfwPollEvents();
        return;
    }
    double timeout = 1e9;  // glfwWaitEventsTimeout needs a finite number
    if (reference_->active() && !reference_->complete()) timeout = 1.0 / 30.0;  // show tiles as they finish
    if (global_->active() && global_->samples() < GlobalRenderer::kMaxSamples) timeout = 0.1;  // and sample passes
    const double statusLeft = statusTime_ + kStatusSeconds - glfwGetTime();
    if (statusLeft > 0.0) timeout = std::min(timeout, statusLeft + 0.01);
    const double before = glfwGetTime();
    glfwWaitEventsTimeout(timeout);
    if (glfwGetTime() - before < timeout) settleFrames_ = kSettleFrames;  // woken by an event
}

bool Viewer::frame() {
    waitForWork();
    const double t0 = glfwGetTime();
    if (glfwWindowShouldClose(window_)) return false;
    handleDrops();
    glfwGetFramebufferSize(window_, &fbW_, &fbH_);
    glfwGetWindowSize(window_, &winW_, &winH_);
    if (fbW_ <= 0 || fbH_ <= 0 || winW_ <= 0 || winH_ <= 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED)) {
        glfwWaitEventsTimeout(0.1);  // minimised: no GL work at all until the window has a size again
        return true;
    }
    computeLayout();
    runScript();

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    feedSyntheticMouse();
    ImGui::NewFrame();
    handleKeys();
    handleMouse();
    updateReference();
    updateMetrics();
    updateProbe();
    updateEquation();

    PanelContext ctx(state_, *this, fields_);
    ctx.probe = probe_ ? &*probe_ : nullptr;
    ctx.rayTree = rayTree_ ? &rayTreePanel_ : nullptr;
    ctx.equation = equation_ ? &*equation_ : nullptr;
    ctx.reference = {reference_->active(),  reference_->complete(), reference_->progress(),
                     reference_->seconds(), reference_->threads(),  reference_->error()};
    ctx.global = {global_->active(), global_->samples(), GlobalRenderer::kMaxSamples, global_->passProgress(),
                  global_->noise8(), global_->seconds(), global_->threads(),          global_->error()};
    ctx.global.denoisedSamples = global_->denoisedSamples();
    if (probe_ && isGlobal(state_.mode)) ctx.probeGlobal = global_->estimate(probe_->x, probe_->y);
    ctx.metrics = metrics_ && metricsRevision_ == state_.revision ? &*metrics_ : nullptr;
    if (ctx.metrics) ctx.metricsWords = metricsWords_;
    ctx.shaderError = shaderError_;
    if (glfwGetTime() - statusTime_ < kStatusSeconds) {
        ctx.status = status_;
        ctx.statusError = statusError_;
    }
    ctx.frameMs = recentFrameMs();
    ctx.renderWidth = renderW_;
    ctx.renderHeight = renderH_;
    ctx.uiScale = uiScale_;
    // Compact on a projector, with the ray tree on (its rays need the room), and wherever the whole window
    // (about 720 units tall) would not fit the image.
    ctx.compactProbe = uiScale_ >= 1.5f || state_.probe.rayTree || imageH_ < 760.0f * uiScale_;
    ctx.wipe = wipeFraction();
    ctx.undoSteps = history_.undoSteps();
    ctx.redoSteps = history_.redoSteps();
    if (showPanel_) drawSidePanel(ctx, panelWidth_, float(winH_), panelOverlays_);
    const float margin = 10.0f * uiScale_;
    const float left = visibleLeft(), visibleW = imageX_ + imageW_ - left;
    drawLessonWindow(ctx, left + margin, imageY_ + imageH_ - margin,
                     std::min(visibleW - 2.0f * margin, 760.0f * uiScale_), ctx.probe != nullptr);
    if (!ctx.probe) fields_.probeWindowMoved = false;
    if (ctx.probe) {
        // Beside the probed point inside the visible image, clear of the point and its arrows, at the size
        // it was drawn last frame.
        ProbeWindowSpace space;
        space.visibleMin = glm::vec2(left + margin, imageY_ + margin);
        space.visibleMax = glm::vec2(imageX_ + imageW_ - margin, imageY_ + imageH_ - margin);
        space.point = glm::vec2(imageX_ + (float(state_.probe.x) + 0.5f) / float(renderW_) * imageW_,
                                imageY_ + (float(state_.probe.y) + 0.5f) / float(renderH_) * imageH_);
        space.clearance = 0.22f * imageH_ + 20.0f * uiScale_;  // the arrows (arrow_overlay.h): ~0.2 of the height
        space.minClearance = 20.0f * uiScale_;
        const glm::vec2 size(fields_.probeWindowWidth, fields_.probeWindowHeight);
        const ProbeWindowPlace place = placeProbeWindow(space, size);
        drawProbeWindow(ctx, place.topLeft.x, place.topLeft.y, place.fits || fields_.probeWindowMoved);
        if (options_.verbose && !fields_.probeWindowMoved) logProbeWindow(space, place, size);
    }

    // Edits become undo steps between gestures, so a slider drag or a mouse drag is one step.
    if (!ImGui::IsAnyItemActive() && !leftDown_ && !panning_ && draggingLight_ < 0) history_.commit(state_);

    // --stats forces a raster redraw on every other frame, so it measures both the frame a change costs
    // (the honest figure) and the frame that only redraws the window.
    const bool forced = options_.stats && frame_ % 2 == 0;
    const bool moving = cameraMoved();
    const bool redrawn = ensureRasterCurrent(forced, moving && state_.scene.raster.movingPreview);
    if (!redrawn) accumulate();
    compose();
    ++frame_;
    const bool last = finished();
    if (last && !options_.windowScreenshot.empty()) pendingWindowShot_ = options_.windowScreenshot;
    if (!pendingWindowShot_.empty()) {
        writeWindowScreenshot(pendingWindowShot_);
        pendingWindowShot_.clear();
    }
    glfwSwapBuffers(window_);
    const double ms = (glfwGetTime() - t0) * 1000.0;
    if (options_.stats) (redrawn ? frameStats_ : idleStats_).add(ms);
    recentMs_[size_t(frame_) % recentMs_.size()] = ms;
    return !last;
}

// Median of the last frames, for the panel's header (FrameStats keeps every frame for --stats).
double Viewer::recentFrameMs() const {
    const size_t n = std::min(size_t(frame_), recentMs_.size());
    if (n == 0) return 0.0;
    std::array<double, 64> v{};
    std::copy_n(recentMs_.begin(), n, v.begin());
    std::nth_element(v.begin(), v.begin() + long(n / 2), v.begin() + long(n));
    return v[n / 2];
}

void Viewer::computeLayout() {
    fbScale_ = float(fbW_) / float(winW_);
    panelWidth_ = showPanel_ ? std::min(kViewerPanelWidth * uiScale_, 0.5f * float(winW_)) : 0.0f;
    // At a large UI scale a panel beside the image would squeeze it into a portrait: then it lies over the
    // image instead, and the image keeps the window's shape (projector mode).
    const bool overlay = overlayPanel_ || (uiScale_ >= 1.5f && panelWidth_ > 0.34f * float(winW_));
    panelOverlays_ = overlay && showPanel_;
    const int areaX = overlay ? 0 : int(std::lround(panelWidth_ * fbScale_));
    const int areaW = std::max(1, fbW_ - areaX), areaH = std::max(1, fbH_);
    if (options_.width > 0) {
        renderW_ = options_.width;
        renderH_ = options_.height;
    } else {
        renderW_ = areaW;
        renderH_ = areaH;
    }
    // A fixed size shows 1:1 when it fits, else scaled down to fit, centred.
    const float scale = std::min({1.0f, float(areaW) / float(renderW_), float(areaH) / float(renderH_)});
    fbRect_.width = std::max(1, int(std::lround(float(renderW_) * scale)));
    fbRect_.height = std::max(1, int(std::lround(float(renderH_) * scale)));
    fbRect_.x = areaX + (areaW - fbRect_.width) / 2;
    fbRect_.y = (areaH - fbRect_.height) / 2;
    imageX_ = float(fbRect_.x) / fbScale_;
    imageY_ = float(fbH_ - fbRect_.y - fbRect_.height) / fbScale_;
    imageW_ = float(fbRect_.width) / fbScale_;
    imageH_ = float(fbRect_.height) / fbScale_;
}

bool Viewer::cameraMoved() {
    const Camera& c = state_.scene.camera;
    const bool moved = lastCamera_ && (c.position != lastCamera_->position || c.target != lastCamera_->target ||
                                       c.up != lastCamera_->up || c.fovY != lastCamera_->fovY);
    lastCamera_ = c;
    return moved;
}

bool Viewer::ensureRasterCurrent(bool force, bool preview) {
    if (renderW_ <= 0 || renderH_ <= 0) return false;
    if (meshGeometry_ != state_.geometryRevision) {
        raster_->uploadMeshes(state_.scene);
        meshGeometry_ = state_.geometryRevision;
        rasterRevision_ = 0;
    }
    const bool changed = rasterRevision_ != state_.revision || rasterW_ != renderW_ || rasterH_ != renderH_ ||
                         (rasterPreview_ && !preview);
    if (!force && !changed) return false;
    if (changed) lastChange_ = glfwGetTime();
    // A forced redraw of an unchanged image (--stats) is a full one: what any change but a material edit costs.
    if (!changed) raster_->invalidate();
    const double t0 = glfwGetTime();
    try {
        if (preview) {
            // Half the width and height, a quarter of the pixels; the display pass scales it up. The shadow
            // maps keep the full image's size ("auto" depends on it), so they are neither re-rendered nor
            // coarser than in the full frame that follows.
            Scene scene = state_.scene;
            scene.raster.shadowMapSize = raster::shadowMapSizeFor(scene.raster, renderW_, renderH_);
            raster_->draw(scene, std::max(1, (renderW_ + 1) / 2), std::max(1, (renderH_ + 1) / 2), true);
        } else {
            raster_->draw(state_.scene, renderW_, renderH_, true);
        }
    } catch (const std::runtime_error& e) {
        // A shadow-map size too large for memory (raster_limits.h budget): say so and fall back to auto.
        if (state_.scene.raster.shadowMapSize == 0) throw;
        setStatus(std::string(e.what()) + "; using auto", true);
        state_.scene.raster.shadowMapSize = 0;
        markRasterChanged(state_);
        return ensureRasterCurrent(force, preview);
    }
    if (options_.stats) glFinish();  // so the figure is the draw, not just its submission
    if (options_.stats) rasterStats_.add((glfwGetTime() - t0) * 1000.0);
    const raster::RasterRenderer::DrawReport& report = raster_->lastDraw();
    partialDraws_ += report.partial ? 1 : 0;
    previewDraws_ += preview ? 1 : 0;
    shadowRenders_ += report.shadowMaps ? 1 : 0;
    environmentRenders_ += report.environments ? 1 : 0;
    rasterRevision_ = state_.revision;
    rasterW_ = renderW_;
    rasterH_ = renderH_;
    rasterPreview_ = preview;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return true;
}

// The smooth still frame (accumulation.h): in Raster mode, once nothing changes and no gesture is under
// way, two jittered samples per frame until the k×k grid is complete. Split and Difference keep the centre
// sample, so raster and reference are compared sample for sample.
bool Viewer::accumulate() {
    if (!fields_.smooth || state_.mode != ViewMode::Raster || options_.stats) return false;
    if (leftDown_ || panning_ || draggingLight_ >= 0 || ImGui::IsAnyItemActive()) return false;
    accumulation_->restart(state_.revision, renderW_, renderH_);
    if (accumulation_->converged()) return false;
    for (int i = 0; i < 2; ++i) {
        // Into the renderer's sample target: its centre image and coverage stay as they are.
        const raster::RenderTarget& sample =
            raster_->drawSample(state_.scene, renderW_, renderH_, accumulation_->nextJitter());
        accumulation_->add(sample.colorTexture());
    }
    if (accumulation_->converged() && options_.verbose)
        std::fprintf(stderr, "shadelab: smooth frame, %d samples, %.0f ms after the last change\n",
                     accumulation_->samples(), (glfwGetTime() - lastChange_) * 1000.0);
    return true;
}

bool Viewer::showsDenoised() const { return state_.globalDenoise && global_->denoisedSamples() > 0; }

void Viewer::updateReference() {
    if (isGlobal(state_.mode)) {
        reference_->pause();
        global_->request(state_.scene, renderW_, renderH_, state_.referenceRevision, state_.globalPart);
        global_->update();
        return;
    }
    global_->pause();
    if (state_.mode == ViewMode::Raster && !waiting_) {
        reference_->pause();
        return;
    }
    // Split and Difference compare with the rasterizer: the reference traces at the comparison's depth
    // (compare/comparison.h); Traced shows it at the scene's own depth.
    const bool comparing = state_.mode == ViewMode::Split || state_.mode == ViewMode::Difference;
    reference_->request(state_.scene, renderW_, renderH_, state_.referenceRevision,
                        comparing ? comparisonDepth(state_.scene) : -1);
    reference_->update();
    // Once per finished reference: pixels with no finite value are said on the status line (no silent black).
    if (reference_->complete() && reference_->revision() == state_.referenceRevision &&
        finiteCheckedRevision_ != state_.referenceRevision) {
        finiteCheckedRevision_ = state_.referenceRevision;
        toPixels(reference_->image(), "traced image");
    }
}

void Viewer::compose() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fbW_, fbH_);
    // The image pass covers its rectangle; clear only what it leaves (a whole-window clear costs ~1 ms).
    const bool letterboxed = fbRect_.y > 0 || fbRect_.height < fbH_ || fbRect_.x + fbRect_.width < fbW_;
    glClearColor(0.09f, 0.09f, 0.10f, 1.0f);
    if (letterboxed) {
        glDisable(GL_SCISSOR_TEST);
        glClear(GL_COLOR_BUFFER_BIT);
    } else if (fbRect_.x > 0) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, fbRect_.x, fbH_);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
    }
    ImageViewInputs in;
    // The smooth frame once it has a centred average for this very image, else the centre sample.
    const bool smooth = state_.mode == ViewMode::Raster && fields_.smooth && accumulation_->samples() >= 2 &&
                        !accumulation_->restart(state_.revision, renderW_, renderH_);
    in.raster = smooth ? accumulation_->texture() : raster_->target().colorTexture();
    in.imageWidth = raster_->target().width();
    in.imageHeight = raster_->target().height();
    if (isGlobal(state_.mode) && global_->active()) {
        // The path tracer's image in the traced slot: Global shows it whole, Local | Global as the wipe's right.
        in.traced = showsDenoised() ? global_->denoisedTexture() : global_->texture();
        in.tiles = global_->tileTexture();
        in.tileSize = global_->tileSize();
    } else if (reference_->active()) {
        in.traced = reference_->texture();
        in.tiles = reference_->tileTexture();
        in.tileSize = reference_->tileSize();
    }
    in.mode = state_.mode == ViewMode::Global        ? ViewMode::Traced
              : state_.mode == ViewMode::LocalGlobal ? ViewMode::Split
                                                     : state_.mode;
    in.encoding = state_.encoding;
    in.display = state_.scene.display;
    in.split = wipeFraction();
    in.gain = float(state_.heatGain);
    in.coverage = raster_->target().coverageTexture();
    in.selected = state_.selected;
    imageView_->draw(fbRect_, in);
    if (fields_.captions) drawCaptions();
    drawToast();
    if (fields_.lightMarkers) drawLightMarkers();  // over the captions: a light off the frame sits at its edge
    if (probe_ && probe_->hit) {
        if (rayTree_) drawRayTree();
        drawArrowLabels(arrows_->draw(state_.scene, *probe_, renderW_, renderH_, fbRect_, fbH_, fbScale_ * uiScale_));
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    gl::checkError("viewer frame");
}

// The left edge of the part of the image the panel does not cover, window units.
float Viewer::visibleLeft() const { return panelOverlays_ ? std::max(imageX_, panelWidth_) : imageX_; }

float Viewer::wipeFraction() const {
    const float centre = 0.5f * (visibleLeft() + imageX_ + imageW_);
    return wipePosition(state_, imageW_ > 0.0f ? (centre - imageX_) / imageW_ : 0.5f);
}

}  // namespace shadelab::app
