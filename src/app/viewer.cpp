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
                    stats_.frames.count() + stats_.idle.count(), layout_.renderWidth, layout_.renderHeight,
                    shape_.windowWidth, shape_.windowHeight, shape_.fbWidth, shape_.fbHeight);
        std::printf("shadelab:   frame, raster redrawn  median %6.2f ms   p95 %6.2f ms   (%zu frames)\n",
                    stats_.frames.median(), stats_.frames.percentile(95.0), stats_.frames.count());
        std::printf("shadelab:   raster draw alone      median %6.2f ms   p95 %6.2f ms   (draw + glFinish)\n",
                    stats_.raster.median(), stats_.raster.percentile(95.0));
        std::printf(
            "shadelab:   partial redraws        %zu of %zu (a material edit: only its objects); shadow maps "
            "re-rendered in %zu, environment cubes in %zu\n",
            stats_.partialDraws, stats_.raster.count(), stats_.shadowRenders, stats_.environmentRenders);
        std::printf("shadelab:   half-size previews     %zu of %zu (the camera moving, raster.movingPreview %s)\n",
                    stats_.previewDraws, stats_.raster.count(), state_.scene.raster.movingPreview ? "on" : "off");
        const PanelCache::Counts& panel = panelCache_->counts();
        std::printf(
            "shadelab:   side panel             drawn in %zu frames, its kept pixels copied in %zu, drawn with "
            "the rest in %zu\n",
            panel.misses, panel.hits, panel.whole);
        if (panelCache_->mode() == PanelCache::Mode::Verify || panelCache_->mode() == PanelCache::Mode::VerifyStale)
            std::printf("shadelab:   side panel verified    %zu frames compared, %zu differing\n", panel.verified,
                        panel.differing);
        if (stats_.idle.count())
            std::printf("shadelab:   frame, nothing changed median %6.2f ms   p95 %6.2f ms   (%zu frames)\n",
                        stats_.idle.median(), stats_.idle.percentile(95.0), stats_.idle.count());
        if (reference_->active())
            std::printf("shadelab:   reference    %.0f%% of tiles in %.1f s on %d thread(s)%s\n",
                        100.0 * reference_->progress(), reference_->seconds(), reference_->threads(),
                        reference_->complete() ? ", complete" : ", still running");
    }
    return 0;
}

bool Viewer::finished() const {
    if (options_.frames < 0 || frame_ < options_.frames) return false;
    return !player_ || player_->finished();
}

// An idle viewer uses no CPU (docs/viewer.md, "Idle"): when nothing is animating it sleeps in glfwWaitEvents until
// input, a drop or a resize arrives, or until the next thing it must show (a status message expiring, a reference
// tile). A few frames after any input let ImGui settle its hover and focus state before sleeping again.
void Viewer::waitForWork() {
    const bool scripted = options_.frames >= 0 || options_.stats || (player_ && !player_->finished());
    const bool changed = state_.revision != idle_.revision ||
                         (fields_.smooth && state_.mode == ViewMode::Raster && !accumulation_->converged());
    idle_.revision = state_.revision;
    if (scripted || changed || idle_.settleFrames > 0) {
        if (idle_.settleFrames > 0) --idle_.settleFrames;
        if (changed) idle_.settleFrames = kSettleFrames;
        glfwPollEvents();
        return;
    }
    double timeout = 1e9;  // glfwWaitEventsTimeout needs a finite number
    if (reference_->active() && !reference_->complete()) timeout = 1.0 / 30.0;  // show tiles as they finish
    if (global_->active() && global_->samples() < GlobalRenderer::kMaxSamples) timeout = 0.1;  // and sample passes
    const double statusLeft = status_.time + kStatusSeconds - glfwGetTime();
    if (statusLeft > 0.0) timeout = std::min(timeout, statusLeft + 0.01);
    const double before = glfwGetTime();
    glfwWaitEventsTimeout(timeout);
    if (glfwGetTime() - before < timeout) idle_.settleFrames = kSettleFrames;  // woken by an event
}

bool Viewer::frame() {
    waitForWork();
    const double t0 = glfwGetTime();
    if (glfwWindowShouldClose(window_.handle)) return false;
    handleDrops();
    glfwGetFramebufferSize(window_.handle, &shape_.fbWidth, &shape_.fbHeight);
    glfwGetWindowSize(window_.handle, &shape_.windowWidth, &shape_.windowHeight);
    if (shape_.fbWidth <= 0 || shape_.fbHeight <= 0 || shape_.windowWidth <= 0 || shape_.windowHeight <= 0 ||
        glfwGetWindowAttrib(window_.handle, GLFW_ICONIFIED)) {
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
    ctx.probe = probe_.result ? &*probe_.result : nullptr;
    ctx.rayTree = rayTree_.view ? &rayTree_.panel : nullptr;
    ctx.equation = equation_.result ? &*equation_.result : nullptr;
    ctx.reference = {reference_->active(),  reference_->complete(), reference_->progress(),
                     reference_->seconds(), reference_->threads(),  reference_->error()};
    ctx.global = {global_->active(), global_->samples(), GlobalRenderer::kMaxSamples, global_->passProgress(),
                  global_->noise8(), global_->seconds(), global_->threads(),          global_->error()};
    ctx.global.denoisedSamples = global_->denoisedSamples();
    if (probe_.result && isGlobal(state_.mode)) ctx.probeGlobal = global_->estimate(probe_.result->x, probe_.result->y);
    ctx.metrics = metrics_.result && metrics_.revision == state_.revision ? &*metrics_.result : nullptr;
    if (ctx.metrics) ctx.metricsWords = metrics_.words;
    ctx.shaderError = shaderError_;
    if (glfwGetTime() - status_.time < kStatusSeconds) {
        ctx.status = status_.message;
        ctx.statusError = status_.error;
    }
    if (const double now = glfwGetTime(); now - stats_.shownAt >= 0.5) {
        stats_.shownMs = recentFrameMs();
        stats_.shownAt = now;
    }
    ctx.frameMs = stats_.shownMs;
    ctx.renderWidth = layout_.renderWidth;
    ctx.renderHeight = layout_.renderHeight;
    ctx.uiScale = shape_.uiScale;
    // Compact on a projector, with the ray tree on (its rays need the room), and wherever the whole window
    // (about 720 units tall) would not fit the image.
    ctx.compactProbe = shape_.uiScale >= 1.5f || state_.probe.rayTree || layout_.imageH < 760.0f * shape_.uiScale;
    ctx.wipe = wipeFraction();
    ctx.undoSteps = history_.undoSteps();
    ctx.redoSteps = history_.redoSteps();
    if (shape_.showPanel) drawSidePanel(ctx, layout_.panelWidth, float(shape_.windowHeight), layout_.panelOverlays);
    const float margin = 10.0f * shape_.uiScale;
    const float left = visibleLeft(), visibleW = layout_.imageX + layout_.imageW - left;
    drawLessonWindow(ctx, left + margin, layout_.imageY + layout_.imageH - margin,
                     std::min(visibleW - 2.0f * margin, 760.0f * shape_.uiScale), ctx.probe != nullptr);
    if (!ctx.probe) fields_.probeWindowMoved = false;
    if (ctx.probe) {
        // Beside the probed point inside the visible image, clear of the point and its arrows, at the size
        // it was drawn last frame.
        ProbeWindowSpace space;
        space.visibleMin = glm::vec2(left + margin, layout_.imageY + margin);
        space.visibleMax =
            glm::vec2(layout_.imageX + layout_.imageW - margin, layout_.imageY + layout_.imageH - margin);
        space.point =
            glm::vec2(layout_.imageX + (float(state_.probe.x) + 0.5f) / float(layout_.renderWidth) * layout_.imageW,
                      layout_.imageY + (float(state_.probe.y) + 0.5f) / float(layout_.renderHeight) * layout_.imageH);
        space.clearance =
            0.22f * layout_.imageH + 20.0f * shape_.uiScale;  // the arrows (arrow_overlay.h): ~0.2 of the height
        space.minClearance = 20.0f * shape_.uiScale;
        const glm::vec2 size(fields_.probeWindowWidth, fields_.probeWindowHeight);
        const ProbeWindowPlace place = placeProbeWindow(space, size);
        drawProbeWindow(ctx, place.topLeft.x, place.topLeft.y, place.fits || fields_.probeWindowMoved);
        if (options_.verbose && !fields_.probeWindowMoved) logProbeWindow(space, place, size);
    }

    // Edits become undo steps between gestures, so a slider drag or a mouse drag is one step.
    if (!ImGui::IsAnyItemActive() && !pointer_.leftDown && !pointer_.panning && pointer_.light < 0)
        history_.commit(state_);

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
    glfwSwapBuffers(window_.handle);
    const double ms = (glfwGetTime() - t0) * 1000.0;
    if (options_.stats) (redrawn ? stats_.frames : stats_.idle).add(ms);
    stats_.recentMs[size_t(frame_) % stats_.recentMs.size()] = ms;
    return !last;
}

// Median of the last frames, for the panel's header (FrameStats keeps every frame for --stats).
double Viewer::recentFrameMs() const {
    const size_t n = std::min(size_t(frame_), stats_.recentMs.size());
    if (n == 0) return 0.0;
    std::array<double, 64> v{};
    std::copy_n(stats_.recentMs.begin(), n, v.begin());
    std::nth_element(v.begin(), v.begin() + long(n / 2), v.begin() + long(n));
    return v[n / 2];
}

void Viewer::computeLayout() {
    shape_.fixedWidth = options_.width;
    shape_.fixedHeight = options_.height;
    layout_ = layOutViewer(shape_);
}

bool Viewer::cameraMoved() {
    const Camera& c = state_.scene.camera;
    const bool moved =
        shown_.lastCamera && (c.position != shown_.lastCamera->position || c.target != shown_.lastCamera->target ||
                              c.up != shown_.lastCamera->up || c.fovY != shown_.lastCamera->fovY);
    shown_.lastCamera = c;
    return moved;
}

bool Viewer::ensureRasterCurrent(bool force, bool preview) {
    if (layout_.renderWidth <= 0 || layout_.renderHeight <= 0) return false;
    if (shown_.meshGeometry != state_.geometryRevision) {
        raster_->uploadMeshes(state_.scene);
        shown_.meshGeometry = state_.geometryRevision;
        shown_.revision = 0;
    }
    const bool changed = shown_.revision != state_.revision || shown_.width != layout_.renderWidth ||
                         shown_.height != layout_.renderHeight || (shown_.preview && !preview);
    if (!force && !changed) return false;
    if (changed) shown_.lastChange = glfwGetTime();
    // A forced redraw of an unchanged image (--stats) is a full one: what any change but a material edit costs.
    if (!changed) raster_->invalidate();
    const double t0 = glfwGetTime();
    try {
        if (preview) {
            // Half the width and height, a quarter of the pixels; the display pass scales it up. The shadow
            // maps keep the full image's size ("auto" depends on it), so they are neither re-rendered nor
            // coarser than in the full frame that follows.
            Scene scene = state_.scene;
            scene.raster.shadowMapSize =
                raster::shadowMapSizeFor(scene.raster, layout_.renderWidth, layout_.renderHeight);
            raster_->draw(scene, std::max(1, (layout_.renderWidth + 1) / 2),
                          std::max(1, (layout_.renderHeight + 1) / 2), true);
        } else {
            raster_->draw(state_.scene, layout_.renderWidth, layout_.renderHeight, true);
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
    if (options_.stats) stats_.raster.add((glfwGetTime() - t0) * 1000.0);
    const raster::RasterRenderer::DrawReport& report = raster_->lastDraw();
    stats_.partialDraws += report.partial ? 1 : 0;
    stats_.previewDraws += preview ? 1 : 0;
    stats_.shadowRenders += report.shadowMaps ? 1 : 0;
    stats_.environmentRenders += report.environments ? 1 : 0;
    shown_.revision = state_.revision;
    shown_.width = layout_.renderWidth;
    shown_.height = layout_.renderHeight;
    shown_.preview = preview;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return true;
}

// The smooth still frame (accumulation.h): in Raster mode, once nothing changes and no gesture is under
// way, two jittered samples per frame until the k×k grid is complete. Split and Difference keep the centre
// sample, so raster and reference are compared sample for sample.
bool Viewer::accumulate() {
    if (!fields_.smooth || state_.mode != ViewMode::Raster || options_.stats) return false;
    if (pointer_.leftDown || pointer_.panning || pointer_.light >= 0 || ImGui::IsAnyItemActive()) return false;
    accumulation_->restart(state_.revision, layout_.renderWidth, layout_.renderHeight);
    if (accumulation_->converged()) return false;
    for (int i = 0; i < 2; ++i) {
        // Into the renderer's sample target: its centre image and coverage stay as they are.
        const raster::RenderTarget& sample =
            raster_->drawSample(state_.scene, layout_.renderWidth, layout_.renderHeight, accumulation_->nextJitter());
        accumulation_->add(sample.colorTexture());
    }
    if (accumulation_->converged() && options_.verbose)
        std::fprintf(stderr, "shadelab: smooth frame, %d samples, %.0f ms after the last change\n",
                     accumulation_->samples(), (glfwGetTime() - shown_.lastChange) * 1000.0);
    return true;
}

bool Viewer::showsDenoised() const { return state_.globalDenoise && global_->denoisedSamples() > 0; }

void Viewer::updateReference() {
    if (isGlobal(state_.mode)) {
        reference_->pause();
        global_->request(state_.scene, layout_.renderWidth, layout_.renderHeight, state_.referenceRevision,
                         state_.globalPart);
        global_->update();
        return;
    }
    global_->pause();
    if (state_.mode == ViewMode::Raster && !(player_ && player_->waitingForReference())) {
        reference_->pause();
        return;
    }
    // Split and Difference compare with the rasterizer: the reference traces at the comparison's depth
    // (compare/comparison.h); Traced shows it at the scene's own depth.
    const bool comparing = state_.mode == ViewMode::Split || state_.mode == ViewMode::Difference;
    reference_->request(state_.scene, layout_.renderWidth, layout_.renderHeight, state_.referenceRevision,
                        comparing ? comparisonDepth(state_.scene) : -1);
    reference_->update();
    // Once per finished reference: pixels with no finite value are said on the status line (no silent black).
    if (reference_->complete() && reference_->revision() == state_.referenceRevision &&
        metrics_.finiteChecked != state_.referenceRevision) {
        metrics_.finiteChecked = state_.referenceRevision;
        toPixels(reference_->image(), "traced image");
    }
}

void Viewer::compose() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, shape_.fbWidth, shape_.fbHeight);
    // The image pass covers its rectangle; clear only what it leaves (a whole-window clear costs ~1 ms).
    const bool letterboxed = layout_.fbRect.y > 0 || layout_.fbRect.height < shape_.fbHeight ||
                             layout_.fbRect.x + layout_.fbRect.width < shape_.fbWidth;
    const std::array<float, 3> clear = {0.09f, 0.09f, 0.10f};
    // The docked side panel's background is this clear's too (drawSidePanel leaves it out).
    const int panelPixels =
        layout_.panelOverlays ? 0 : std::min(int(std::lround(layout_.panelWidth * layout_.fbScale)), shape_.fbWidth);
    glClearColor(clear[0], clear[1], clear[2], 1.0f);
    if (letterboxed) {
        glDisable(GL_SCISSOR_TEST);
        glClear(GL_COLOR_BUFFER_BIT);
    } else if (layout_.fbRect.x > panelPixels) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(panelPixels, 0, layout_.fbRect.x - panelPixels, shape_.fbHeight);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
    }
    if (panelPixels > 0) {
        const std::array<float, 3> bg = sidePanelBackground(clear);
        glClearColor(bg[0], bg[1], bg[2], 1.0f);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, panelPixels, shape_.fbHeight);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
    }
    ImageViewInputs in;
    // The smooth frame once it has a centred average for this very image, else the centre sample.
    const bool smooth = state_.mode == ViewMode::Raster && fields_.smooth && accumulation_->samples() >= 2 &&
                        !accumulation_->restart(state_.revision, layout_.renderWidth, layout_.renderHeight);
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
    if (in.selected != 0) {
        const raster::PixelRect r = raster_->objectRect(state_.scene, in.selected);
        in.selectedBounds = ImageRect{r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0};
    }
    imageView_->draw(layout_.fbRect, in);
    if (fields_.captions) drawCaptions();
    drawToast();
    if (fields_.lightMarkers) drawLightMarkers();  // over the captions: a light off the frame sits at its edge
    if (probe_.result && probe_.result->hit) {
        if (rayTree_.view) drawRayTree();
        drawArrowLabels(arrows_->draw(state_.scene, *probe_.result, layout_.renderWidth, layout_.renderHeight,
                                      layout_.fbRect, shape_.fbHeight, layout_.fbScale * shape_.uiScale));
    }
    ImGui::Render();
    panelCache_->render(ImGui::GetDrawData(), panelPixels, shape_.fbWidth, shape_.fbHeight);
    gl::checkError("viewer frame");
}

// The left edge of the part of the image the panel does not cover, window units.
float Viewer::visibleLeft() const {
    return layout_.panelOverlays ? std::max(layout_.imageX, layout_.panelWidth) : layout_.imageX;
}

float Viewer::wipeFraction() const {
    const float centre = 0.5f * (visibleLeft() + layout_.imageX + layout_.imageW);
    return wipePosition(state_, layout_.imageW > 0.0f ? (centre - layout_.imageX) / layout_.imageW : 0.5f);
}

}  // namespace shadelab::app
