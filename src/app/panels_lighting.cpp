// Lighting panel: Phong, Blinn-Phong or pbr, the five term switches, and the lecture's progression as steps.
#include "app/panels.h"

#include <imgui.h>
#include <iterator>

namespace shadelab::app {

void drawLightingSection(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    int model = modelIndex(s.scene.model);
    if (ImGui::RadioButton("Phong  (R·V)^s", &model, 0)) setModel(s, ShadingModel::Phong);
    ImGui::SameLine();
    if (ImGui::RadioButton("Blinn-Phong  (N·H)^s", &model, 1)) setModel(s, ShadingModel::BlinnPhong);
    ImGui::SameLine();
    if (ImGui::RadioButton("PBR  GGX", &model, 2)) setModel(s, ShadingModel::Pbr);
    if (s.scene.model != ShadingModel::Pbr) {
        bool normalized = s.scene.normalized;
        if (ImGui::Checkbox("normalized lobe  (s+2)/2, (s+8)/8", &normalized)) setNormalized(s, normalized);
    }

    ImGui::TextDisabled("Terms");
    for (size_t i = 0; i < std::size(kTermNames); ++i) {
        const Term t = kTermNames[i].value;
        bool on = termEnabled(s.scene.terms, t);
        if (i != 0 && i != 3) ImGui::SameLine();
        if (ImGui::Checkbox(kTermNames[i].name, &on)) setTerm(s, t, on);
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("raster: shadow maps, mirror planes, environment cubes; transmission (kt): reference only");
    ImGui::PopStyleColor();

    ImGui::TextDisabled("Progression (keys 1-5)");
    const char* labels[] = {"1 ambient", "2 +diffuse", "3 +specular", "4 +shadows", "5 +reflections"};
    const int current = progressionStep(s.scene.terms);
    for (int step = 1; step <= kProgressionSteps; ++step) {
        if (step != 1 && step != 4) ImGui::SameLine();
        const bool active = step == current;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        if (ImGui::Button(labels[step - 1])) applyProgression(s, step);
        if (active) ImGui::PopStyleColor();
    }
}

}  // namespace shadelab::app
