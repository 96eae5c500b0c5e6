#include "app/captions.h"

namespace shadelab::app {
namespace {

const char* globalCaption(trace::PathPart part) {
    switch (part) {
        case trace::PathPart::Direct: return "global illumination, direct light only (path traced)";
        case trace::PathPart::Indirect: return "indirect light only: what the ambient term stands in for";
        case trace::PathPart::All: break;
    }
    return "global illumination (path traced)";
}

// The terms `shown` listed, named by the progression step and "no illumination" that the scene's own terms are.
std::string stepCaption(const Terms& shown, const Terms& scene) {
    std::string text;
    for (const auto& entry : kTermNames) {
        if (!termEnabled(shown, entry.value)) continue;
        if (!text.empty()) text += " + ";
        text += entry.name;
    }
    // No light term on: every surface shows its unlit colour (docs/lighting.md), whatever else is on.
    if (!scene.ambient && !scene.diffuse && !scene.specular)
        text = text.empty() ? "no illumination" : "no illumination, " + text;
    if (text.empty()) text = "nothing";
    const int step = progressionStep(scene);
    return step >= 0 ? "step " + std::to_string(step) + ": " + text : text;
}

}  // namespace

std::string modelCaption(const Scene& scene) {
    switch (scene.model) {
        case ShadingModel::Phong: return scene.normalized ? "normalised Phong" : "Phong";
        case ShadingModel::BlinnPhong: return scene.normalized ? "normalised Blinn-Phong" : "Blinn-Phong";
        case ShadingModel::Pbr: return "PBR (GGX)";
    }
    return toString(scene.model);
}

std::string termsCaption(const Terms& terms) { return stepCaption(terms, terms); }

std::string imageCaption(const ViewerState& state) {
    const char* mode = "";
    switch (state.mode) {
        case ViewMode::Raster: mode = "raster"; break;
        case ViewMode::Traced: mode = "reference (Whitted ray tracer)"; break;
        case ViewMode::Split: mode = "raster | reference"; break;
        case ViewMode::Difference: mode = "|raster - reference|, amplified"; break;
        case ViewMode::Global: mode = globalCaption(state.globalPart); break;
        case ViewMode::LocalGlobal: mode = "local (raster) | global (path traced)"; break;
    }
    // The path tracer leaves the ambient term out whatever its switch says (light bounces instead).
    Terms terms = state.scene.terms;
    if (state.mode == ViewMode::Global) terms.ambient = false;
    std::string caption =
        modelCaption(state.scene) + "  \xc2\xb7  " + stepCaption(terms, state.scene.terms) + "  \xc2\xb7  " + mode;
    // A display that is not Standard says so: the picture is no longer the clamped values (the difference view
    // never uses it).
    if (!state.scene.display.isStandard() && state.mode != ViewMode::Difference)
        caption += "  \xc2\xb7  " + describe(state.scene.display);
    return caption;
}

}  // namespace shadelab::app
