// Viewer actions that need the window: script playback, captures (the rendered image through the one
// shared float → 8-bit conversion, the probe report, the whole window), open, save, shader hot reload,
// and the raster-vs-reference metrics.
#include "app/viewer.h"

#include "app/app.h"
#include "app/offline_render.h"
#include "app/save_policy.h"
#include "compare/difference_sites.h"
#include "image/encode.h"
#include "image/png.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"
#include "util/atomic_file.h"
#include "util/error_line.h"
#include "util/input_error.h"
#include "util/messages.h"
#include "util/output_file.h"
#include "util/warning_capture.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <type_traits>
#include <variant>

namespace shadelab::app {
namespace {

// A whole float target as the 8-bit image a screenshot writes (the one shared conversion, toImage8).
Image8 readTarget8(const raster::RenderTarget& target, Encoding encoding, const DisplaySettings& display,
                   uint64_t* nonFinite) {
    Image8 img;
    img.width = target.width();
    img.height = target.height();
    img.channels = 3;
    img.data.resize(size_t(img.width) * size_t(img.height) * 3);
    target.readColor8(img, 0, encoding, display, nonFinite);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return img;
}

}  // namespace

void Viewer::runScript() {
    if (player_) player_->play(frame_, state_, *this);
}

bool Viewer::referenceComplete() {
    // In Global modes: the path tracer's first whole sample pass of this state.
    return isGlobal(state_.mode) ? global_->samples() > 0 && global_->revision() == state_.referenceRevision
                                 : reference_->complete() && reference_->revision() == state_.referenceRevision;
}

bool Viewer::writeSmoothFrame(const std::string& path) {
    if (!accumulation_->converged() ||
        accumulation_->restart(state_.revision, layout_.renderWidth, layout_.renderHeight))
        return false;
    uint64_t nonFinite = 0;
    const Image8 smooth = readTarget8(accumulation_->target(), state_.encoding, state_.scene.display, &nonFinite);
    warnNonFinite("smooth frame", nonFinite, smooth);
    writePng(path, smooth);
    return true;
}

double Viewer::seconds() { return glfwGetTime(); }

void Viewer::performAction(const ScriptAction& a) {
    using namespace actions;
    std::visit(
        [&](const auto& x) {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, Screenshot>) {
                writePng(x.path, captureRaster());
            } else if constexpr (std::is_same_v<T, ReferenceScreenshot>) {
                if (isGlobal(state_.mode)) {
                    // The path tracer's image as shown: the PNG `shadelab render --renderer path --spp N`
                    // writes (with --denoise when the denoised preview is shown), N the samples so far
                    // (printed, so a script or a test can render the same).
                    if (global_->samples() == 0 || global_->revision() != state_.referenceRevision)
                        player_->fail(a, "the path tracer has no whole sample yet (use waitReference first)");
                    const bool denoised = showsDenoised();
                    writePng(x.path,
                             toPixels(denoised ? global_->denoisedImage() : global_->image(), "path-traced image"));
                    std::fprintf(stderr, "shadelab: %s: path traced, %d samples per pixel%s\n", x.path.c_str(),
                                 denoised ? global_->denoisedSamples() : global_->samples(),
                                 denoised ? ", denoised" : "");
                    return;
                }
                if (!reference_->complete() || reference_->revision() != state_.referenceRevision)
                    player_->fail(a, "the reference is not complete (use waitReference first)");
                writePng(x.path, toPixels(reference_->image(), "traced image"));
            } else if constexpr (std::is_same_v<T, WindowScreenshot>) {
                pendingWindowShot_ = x.path;
            } else if constexpr (std::is_same_v<T, ProbeReport>) {
                writeProbeReport(x.path);
            } else if constexpr (std::is_same_v<T, SaveScene>) {
                if (const std::string why = saveRefusal(x.path); !why.empty())
                    player_->fail(a, x.path + ": " + why, "path");
                saveSceneJson(state_.scene, x.path);
            } else if constexpr (std::is_same_v<T, Render>) {
                render::RenderRequest request = x.request;
                if (!x.sizeGiven) request.width = layout_.renderWidth, request.height = layout_.renderHeight;
                request.encoding = state_.encoding;
                // A render never replaces the scene it was made from.
                if (!state_.scenePath.empty()) refuseInputAsOutput(x.path, "path", {state_.scenePath});
                ensureRasterCurrent(false);  // the meshes of the state's scene are uploaded
                try {
                    uint64_t nonFinite = 0;
                    const Image8 image = renderOffline(*raster_, state_.scene, request, &nonFinite);
                    warnNonFinite("render", nonFinite, image);
                    writePng(x.path, image);
                } catch (const SettingError& e) {
                    player_->fail(a, e.reason(), e.field());
                }
                std::fprintf(stderr, "shadelab: %s: %s render, %dx%d\n", x.path.c_str(),
                             render::toString(request.engine), request.width, request.height);
            } else if constexpr (std::is_same_v<T, Undo>) {
                undo();
            } else if constexpr (std::is_same_v<T, Redo>) {
                redo();
            } else if constexpr (std::is_same_v<T, Open>) {
                WarningCapture warnings;
                Scene scene = loadScene(x.path, WarningCapture::warn);  // a script stops on a bad file
                app::openScene(state_, std::move(scene), x.path);
                state_.loadWarnings = warnings.lines();
                rememberRecent(fields_.recent, x.path);
                setStatus("opened " + x.path, false);  // as the Open button says it
            } else if constexpr (std::is_same_v<T, ReloadShaders>) {
                reloadShaders(x.dir);
            } else if constexpr (std::is_same_v<T, ResizeWindow>) {
                glfwSetWindowSize(window_.handle, x.width, x.height);
            } else {
                applyScriptAction(state_, a, player_->file());
            }
        },
        a.action);
}

// Feeds a scripted drag to Dear ImGui's mouse state, after the GLFW backend has read the real pointer and
// before ImGui::NewFrame turns it into clicks and deltas: frame 0 moves to the start, 1 presses, then
// `steps` moves, then the release. handleMouse cannot tell it from a hand on the mouse.
void Viewer::feedSyntheticMouse() {
    if (!player_) return;
    const std::optional<DragPointer> pointer = player_->nextDragPointer();
    if (!pointer) return;
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = windowPoint(pointer->imagePixel);
    io.MouseDown[0] = pointer->down;
}

Image8 Viewer::captureRaster() {
    ensureRasterCurrent(false);
    uint64_t nonFinite = 0;
    Image8 img = readTarget8(raster_->target(), state_.encoding, state_.scene.display, &nonFinite);
    warnNonFinite("raster image", nonFinite, img);
    return img;
}

Image8 Viewer::toPixels(const ImageF& image, const char* what) {
    uint64_t nonFinite = 0;
    Image8 img = toImage8(image, state_.encoding, state_.scene.display, &nonFinite);
    warnNonFinite(what, nonFinite, img);
    return img;
}

void Viewer::warnNonFinite(const char* what, uint64_t nonFinite, const Image8& image) {
    if (nonFinite == 0) return;
    const std::string text =
        std::string(what) + ": " + nonFiniteMessage(nonFinite, uint64_t(image.width) * uint64_t(image.height));
    printWarning(text);
    setStatus(text, true);
}

uint32_t Viewer::coverageAt(int x, int y) {
    ensureRasterCurrent(false);
    if (x < 0 || y < 0 || x >= shown_.width || y >= shown_.height) return 0;
    raster_->target().bind();
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    uint32_t id = 0;
    glReadPixels(x, shown_.height - 1 - y, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &id);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::checkError("coverage readback");
    return id;
}

void Viewer::writeProbeReport(const std::string& path) {
    if (!state_.probe.active)
        throw InputError(path, "no probe is set (click the image, or use a 'probe' script action)");
    updateProbe();
    const uint32_t coverage = coverageAt(state_.probe.x, state_.probe.y);
    writeFileAtomic(path,
                    probeReportJson(*probe_.result, state_.scene, coverage, rayTree_.view ? &*rayTree_.view : nullptr));
}

void Viewer::writeWindowScreenshot(const std::string& path) {
    Image8 img;
    img.width = shape_.fbWidth;
    img.height = shape_.fbHeight;
    img.channels = 3;
    std::vector<uint8_t> rgba(size_t(shape_.fbWidth) * size_t(shape_.fbHeight) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, shape_.fbWidth, shape_.fbHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    img.data.resize(size_t(shape_.fbWidth) * size_t(shape_.fbHeight) * 3);
    for (int y = 0; y < shape_.fbHeight; ++y)
        for (int x = 0; x < shape_.fbWidth; ++x)
            std::memcpy(&img.data[(size_t(y) * size_t(shape_.fbWidth) + size_t(x)) * 3],
                        &rgba[(size_t(shape_.fbHeight - 1 - y) * size_t(shape_.fbWidth) + size_t(x)) * 4], 3);
    writePng(path, img);
}

void Viewer::updateMetrics() {
    if (state_.mode != ViewMode::Difference || !reference_->complete() ||
        reference_->revision() != state_.referenceRevision || metrics_.revision == state_.revision)
        return;
    const Image8 raster = captureRaster();
    std::vector<uint32_t> rasterCoverage;
    raster_->target().readCoverage(rasterCoverage);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const Image8 traced = toPixels(reference_->image(), "traced image");
    if (traced.width != raster.width || traced.height != raster.height) return;
    metrics_.result = compareImages(raster, traced, rasterCoverage, reference_->coverage());
    metrics_.words = describeDifference(state_.scene, differenceSites(raster, traced, rasterCoverage, *metrics_.result),
                                        metrics_.result->gates.threshold);
    metrics_.revision = state_.revision;
}

void Viewer::openScene(const std::string& path) {
    try {
        WarningCapture warnings;
        Scene scene = loadScene(path, WarningCapture::warn);
        app::openScene(state_, std::move(scene), path);
        state_.loadWarnings = warnings.lines();
        rememberRecent(fields_.recent, path);
        fields_.openPath = path;
        fields_.savePath = defaultSavePath(path);
        metrics_.result.reset();
        setStatus("opened " + path, false);
    } catch (const std::exception& e) {
        setStatus(e.what(), true);
    }
}

void Viewer::saveScene(const std::string& path) {
    if (const std::string why = saveRefusal(path); !why.empty()) {
        setStatus(path + ": " + why, true);
        return;
    }
    try {
        saveSceneJson(state_.scene, path);
        setStatus("saved " + path, false);
    } catch (const std::exception& e) {
        setStatus(e.what(), true);
    }
}

void Viewer::undo() {
    if (history_.undo(state_)) {
        metrics_.result.reset();
        setStatus("undone (" + std::to_string(history_.undoSteps()) + " more to undo)", false);
    }
}

void Viewer::redo() {
    if (history_.redo(state_)) {
        metrics_.result.reset();
        setStatus("redone (" + std::to_string(history_.redoSteps()) + " more to redo)", false);
    }
}

void Viewer::screenshot(const std::string& path) {
    try {
        writePng(path, captureRaster());
        setStatus("wrote " + path + " (" + std::to_string(shown_.width) + "x" + std::to_string(shown_.height) + ")",
                  false);
    } catch (const std::exception& e) {
        setStatus(e.what(), true);
    }
}

// Rebuilds every program from the shaders on disk; on any error keeps the running ones and shows it.
void Viewer::reloadShaders(const std::string& from) {
    const std::string dir = from.empty() ? shaderSourceDir() : from;
    try {
        const gl::ShaderLibrary shaders(dir);
        auto raster = std::make_unique<raster::RasterRenderer>(shaders);
        raster->setPartialRedraw(true);
        auto view = std::make_unique<ImageView>(shaders);
        view->buildAll();
        auto arrows = std::make_unique<ArrowOverlay>(shaders);
        raster_ = std::move(raster);
        imageView_ = std::move(view);
        arrows_ = std::move(arrows);
        shown_.meshGeometry = 0;  // the new renderer has no meshes yet
        shown_.revision = 0;
        shaderError_.clear();
        setStatus("reloaded shaders from " + dir, false);
    } catch (const std::exception& e) {
        shaderError_ = e.what();
        setStatus("shader reload failed, keeping the last good shaders: " + shaderError_, true);
    }
}

void Viewer::setStatus(const std::string& message, bool error) {
    status_.message = message;
    status_.error = error;
    status_.time = glfwGetTime();
    if (error)
        printError(message);
    else if (options_.verbose)
        std::fprintf(stderr, "shadelab: %s\n", errorLine(message).c_str());
}

}  // namespace shadelab::app
