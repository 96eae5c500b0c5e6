// The side panel: a fixed window down the left edge holding the sections, most used first.
#include "app/panels.h"

#include <imgui.h>

namespace shadelab::app {

std::array<float, 3> sidePanelBackground(const std::array<float, 3>& under) {
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    const float a = bg.w;
    return {bg.x * a + under[0] * (1.0f - a), bg.y * a + under[1] * (1.0f - a), bg.z * a + under[2] * (1.0f - a)};
}

void drawSidePanel(PanelContext& ctx, float width, float height, bool overlay) {
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    if (overlay) ImGui::SetNextWindowBgAlpha(0.8f);
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                             ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoBringToFrontOnFocus;
    // Beside the image the viewer has cleared the panel's rectangle to sidePanelBackground(): on llvmpipe the
    // blended background quad alone was 0.32 M of the 1 M fragments the panel costs at 1720x720.
    if (!overlay) flags |= ImGuiWindowFlags_NoBackground;
    ImGui::Begin("shadelab", nullptr, flags);
    ImGui::TextDisabled("shadelab view  %dx%d  %.1f ms/frame", ctx.renderWidth, ctx.renderHeight, ctx.frameMs);
    ImGui::BeginDisabled(ctx.undoSteps == 0);
    if (ImGui::Button("Undo")) ctx.services.undo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(ctx.redoSteps == 0);
    if (ImGui::Button("Redo")) ctx.services.redo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled("Ctrl+Z, Ctrl+Shift+Z");
    // The status line has a fixed height of two text lines, shown or not, so a message appearing or
    // expiring never moves the controls under the pointer (once, a click meant for Open saved).
    const float statusHeight = 2.0f * ImGui::GetTextLineHeightWithSpacing();
    ImGui::BeginChild("##status", ImVec2(0.0f, statusHeight), false, ImGuiWindowFlags_NoScrollbar);
    if (!ctx.status.empty()) {
        const ImVec4 color = ctx.statusError ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.55f, 0.9f, 0.55f, 1.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, color);
        ImGui::TextWrapped("%s", ctx.status.c_str());
        ImGui::PopStyleColor();
        if (ImGui::IsWindowHovered()) ImGui::SetTooltip("%s", ctx.status.c_str());
    }
    ImGui::EndChild();
    // What the file asked for that shadelab does not draw (textures, extensions): said where it is seen.
    if (!ctx.state.loadWarnings.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.35f, 1.0f));
        const bool open =
            ImGui::TreeNodeEx("##filenotes", ImGuiTreeNodeFlags_DefaultOpen,
                              "this file uses %zu thing(s) shadelab ignores", ctx.state.loadWarnings.size());
        if (open) {
            const std::string prefix = ctx.state.scenePath + ": ";
            for (const std::string& w : ctx.state.loadWarnings)
                ImGui::TextWrapped("%s", w.rfind(prefix, 0) == 0 ? w.c_str() + prefix.size() : w.c_str());
            ImGui::TreePop();
        }
        ImGui::PopStyleColor();
    }
    ImGui::Separator();
    if (ImGui::CollapsingHeader("Lighting model", ImGuiTreeNodeFlags_DefaultOpen)) drawLightingSection(ctx);
    if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) drawMaterialSection(ctx);
    if (ImGui::CollapsingHeader("Lights")) drawLightsSection(ctx);
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) drawViewSection(ctx);
    if (ImGui::CollapsingHeader("Raster shadows & reflections")) drawRasterSection(ctx);
    if (ImGui::CollapsingHeader("Scene")) drawSceneSection(ctx);
    if (ImGui::CollapsingHeader("Keys and mouse")) drawHelpSection();
    ImGui::End();
}

void drawHelpSection() {
    const char* rows[][2] = {
        {"left drag", "orbit about the target"},
        {"right / middle drag", "pan"},
        {"wheel", "zoom"},
        {"click", "select the object, probe that pixel"},
        {"1 .. 5", "ambient, +diffuse, +specular, +shadows, +reflections"},
        {"B", "Phong / Blinn-Phong"},
        {"P", "pbr / Phong"},
        {"V", "next view mode"},
        {"F / R", "frame all / reset camera"},
        {"F5", "reload shaders from shaders/"},
        {"Ctrl+Z", "undo the last edit (camera moves are not edits)"},
        {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
        {"Tab", "hide / show this panel"},
        {"C", "captions on the image on / off"},
        {"F11", "projector mode: the panel over a full-window image"},
        {"Esc", "clear probe and selection"},
        {"drop a file", "open .json, .gltf or .glb"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingStretchProp)) {
        for (const auto& r : rows) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextWrapped("%s", r[0]);
            ImGui::TableSetColumnIndex(1);
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
            ImGui::TextWrapped("%s", r[1]);
            ImGui::PopStyleColor();
        }
        ImGui::EndTable();
    }
    ImGui::TextWrapped(
        "Raster reflections: planes with kr > 0 are exact planar mirrors; reflective spheres and "
        "meshes use an environment cube rendered from the object's centre (one bounce of local "
        "shading and shadows, no self-reflection, parallax error for nearby objects). Compare "
        "with the reference (Split / Difference) to see the error.");
}

}  // namespace shadelab::app
