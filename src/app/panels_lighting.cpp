// Lighting panel: Phong, Blinn-Phong or pbr, the five term switches, the lecture's progression as steps, and
// the white furnace (scene/white_furnace.h).
#include "app/panels.h"

#include <imgui.h>
#include <iterator>
#include <string>

namespace shadelab::app {
namespace {

// Keeps the next widget of width `w` on this line when it fits, else starts a new line (labels never cut).
void sameLineIfFits(float w) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + w <= right) ImGui::SameLine();
}

float radioWidth(const char* label) {
    const ImGuiStyle& style = ImGui::GetStyle();
    return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
}

// pbr only: the environment that lights its surfaces (image-based lighting) and the energy compensation.
// The environment's file is the scene's; choosing another means editing the scene file (loading and
// prefiltering one takes a noticeable moment).
void drawEnvironmentControls(ViewerState& s) {
    bool compensate = s.scene.energyCompensation;
    if (ImGui::Checkbox("energy compensation (multiple scattering)", &compensate)) setEnergyCompensation(s, compensate);
    bool lit = s.scene.environment.has_value();
    const std::string label = !lit                               ? std::string("environment light (IBL): off")
                              : s.scene.environment->hdr.empty() ? std::string("environment light: uniform background")
                                                                 : "environment light: " + s.scene.environment->hdr;
    if (ImGui::Checkbox(label.c_str(), &lit)) {
        Environment e;  // uniform: radiance = background
        if (!lit)
            setEnvironment(s, std::nullopt);
        else
            setEnvironment(s, e);
    }
    if (s.scene.environment) {
        Environment e = *s.scene.environment;
        bool changed = ImGui::SliderFloat("intensity##env", &e.intensity, 0.0f, 4.0f, "%.2f");
        if (!e.hdr.empty()) changed |= ImGui::SliderFloat("rotation##env", &e.rotation, -180.0f, 180.0f, "%.0f deg");
        if (changed) setEnvironment(s, e);
    }
}

}  // namespace

void drawLightingSection(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    int model = modelIndex(s.scene.model);
    const char* names[] = {"Phong  (R·V)^s", "Blinn-Phong  (N·H)^s", "pbr  GGX metallic-roughness",
                           "disney  principled"};
    const ShadingModel models[] = {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr,
                                   ShadingModel::Disney};
    for (int i = 0; i < 4; ++i) {
        if (i > 0) sameLineIfFits(radioWidth(names[i]));
        if (ImGui::RadioButton(names[i], &model, i)) setModel(s, models[i]);
    }
    if (!isPhysicallyBased(s.scene.model)) {
        bool normalized = s.scene.normalized;
        if (ImGui::Checkbox("normalized lobe  (s+2)/2, (s+8)/8", &normalized)) setNormalized(s, normalized);
    } else {
        drawEnvironmentControls(s);
    }

    ImGui::TextDisabled("Terms");
    for (size_t i = 0; i < std::size(kTermNames); ++i) {
        const Term t = kTermNames[i].value;
        bool on = termEnabled(s.scene.terms, t);
        if (i != 0 && i != 3) ImGui::SameLine();
        if (ImGui::Checkbox(kTermNames[i].name, &on)) setTerm(s, t, on);
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped(
        "raster: shadow maps, mirror planes, environment cubes; transmission (kt): reference only; glTF "
        "transmission: the environment and, in one, a cube");
    ImGui::PopStyleColor();

    ImGui::TextDisabled("Progression (keys 0-5)");
    const char* labels[] = {"0 unlit", "1 ambient", "2 +diffuse", "3 +specular", "4 +shadows", "5 +reflections"};
    const int current = progressionStep(s.scene.terms);
    for (int step = 0; step <= kProgressionSteps; ++step) {
        if (step != 0 && step != 3) ImGui::SameLine();
        const bool active = step == current;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        if (ImGui::Button(labels[step])) applyProgression(s, step);
        if (active) ImGui::PopStyleColor();
    }

    const bool furnace = whiteFurnaceOn(s);
    if (furnace) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(furnace ? "White furnace: on (press to restore the scene)" : "White furnace"))
        setWhiteFurnace(s, !furnace);
    if (furnace) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered() || furnace) {
        ImGui::TextWrapped(
            "Every material white (md + ms = 1, baseColor 1), lights off, background and Ia = 1. An object that "
            "reflects exactly the light it receives vanishes; energy lost or gained shows as dark or bright rings.");
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped(
            isPhysicallyBased(s.scene.model)
                ? "pbr and disney: lit by the uniform environment (image-based lighting). GGX without energy "
                  "compensation "
                  "misses its multiple scattering: a white metal shows dark rims that grow with roughness. Tick "
                  "'energy compensation' below and they vanish."
                : "Phong and Blinn-Phong are lit by the ambient term only, a constant that knows nothing of the "
                  "lobe, so every object vanishes. The albedo plot (Material) shows what each lobe reflects.");
        ImGui::PopStyleColor();
    }
}

}  // namespace shadelab::app
