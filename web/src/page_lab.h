// PageLab: the web page's lab, everything the page's script asks of the C++: the scene being shown, its edits,
// the rasterizer's picture, the reference the workers traced, their comparison, the probe and the plots. It
// holds the viewer's plain-data state (app/viewer_state.h) and edits it only through the viewer's script
// actions (app/script.h), so the page has no scene rule, name table or settings conversion of its own: an
// edit in the page is the same edit as in a viewer script. Pictures come from the same calls as
// `shadelab render`: one render::RenderRequest per image, converted by render/render_request.h.
#pragma once

#include "app/albedo_plot.h"
#include "app/image_view.h"
#include "app/viewer_state.h"
#include "image/image.h"
#include "raster/raster_renderer.h"
#include "trace/trace_scene.h"
#include "web_context.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::web {

class PageLab {
public:
    // Creates the WebGL2 context on `canvas` (a CSS selector) and the rasterizer. Throws std::runtime_error.
    explicit PageLab(const std::string& canvas);

    // Opens a scene file (.json, .gltf, .glb) from the module's file system. Returns "" or the one-line error
    // ("upload.glb: truncated file ..."); on error the scene shown before stays.
    std::string open(const std::string& path);
    // Applies viewer-script actions, a JSON object or a list of them in the script format (docs/viewer.md),
    // e.g. {"action": "setShininess", "object": "#1", "s": 64}. Only state actions; "" or the error line.
    std::string act(const std::string& actionsJson);
    // A colour control and its strength slider, as the viewer's light panel splits them (app::splitIntensity):
    // the selected object's `field` ("ma", "md" or "ms") or light `index` becomes colour x intensity, through
    // the script's setMaterial / setLight action. "" or the error line.
    std::string setMaterialColor(const std::string& field, float r, float g, float b, float intensity);
    std::string setLightColor(int index, float r, float g, float b, float intensity);
    // The camera, as the viewer's mouse moves it: drag pixels, wheel steps.
    void orbit(float dxPixels, float dyPixels);
    void pan(float dxPixels, float dyPixels, float viewportHeight);
    void zoom(float steps);

    // What the page's controls show, as JSON: file, title, step, model, mode, selected object and its material,
    // lights, ambient, the objects' labels, and the warnings of the last load.
    std::string stateJson() const;
    // The scene as `Save` writes it (scene/scene_json.h), and the folder its relative model paths start from:
    // what a worker needs to rebuild the same scene. The text is kept until the next change a renderer can see
    // (revision): every reference, Global pass and link asks for it, and writing it takes milliseconds in wasm.
    const std::string& sceneJson();
    std::string sceneDir() const;
    // The edit counter the reference depends on: a reference traced at another revision is stale. A double
    // for JavaScript (embind has no 64-bit integers here), exact to 2^53 edits.
    double referenceRevision() const { return double(state_.referenceRevision); }
    double revision() const { return double(state_.revision); }

    // The rasterizer's picture at width x height: `shadelab render --renderer raster` of the same scene, as RGBA
    // bytes (alpha 255), row 0 at the top. Its coverage ids are kept for picking and for the comparison.
    const std::vector<uint8_t>& renderRaster(int width, int height);
    // The rasterizer's picture at width x height shown on the canvas itself (the page's context's default
    // framebuffer, which the page sizes to width x height), through the viewer's display pass (app/image_view.h)
    // with the selected object outlined, and nothing read back: the viewer's path, with its partial redraw (a
    // material edit redraws only that object's pixels). What a slider drag draws; renderRaster is for the
    // images the page reads.
    void drawRaster(int width, int height);
    // The coverage id under pixel (x, y) of the last raster picture (either call); 0 for the background or outside.
    uint32_t objectAt(int x, int y);
    // The last raster picture's coverage ids as RGBA bytes (compare/coverage_image.h), what
    // `shadelab render --coverage` writes for the same render.
    const std::vector<uint8_t>& rasterCoverageImage();

    // The reference the workers traced: RGB bytes (encoded by them as `shadelab render --renderer trace` encodes
    // its tiles) and coverage ids, width x height. Returns the RGBA bytes to show; throws std::invalid_argument
    // when the sizes do not match.
    const std::vector<uint8_t>& setReference(const std::vector<uint8_t>& rgb, const std::vector<uint32_t>& coverage,
                                             int width, int height);
    // The path tracer's running mean (linear RGBA), encoded for display with the scene's exposure and view
    // transform; returns the RGBA bytes.
    const std::vector<uint8_t>& encodeGlobal(const std::vector<float>& rgba, int width, int height);
    // The last raster picture against the last reference of the same size: the heatmap (RGBA) and the plain-words
    // sentence with the design.md §4 verdict. Empty heatmap when the sizes differ.
    const std::vector<uint8_t>& differenceImage();
    std::string differenceText() const { return differenceText_; }

    // The lighting probe at pixel (x, y) of a width x height image (probe/probe.h), as the viewer's probe
    // report (its JSON, docs/viewer.md) with the pixel's ray tree; also anchors the viewer state's probe there.
    std::string probe(int x, int y, int width, int height);
    // The lobe and albedo plots of the selected object's material (app/lobe_plot.h, app/albedo_plot.h) as JSON
    // curves; `incidence` is θi in degrees. The lobe's "polar" values (over its peak) are at "polarAngles", the
    // outgoing angles θo from N (negative on L's side); the albedo's at "viewAngles".
    std::string lobePlotJson(float incidence) const;
    std::string albedoPlotJson();

    const std::string& glRenderer() const { return context_.renderer(); }

private:
    void uploadIfNeeded();

    WebContext context_;
    std::unique_ptr<raster::RasterRenderer> renderer_;
    std::unique_ptr<app::ImageView> view_;
    bool coverageInTarget_ = false;  // the last raster picture was drawRaster's: its ids are in the GL target
    app::ViewerState state_;
    uint64_t uploadedGeometry_ = 0;
    Image8 raster_, reference_;  // RGB, the images compared
    std::vector<uint32_t> rasterCoverage_, referenceCoverage_;
    std::vector<uint32_t> pickCoverage_;             // objectAt's read of drawRaster's ids
    std::unique_ptr<trace::TraceScene> probeScene_;  // probe's tracer scene, of state_ at probeRevision_
    uint64_t probeRevision_ = 0;
    std::string sceneJson_;  // sceneJson() of state_ at sceneJsonRevision_ (0: none yet)
    uint64_t sceneJsonRevision_ = 0;
    std::optional<app::AlbedoPlot> albedoPlot_;  // the last albedoPlotJson's: it lends the next its unchanged curves
    std::vector<uint8_t> rasterRgba_, referenceRgba_, globalRgba_, heatRgba_, coverageRgba_;
    std::string differenceText_;
};

}  // namespace shadelab::web
