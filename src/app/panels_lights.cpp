// Lights panel: the ambient intensity Ia, then each light (type, position and/or direction, a spot's cone,
// colour and a scalar intensity, attenuation and range), with add and remove.
#include "app/panels.h"

#include <imgui.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <string>

namespace shadelab::app {

void drawLightsSection(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    glm::vec3 Ia = s.scene.ambient;
    if (ImGui::ColorEdit3("Ia  ambient", glm::value_ptr(Ia), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR))
        setAmbient(s, Ia);
    int remove = -1;
    for (size_t i = 0; i < s.scene.lights.size(); ++i) {
        Light l = s.scene.lights[i];
        ImGui::PushID(int(i));
        const std::string title =
            "L" + std::to_string(i + 1) + "  " + (l.name.empty() ? "light" : l.name) + "  (" + toString(l.type) + ")";
        const bool open = ImGui::TreeNodeEx("light", ImGuiTreeNodeFlags_DefaultOpen, "%s", title.c_str());
        if (open) {
            bool changed = false;
            int type = int(l.type);
            bool typeChanged = false;
            bool first = true;
            for (const EnumName<LightType>& t : kLightTypeNames) {
                if (t.alias) continue;
                if (!first) ImGui::SameLine();
                first = false;
                typeChanged |= ImGui::RadioButton(t.name, &type, int(t.value));
            }
            if (typeChanged) {
                l.type = LightType(type);
                changed = true;
            }
            if (l.positional()) {
                changed |= ImGui::DragFloat3("position", glm::value_ptr(l.position), 0.05f);
                changed |= ImGui::DragFloat3("attenuation", glm::value_ptr(l.attenuation), 0.01f, 0.0f, 100.0f);
            }
            if (l.type != LightType::Point &&
                ImGui::DragFloat3("direction", glm::value_ptr(l.direction), 0.01f, -1.0f, 1.0f)) {
                if (glm::length(l.direction) > 1e-4f) l.direction = glm::normalize(l.direction);
                changed = true;
            }
            if (l.type == LightType::Spot) {
                // Angles in degrees on screen, radians in the scene; the inner cone never passes the outer one.
                const float maxDegrees = 90.0f;
                if (ImGui::SliderAngle("inner cone", &l.innerConeAngle, 0.0f, maxDegrees)) {
                    l.innerConeAngle = std::clamp(l.innerConeAngle, 0.0f, l.outerConeAngle);
                    changed = true;
                }
                if (ImGui::SliderAngle("outer cone", &l.outerConeAngle, 0.0f, maxDegrees)) {
                    l.outerConeAngle = std::clamp(l.outerConeAngle, 0.0f, kMaxConeAngle);
                    l.innerConeAngle = std::min(l.innerConeAngle, l.outerConeAngle);
                    changed = true;
                }
            }
            if (l.positional()) {
                // 0 is no range; a positive range ends the light there (KHR_lights_punctual's window).
                if (ImGui::DragFloat("range", &l.range, 0.05f, 0.0f, 1e4f, l.range > 0.0f ? "%.2f" : "none")) {
                    l.range = std::max(l.range, 0.0f);
                    changed = true;
                }
            }
            // Colour and intensity are edited apart: the split last edited here is kept while it still gives
            // this light's Il, so a darker colour stays a darker colour instead of being renormalised into a
            // lower intensity (picking a colour once set the intensity to 0.935).
            std::vector<ColorIntensity>& splits = ctx.fields.lightSplits;
            ColorIntensity ci = splitIntensity(l.color);
            if (i < splits.size() && joinIntensity(splits[i]) == l.color) ci = splits[i];
            const bool colorChanged = ImGui::ColorEdit3("colour", glm::value_ptr(ci.color), ImGuiColorEditFlags_Float);
            const bool intensityChanged = ImGui::DragFloat("intensity", &ci.intensity, 0.01f, 0.0f, 100.0f, "%.3f");
            if (colorChanged || intensityChanged) {
                l.color = joinIntensity(ci);
                if (splits.size() <= i) splits.resize(i + 1);
                splits[i] = ci;
                changed = true;
            }
            if (ImGui::SmallButton("remove")) remove = int(i);
            if (changed) setLight(s, int(i), l);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (remove >= 0) removeLight(s, remove);
    const bool full = s.scene.lights.size() >= size_t(kMaxLights);
    if (full) ImGui::BeginDisabled();
    if (ImGui::Button("add point light")) addLight(s, LightType::Point);
    ImGui::SameLine();
    if (ImGui::Button("add directional light")) addLight(s, LightType::Directional);
    ImGui::SameLine();
    if (ImGui::Button("add spot light")) addLight(s, LightType::Spot);
    if (full) ImGui::EndDisabled();
}

}  // namespace shadelab::app
