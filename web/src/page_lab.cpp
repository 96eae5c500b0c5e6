// PageLab: the viewer state edited by script actions, pictures through render requests, and their comparison.
#include "page_lab.h"

#include "app/albedo_plot.h"
#include "app/lobe_plot.h"
#include "app/script.h"
#include "app/specular_lobe.h"
#include "compare/compare_report.h"
#include "compare/coverage_image.h"
#include "compare/difference_sites.h"
#include "compare/image_compare.h"
#include "image/encode.h"
#include "probe/probe.h"
#include "probe/ray_tree_view.h"
#include "raster/offscreen.h"
#include "render/render_request.h"
#include "scene/coverage.h"
#include "scene/environment_load.h"
#include "scene/object_ref.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"
#include "trace/trace_scene.h"
#include "util/error_line.h"
#include "util/input_error.h"
#include "util/warning_capture.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

namespace shadelab::web {
namespace {

using Json = nlohmann::json;

// What a load in the page may take (the environment map's prefilter and every model): a browser tab's
// WebAssembly memory ends at 2 GiB (-sMAXIMUM_MEMORY), and the page keeps two scenes while it switches.
constexpr uint64_t kPageLoadBytes = uint64_t(512) << 20;

Json vec(const glm::vec3& v) { return Json::array({v.x, v.y, v.z}); }

// An error for the page's message line: one line, escaped and capped as on the terminal.
std::string lineOf(const std::exception& e) { return errorLine(e.what()); }

// RGB bytes → RGBA with alpha 255, as a canvas's ImageData holds them.
void toRgba(const Image8& image, std::vector<uint8_t>& out) {
    const size_t n = size_t(image.width) * size_t(image.height);
    out.resize(n * 4);
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) out[i * 4 + size_t(c)] = image.data[i * size_t(image.channels) + size_t(c)];
        out[i * 4 + 3] = 255;
    }
}

// Linear RGBA floats → the 8-bit RGB image the native front ends encode, with the scene's display.
Image8 encodeLinear(const std::vector<float>& rgba, int width, int height, const Scene& scene) {
    if (rgba.size() != size_t(width) * size_t(height) * 4) throw std::invalid_argument("image size mismatch");
    ImageF image(width, height);
    std::copy(rgba.begin(), rgba.end(), image.pixel(0, 0));
    render::RenderRequest request;
    request.width = width;
    request.height = height;
    return toImage8(image, request.encoding, render::displayOf(request, scene), nullptr);
}

// The page's raster picture: `shadelab render --renderer raster` at width x height, with coverage ids (for
// picking and the comparison). Throws SettingError for a size out of range.
render::RenderRequest rasterRequest(int width, int height) {
    render::RenderRequest request;
    request.engine = render::Engine::Raster;
    request.width = width;
    request.height = height;
    request.coverage = true;
    render::require(request);
    return request;
}

}  // namespace

PageLab::PageLab(const std::string& canvas)
    : context_(canvas),
      renderer_(std::make_unique<raster::RasterRenderer>(gl::ShaderLibrary(), raster::ProgramCheck::OnFirstUse)),
      view_(std::make_unique<app::ImageView>(gl::ShaderLibrary())) {
    renderer_->setPartialRedraw(true);  // bit for bit a full draw (redraw_plan.h), as in the viewer
}

std::string PageLab::open(const std::string& path) {
    try {
        WarningCapture warnings;
        Scene scene =
            loadScene(path, WarningCapture::warn, GltfImportOptions{}, MemoryLimit{kPageLoadBytes, "the page"});
        if (scene.lights.size() > size_t(kMaxLights))
            throw InputError(path, "lights", "the rasterizer takes at most " + std::to_string(kMaxLights) + " lights");
        // As the viewer's Open: camera, selection and probe reset, the view mode kept, the geometry revision
        // bumped (so the rasterizer uploads the new meshes).
        app::openScene(state_, std::move(scene), path);
        state_.loadWarnings = warnings.lines();
        if (objectCount(state_.scene) > 0) app::select(state_, 1);
        return "";
    } catch (const std::exception& e) {
        return lineOf(e);
    }
}

std::string PageLab::act(const std::string& actionsJson) {
    try {
        // One action or a list, as the "actions" of a script file.
        Json parsed = Json::parse(actionsJson);
        Json script = {{"actions", parsed.is_array() ? parsed : Json::array({parsed})}};
        const app::Script s = app::parseScript(script.dump(), "page");
        for (const app::ScriptAction& a : s.actions) {
            if (!app::isStateAction(a)) throw std::invalid_argument("page: " + a.name + ": not an edit the page makes");
            app::applyScriptAction(state_, a, s.file);
        }
        return "";
    } catch (const std::exception& e) {
        return lineOf(e);
    }
}

std::string PageLab::setMaterialColor(const std::string& field, float r, float g, float b, float intensity) {
    if (field != "ma" && field != "md" && field != "ms") return "page: no material colour \"" + field + "\"";
    if (state_.selected == 0) return "page: select an object first (click it)";
    const glm::vec3 value = app::joinIntensity({{r, g, b}, intensity});
    return act(
        Json{{"action", "setMaterial"}, {"object", "#" + std::to_string(state_.selected)}, {field, vec(value)}}.dump());
}

std::string PageLab::setLightColor(int index, float r, float g, float b, float intensity) {
    const glm::vec3 value = app::joinIntensity({{r, g, b}, intensity});
    return act(Json{{"action", "setLight"}, {"index", index}, {"color", vec(value)}}.dump());
}

void PageLab::orbit(float dx, float dy) {
    app::OrbitCamera o = state_.orbit;
    // The viewer's mouse: a drag across 200 pixels turns the camera by one radian.
    app::orbitRotate(o, -dx * 0.005f, dy * 0.005f);
    app::applyOrbit(state_, o);
}

void PageLab::pan(float dx, float dy, float viewportHeight) {
    app::OrbitCamera o = state_.orbit;
    app::orbitPan(o, dx, dy, viewportHeight);
    app::applyOrbit(state_, o);
}

void PageLab::zoom(float steps) {
    app::OrbitCamera o = state_.orbit;
    app::orbitZoom(o, steps);
    app::applyOrbit(state_, o);
}

std::string PageLab::stateJson() const {
    const Scene& sc = state_.scene;
    Json j;
    j["file"] = state_.scenePath;
    j["title"] = sc.title;
    j["notes"] = sc.notes;
    j["step"] = app::progressionStep(sc.terms);
    j["model"] = toString(sc.model);
    j["mode"] = toString(state_.mode);
    j["selected"] = state_.selected;
    j["ambient"] = vec(sc.ambient);
    Json objects = Json::array();
    for (uint32_t id = 1; id <= objectCount(sc); ++id) objects.push_back({{"id", id}, {"label", objectLabel(sc, id)}});
    j["objects"] = objects;
    if (state_.selected != 0) {
        const Material m = app::objectMaterial(sc, state_.selected);
        Json colors;
        for (const auto& [name, value] : {std::pair{"ma", m.ma}, {"md", m.md}, {"ms", m.ms}}) {
            const app::ColorIntensity ci = app::splitIntensity(value);
            colors[name] = {{"color", vec(ci.color)}, {"intensity", ci.intensity}};
        }
        j["material"] = {{"colors", colors},
                         {"ma", vec(m.ma)},
                         {"md", vec(m.md)},
                         {"ms", vec(m.ms)},
                         {"s", m.s},
                         {"baseColor", vec(m.baseColor)},
                         {"metallic", m.metallic},
                         {"roughness", m.roughness}};
    }
    Json lights = Json::array();
    for (const Light& l : sc.lights) {
        const app::ColorIntensity ci = app::splitIntensity(l.color);
        lights.push_back(
            {{"name", l.name}, {"type", toString(l.type)}, {"color", vec(ci.color)}, {"intensity", ci.intensity}});
    }
    j["lights"] = lights;
    j["warnings"] = state_.loadWarnings;
    return j.dump();
}

const std::string& PageLab::sceneJson() {
    if (sceneJsonRevision_ != state_.revision) {
        sceneJson_ = sceneToJson(state_.scene);
        sceneJsonRevision_ = state_.revision;
    }
    return sceneJson_;
}

std::string PageLab::sceneDir() const { return std::filesystem::path(state_.scenePath).parent_path().string(); }

void PageLab::uploadIfNeeded() {
    if (uploadedGeometry_ == state_.geometryRevision) return;
    renderer_->uploadMeshes(state_.scene);
    uploadedGeometry_ = state_.geometryRevision;
}

const std::vector<uint8_t>& PageLab::renderRaster(int width, int height) {
    uploadIfNeeded();
    const render::RenderRequest request = rasterRequest(width, height);
    raster::OffscreenResult r =
        raster::renderOffscreen(*renderer_, state_.scene, render::toOffscreen(request, state_.scene));
    raster_ = std::move(r.pixels);
    rasterCoverage_ = std::move(r.coverage);
    coverageInTarget_ = false;
    toRgba(raster_, rasterRgba_);
    return rasterRgba_;
}

void PageLab::drawRaster(int width, int height) {
    uploadIfNeeded();
    const render::RenderRequest request = rasterRequest(width, height);
    renderer_->draw(state_.scene, width, height, true);
    const raster::RenderTarget& target = renderer_->target();
    app::ImageViewInputs in;
    in.raster = target.colorTexture();
    in.imageWidth = target.width();
    in.imageHeight = target.height();
    in.display = render::displayOf(request, state_.scene);
    in.coverage = target.coverageTexture();
    in.selected = state_.selected;
    if (in.selected != 0) {
        const raster::PixelRect r = renderer_->objectRect(state_.scene, in.selected);
        in.selectedBounds = app::ImageRect{r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0};
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    view_->draw({0, 0, width, height}, in);
    coverageInTarget_ = true;
}

uint32_t PageLab::objectAt(int x, int y) {
    const std::vector<uint32_t>* ids = &rasterCoverage_;
    int width = raster_.width, height = raster_.height;
    if (coverageInTarget_) {
        // Read when asked (a click), not every frame.
        const raster::RenderTarget& target = renderer_->target();
        target.readCoverage(pickCoverage_);
        ids = &pickCoverage_;
        width = target.width();
        height = target.height();
    }
    if (x < 0 || y < 0 || x >= width || y >= height || ids->empty()) return 0;
    return (*ids)[size_t(y) * size_t(width) + size_t(x)];
}

const std::vector<uint8_t>& PageLab::rasterCoverageImage() {
    toRgba(coverageToImage(rasterCoverage_, raster_.width, raster_.height), coverageRgba_);
    return coverageRgba_;
}

const std::vector<uint8_t>& PageLab::setReference(const std::vector<uint8_t>& rgb,
                                                  const std::vector<uint32_t>& coverage, int width, int height) {
    const size_t pixels = size_t(std::max(width, 0)) * size_t(std::max(height, 0));
    if (rgb.size() != pixels * 3 || coverage.size() != pixels) throw std::invalid_argument("image size mismatch");
    reference_ = Image8{width, height, 3, rgb};
    referenceCoverage_ = coverage;
    toRgba(reference_, referenceRgba_);
    return referenceRgba_;
}

const std::vector<uint8_t>& PageLab::encodeGlobal(const std::vector<float>& rgba, int width, int height) {
    toRgba(encodeLinear(rgba, width, height, state_.scene), globalRgba_);
    return globalRgba_;
}

const std::vector<uint8_t>& PageLab::differenceImage() {
    heatRgba_.clear();
    differenceText_.clear();
    if (raster_.width == 0 || raster_.width != reference_.width || raster_.height != reference_.height)
        return heatRgba_;
    const CompareResult cmp = compareImages(raster_, reference_, rasterCoverage_, referenceCoverage_);
    const DifferenceSites sites = differenceSites(raster_, reference_, rasterCoverage_, cmp);
    differenceText_ = describeDifference(state_.scene, sites, cmp.gates.threshold) + "\n" + compareSummary(cmp);
    toRgba(diffHeatmap(raster_, reference_, cmp.bandMask, state_.heatGain), heatRgba_);
    return heatRgba_;
}

std::string PageLab::probe(int x, int y, int width, int height) {
    try {
        // The tracer's copy of the scene (its BVH) is kept until the scene changes: clicks in a row reuse it.
        if (!probeScene_ || probeRevision_ != state_.revision) {
            probeScene_ = std::make_unique<trace::TraceScene>(state_.scene);
            probeRevision_ = state_.revision;
        }
        const ProbeResult p = probePixel(*probeScene_, width, height, x, y);
        app::setProbe(state_, x, y);
        if (p.hit) state_.probe.anchor = ProbeAnchor{p.objectId, p.P};
        // With the rays the reference traces from the pixel (the viewer's ray view, probe/ray_tree_view.h).
        std::optional<RayTreeView> tree;
        if (p.hit) tree = recordRayTree(*probeScene_, width, height, x, y);
        return probeReportJson(p, state_.scene, p.objectId, tree ? &*tree : nullptr);
    } catch (const std::exception& e) {
        return Json{{"error", lineOf(e)}}.dump();
    }
}

std::string PageLab::lobePlotJson(float incidence) const {
    if (state_.selected == 0) return "{}";
    const Material m = app::objectMaterial(state_.scene, state_.selected);
    // The plots take s as a Phong exponent: under Blinn-Phong it is converted by the equivalence rule.
    app::LobePlotSettings settings;
    settings.phongExponent = state_.scene.model == ShadingModel::BlinnPhong ? app::equivalentPhongExponent(m.s) : m.s;
    settings.roughness = m.roughness;
    settings.metallic = m.metallic;
    settings.baseColor = m.baseColor;
    settings.incidence = std::clamp(incidence, 0.0f, 89.0f);
    const app::LobePlot plot = app::makeLobePlot(settings);
    Json curves = Json::array();
    for (const app::LobeCurve& c : plot.curves)
        curves.push_back({{"label", c.label}, {"peak", c.peak}, {"polar", c.polar}, {"value", c.value}});
    Json polarAngles = Json::array();
    for (int i = 0; i < settings.polarSamples; ++i) polarAngles.push_back(plot.polarAngleAt(i));
    return Json{
        {"incidence", settings.incidence}, {"axis", settings.axis}, {"polarAngles", polarAngles}, {"curves", curves}}
        .dump();
}

std::string PageLab::albedoPlotJson() {
    if (state_.selected == 0) return "{}";
    const Material m = app::objectMaterial(state_.scene, state_.selected);
    app::AlbedoPlotSettings settings;
    settings.phongExponent = state_.scene.model == ShadingModel::BlinnPhong ? app::equivalentPhongExponent(m.s) : m.s;
    settings.roughness = m.roughness;
    albedoPlot_ = app::makeAlbedoPlot(settings, albedoPlot_ ? &*albedoPlot_ : nullptr);
    const app::AlbedoPlot& plot = *albedoPlot_;
    Json curves = Json::array();
    for (const app::AlbedoCurve& c : plot.curves)
        curves.push_back({{"label", c.label}, {"albedo", c.albedo}, {"dashed", c.dashed}});
    return Json{{"viewAngles", plot.viewAngles}, {"curves", curves}}.dump();
}

}  // namespace shadelab::web
