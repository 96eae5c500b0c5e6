// Material panel: pick an object, edit ma/md/ms/s/kr/kt/ior and the pbr fields or apply a classic preset, and
// watch the lobe plots follow (panels_lobe.cpp); the equivalent-exponent buttons switch model keeping the
// highlight's size (specular_lobe.h).
#include "app/panels.h"

#include "app/material_presets.h"
#include "app/specular_lobe.h"
#include "scene/material_json.h"

#include <imgui.h>

#include <cmath>
#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>

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

// Which of `group`'s fields are derived from the other model's (Material::derived), in one dim line.
void derivedNote(const Material& m, uint8_t group, const char* how) {
    if (!(m.derived & group)) return;
    std::string names;
    for (const auto& entry : kMaterialFieldNames)
        if (m.derived & group & entry.value) names += (names.empty() ? "" : ", ") + std::string(entry.name);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("derived: %s (%s)", names.c_str(), how);
    ImGui::PopStyleColor();
}

// The material's own shading model, or the scene's (the first entry): side by side in one picture.
bool modelCombo(ShadingModel sceneModel, Material& m) {
    const std::string sceneEntry = std::string("the scene's (") + toString(sceneModel) + ")";
    const char* current = m.model ? toString(*m.model) : sceneEntry.c_str();
    bool changed = false;
    if (ImGui::BeginCombo("model", current)) {
        if (ImGui::Selectable(sceneEntry.c_str(), !m.model)) {
            changed = m.model.has_value();
            m.model.reset();
        }
        for (ShadingModel model :
             {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr, ShadingModel::Disney})
            if (ImGui::Selectable(toString(model), m.model == model)) {
                changed = m.model != model;
                m.model = model;
            }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "the model this object is shaded with, in every renderer; the scene's model (Lighting) "
            "shades the objects that name none");
    return changed;
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
    bool changed = modelCombo(s.scene.model, m);
    const ImGuiColorEditFlags colorFlags = ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR;
    derivedNote(m, kPhongFields, "from baseColor, metallic, roughness; editing one sets it");
    changed |= ImGui::ColorEdit3("ma  ambient", glm::value_ptr(m.ma), colorFlags);
    changed |= ImGui::ColorEdit3("md  diffuse", glm::value_ptr(m.md), colorFlags);
    changed |= ImGui::ColorEdit3("ms  specular", glm::value_ptr(m.ms), colorFlags);
    float shininess = m.s;
    if (ImGui::SliderFloat("s  shininess", &shininess, 1.0f, 2048.0f, "%.1f", ImGuiSliderFlags_Logarithmic))
        setShininess(s, s.selected, shininess);
    changed |= ImGui::ColorEdit3("kr  reflect", glm::value_ptr(m.kr), colorFlags);
    changed |= ImGui::ColorEdit3("kt  transmit", glm::value_ptr(m.kt), colorFlags);
    changed |= ImGui::SliderFloat("ior", &m.ior, 1.0f, 3.0f, "%.3f");
    // Radiance, not a reflectance: values above 1 are the point (an area light for the path tracer).
    if (ImGui::DragFloat3("emission", glm::value_ptr(m.emission), 0.05f, 0.0f, 1000.0f, "%.2f")) {
        m.emission = glm::max(m.emission, glm::vec3(0.0f));
        changed = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "emitted radiance: an area light under the path tracer (Global mode); the rasterizer and "
            "the Whitted reference add it to the object's colour");
    ImGui::TextDisabled("pbr: glTF metallic-roughness");
    derivedNote(m, kPbrFields, "from md and s; editing one sets it");
    changed |= ImGui::ColorEdit3("baseColor", glm::value_ptr(m.baseColor), ImGuiColorEditFlags_Float);
    changed |= ImGui::SliderFloat("metallic", &m.metallic, 0.0f, 1.0f, "%.2f");
    changed |= ImGui::SliderFloat("roughness", &m.roughness, 0.0f, 1.0f, "%.3f");
    // The principled BRDF's own eight, shown where they shade something (its baseColor, metallic and roughness
    // are the pbr fields above).
    if (modelOf(m, s.scene.model) == ShadingModel::Disney) {
        ImGui::TextDisabled("disney: Burley 2012's principled BRDF");
        for (const DisneyField& field : kDisneyFields)
            changed |= ImGui::SliderFloat(field.name, &(m.disney.*field.member), 0.0f, 1.0f, "%.2f");
    }
    // glTF's layers, shaded under pbr (disney has its own clearcoat and sheen above).
    if (modelOf(m, s.scene.model) == ShadingModel::Pbr) {
        ImGui::TextDisabled("pbr: glTF clear coat (KHR_materials_clearcoat)");
        changed |= ImGui::SliderFloat("clearcoat", &m.clearcoat.factor, 0.0f, 1.0f, "%.2f");
        changed |= ImGui::SliderFloat("coat roughness", &m.clearcoat.roughness, 0.0f, 1.0f, "%.3f");
        // glTF's specular layer: the dielectric's lobe weight and F0 tint (its F0 from ior, above).
        ImGui::TextDisabled("pbr: glTF specular (KHR_materials_specular), F0 from ior");
        changed |= ImGui::SliderFloat("specular weight", &m.specular.factor, 0.0f, 1.0f, "%.2f");
        changed |= ImGui::ColorEdit3("specular color", glm::value_ptr(m.specular.color), colorFlags);
        m.specular.color = glm::clamp(m.specular.color, 0.0f, kMaxSpecularColor);
        // glTF's sheen: the fibres' colour (black: none) and roughness.
        ImGui::TextDisabled("pbr: glTF sheen (KHR_materials_sheen)");
        changed |= ImGui::ColorEdit3("sheen color", glm::value_ptr(m.sheen.color), colorFlags);
        m.sheen.color = glm::clamp(m.sheen.color, 0.0f, 1.0f);
        changed |= ImGui::SliderFloat("sheen roughness", &m.sheen.roughness, 0.0f, 1.0f, "%.2f");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("velvet, cloth, dust: a rim of light at grazing angles; the colour black turns it off");
        // glTF's anisotropy: the highlight stretched along a direction turned from the tangent.
        ImGui::TextDisabled("pbr: glTF anisotropy (KHR_materials_anisotropy)");
        changed |= ImGui::SliderFloat("anisotropy", &m.anisotropy.strength, 0.0f, 1.0f, "%.2f");
        changed |= ImGui::SliderAngle("aniso rotation", &m.anisotropy.rotation, -180.0f, 180.0f);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the direction the highlight stretches along, turned from the sphere's parallels");
        // glTF's transmission and volume: light through the surface, and the medium inside it.
        ImGui::TextDisabled("pbr: glTF transmission, volume (KHR_materials_*)");
        changed |= ImGui::SliderFloat("transmission", &m.transmission.factor, 0.0f, 1.0f, "%.2f");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the share of the diffuse light that passes through, tinted by the base colour");
        changed |=
            ImGui::SliderFloat("thickness", &m.volume.thickness, 0.0f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("0: a thin wall, light passes straight through; more: a solid that refracts by ior");
        // 0 on the slider is an infinite distance: a medium that absorbs nothing.
        float distance = std::isfinite(m.volume.attenuationDistance) ? m.volume.attenuationDistance : 0.0f;
        if (ImGui::SliderFloat("atten distance", &distance, 0.0f, 100.0f, distance > 0.0f ? "%.2f" : "none",
                               ImGuiSliderFlags_Logarithmic)) {
            m.volume.attenuationDistance = distance > 0.0f ? distance : std::numeric_limits<float>::infinity();
            changed = true;
        }
        changed |= ImGui::ColorEdit3("atten color", glm::value_ptr(m.volume.attenuationColor), colorFlags);
        m.volume.attenuationColor = glm::clamp(m.volume.attenuationColor, 0.0f, 1.0f);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("what is left of white light after the attenuation distance inside");
    }
    if (changed) {
        m.s = objectMaterial(s.scene, s.selected).s;  // the slider above already applied its own change
        setObjectMaterial(s, s.selected, m);
    }

    if (whiteFurnaceOn(s)) ImGui::TextDisabled("White furnace on: edits are dropped when it is turned off.");

    // The lobe plots use s as a Phong exponent: under Blinn-Phong it is converted by the equivalence rule.
    const float s2 = objectMaterial(s.scene, s.selected).s;
    const float phongS = s.scene.model == ShadingModel::BlinnPhong ? equivalentPhongExponent(s2) : s2;
    drawLobePlots(ctx, objectMaterial(s.scene, s.selected), phongS);

    // The equivalent exponents belong to the lecture's models; pbr and disney read roughness, not s.
    if (isPhysicallyBased(s.scene.model)) return;
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

}  // namespace shadelab::app
