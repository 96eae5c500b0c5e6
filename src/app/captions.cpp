#include "app/captions.h"

#include "scene/scene_models.h"

#include <cstdio>

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
    std::string words;
    switch (scene.model) {
        case ShadingModel::Phong: words = scene.normalized ? "normalised Phong" : "Phong"; break;
        case ShadingModel::BlinnPhong: words = scene.normalized ? "normalised Blinn-Phong" : "Blinn-Phong"; break;
        case ShadingModel::Pbr: words = "PBR (GGX)"; break;
        case ShadingModel::Disney: words = "Disney principled"; break;
    }
    // Objects whose material names another model are shaded with it: say so, or the caption misleads.
    for (ShadingModel other : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr, ShadingModel::Disney})
        if (other != scene.model && usesModel(scene, other)) return words + " and the objects' own models";
    return words;
}

WipeCaptions wipeCaptions(ViewMode mode) {
    if (mode == ViewMode::Split) return {"raster", "reference (Whitted ray tracer)"};
    if (mode == ViewMode::LocalGlobal) return {"local (raster)", "global (path traced)"};
    return {};
}

WipeLabelPlacement placeWipeLabels(float visibleLeft, float visibleRight, float wipe, float gap, float leftWidth,
                                   float rightWidth) {
    WipeLabelPlacement p;
    p.leftX = wipe - gap - leftWidth;
    p.rightX = wipe + gap;
    p.leftShown = p.leftX >= visibleLeft && wipe - gap <= visibleRight;
    p.rightShown = p.rightX >= visibleLeft && p.rightX + rightWidth <= visibleRight;
    return p;
}

std::string termsCaption(const Terms& terms) { return stepCaption(terms, terms); }

std::string imageCaption(const ViewerState& state, const GlobalCaption& global) {
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
    if (isGlobal(state.mode)) {
        char progress[64];
        if (global.samples == 0)
            std::snprintf(progress, sizeof progress, "first sample");
        else if (global.samples == 1)  // one sample per pixel measures no noise
            std::snprintf(progress, sizeof progress, "1 sample, noise -");
        else
            std::snprintf(progress, sizeof progress, "%d samples, noise %.1f/255", global.samples, global.noise8);
        caption += std::string("  \xc2\xb7  ") + progress;
        // The preview is not the estimate: a class must know when the noise it does not see was filtered away.
        if (global.denoised) caption += "  \xc2\xb7  denoised";
    }
    // A display that is not Standard says so: the picture is no longer the clamped values (the difference view
    // never uses it).
    if (!state.scene.display.isStandard() && state.mode != ViewMode::Difference)
        caption += "  \xc2\xb7  " + describe(state.scene.display);
    return caption;
}

}  // namespace shadelab::app
