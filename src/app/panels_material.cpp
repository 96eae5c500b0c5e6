// Material panel: pick an object, edit ma/md/ms/s/kr/kt/ior or apply a classic preset, and watch the
// specular lobe follow the shininess slider; the equivalent-exponent buttons switch model keeping the
// highlight's size (specular_lobe.h).
#include "app/panels.h"

#include "app/material_presets.h"
#include "app/specular_lobe.h"

#include <imgui.h>
#include <glm/gtc/type_ptr.hpp>

#include <string>

namespace shadelab::app {
namespace {

void objectCombo(ViewerState& s) {
    const std::string preview = s.selected ? objectLabel(s.scene, s.selected) : "(click an object)";
    if (!ImGui::BeginCombo("object", preview.c_str())) return;
    for (uint32_t id = 1; id <= objectCount(s.scene); ++id) {
        const std::string label = objectLabel(s.scene, id);
        if (ImGui::Selectable(label.c_str(), id == s.selected)) select(s, id);
    }
    ImGui::EndCombo();
}

void presetCombo(ViewerState& s) {
    if (!ImGui::BeginCombo("preset", "OpenGL teapot table...")) return;
    for (const MaterialPreset& p : materialPresets())
        if (ImGui::Selectable(p.name)) applyPreset(s, s.selected, p);
    ImGui::EndCombo();
}

}  // namespace

void drawMaterialSection(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    objectCombo(s);
    if (s.selected == 0) {
        ImGui::TextDisabled("Click an object in the image to edit its material.");
        return;
    }
    presetCombo(s);
    Material m = objectMaterial(s.scene, s.selected);
    bool changed = false;
    const ImGuiColorEditFlags colorFlags = ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR;
    changed |= ImGui::ColorEdit3("ma  ambient", glm::value_ptr(m.ma), colorFlags);
    changed |= ImGui::ColorEdit3("md  diffuse", glm::value_ptr(m.md), colorFlags);
    changed |= ImGui::ColorEdit3("ms  specular", glm::value_ptr(m.ms), colorFlags);
    float shininess = m.s;
    if (ImGui::SliderFloat("s  shininess", &shininess, 1.0f, 2048.0f, "%.1f", ImGuiSliderFlags_Logarithmic))
        setShininess(s, s.selected, shininess);
    changed |= ImGui::ColorEdit3("kr  reflect", glm::value_ptr(m.kr), colorFlags);
    changed |= ImGui::ColorEdit3("kt  transmit", glm::value_ptr(m.kt), colorFlags);
    changed |= ImGui::SliderFloat("ior", &m.ior, 1.0f, 3.0f, "%.3f");
    ImGui::TextDisabled("pbr: glTF metallic-roughness");
    changed |= ImGui::ColorEdit3("baseColor", glm::value_ptr(m.baseColor), ImGuiColorEditFlags_Float);
    changed |= ImGui::SliderFloat("metallic", &m.metallic, 0.0f, 1.0f, "%.2f");
    changed |= ImGui::SliderFloat("roughness", &m.roughness, 0.0f, 1.0f, "%.3f");
    if (changed) {
        m.s = objectMaterial(s.scene, s.selected).s;  // the slider above already applied its own change
        setObjectMaterial(s, s.selected, m);
    }

    // The lobe plot and the equivalent exponents belong to the lecture's models (pbr's plots: issue 12, later).
    if (s.scene.model == ShadingModel::Pbr) return;
    const float s2 = objectMaterial(s.scene, s.selected).s;
    drawSpecularLobe(s2, s.scene.model, ImGui::GetContentRegionAvail().x, 130.0f * ctx.uiScale);

    ImGui::TextDisabled("Equivalent exponent: keep the highlight's size");
    if (s.scene.model == ShadingModel::Phong) {
        const std::string label =
            "Switch to Blinn-Phong, s' = " + std::to_string(int(equivalentBlinnExponent(s2) + 0.5f));
        if (ImGui::Button(label.c_str()))
            switchModelKeepingHighlights(s, ShadingModel::BlinnPhong, ctx.fields.convertAllObjects);
    } else {
        const std::string label = "Switch to Phong, s = " + std::to_string(int(equivalentPhongExponent(s2) + 0.5f));
        if (ImGui::Button(label.c_str()))
            switchModelKeepingHighlights(s, ShadingModel::Phong, ctx.fields.convertAllObjects);
    }
    ImGui::SameLine();
    ImGui::Checkbox("all objects", &ctx.fields.convertAllObjects);
}

void drawSpecularLobe(float s, ShadingModel model, float width, float height) {
    constexpr int kSamples = 181;
    // The material's exponent belongs to the current model; the other model's lobe uses the equivalent one.
    const bool phong = model == ShadingModel::Phong;
    const float sPhong = phong ? s : equivalentPhongExponent(s);
    const float sBlinn = phong ? equivalentBlinnExponent(s) : s;
    const float range = lobePlotRange(sPhong);  // degrees: the x axis zooms in on narrow lobes
    struct Curve {
        std::vector<float> v;
        ImU32 color;
        float thickness;
        std::string label;
    };
    char buf[96];
    // Drawn in this order: the Phong lobe last and thin, over the wide equivalent Blinn lobe it matches.
    std::vector<Curve> curves;
    std::snprintf(buf, sizeof buf, "(N·H)^%.0f  Blinn-Phong, same exponent", phong ? s : sPhong);
    curves.push_back({blinnLobe(phong ? s : sPhong, kSamples, range), IM_COL32(120, 150, 255, 220), 2.0f, buf});
    std::snprintf(buf, sizeof buf, "(N·H)^%.0f  Blinn-Phong, equivalent", sBlinn);
    curves.push_back({blinnLobe(sBlinn, kSamples, range), IM_COL32(90, 220, 110, 200), 6.0f, buf});
    std::snprintf(buf, sizeof buf, "(R·V)^%.0f  Phong", sPhong);
    curves.push_back({phongLobe(sPhong, kSamples, range), IM_COL32(255, 170, 60, 255), 2.0f, buf});

    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const ImVec2 p1(p0.x + width, p0.y + height);
    dl->AddRectFilled(p0, p1, IM_COL32(25, 25, 30, 255));
    for (int k = 1; k < 3; ++k) {  // thirds of the range
        const float x = p0.x + width * float(k) / 3.0f;
        dl->AddLine(ImVec2(x, p0.y), ImVec2(x, p1.y), IM_COL32(70, 70, 80, 255));
    }
    const float halfY = p1.y - 0.5f * height;
    dl->AddLine(ImVec2(p0.x, halfY), ImVec2(p1.x, halfY), IM_COL32(70, 70, 80, 255));
    for (const Curve& c : curves) {
        std::vector<ImVec2> pts;
        for (int i = 0; i < kSamples; ++i)
            pts.emplace_back(p0.x + width * float(i) / float(kSamples - 1), p1.y - height * c.v[size_t(i)]);
        dl->AddPolyline(pts.data(), int(pts.size()), c.color, 0, c.thickness);
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::TextDisabled("angle of R to V: 0° to %.0f°; lines at ½", range);
    for (auto it = curves.rbegin(); it != curves.rend(); ++it) {
        const Curve& c = *it;
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::ColorConvertU32ToFloat4(c.color));
        ImGui::TextUnformatted(c.label.c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace shadelab::app
