// Scene panel (open, save, screenshot, shader reload with its error) and the lesson window that shows
// the scene file's title and notes over the image.
#include "app/panels.h"
#include "app/save_policy.h"
#include "scene/stage.h"

#include <imgui.h>
#include <imgui_stdlib.h>
#include <filesystem>

namespace shadelab::app {

std::string defaultSavePath(const std::string& scenePath) {
    if (scenePath.empty()) return "scene-saved.json";
    const std::filesystem::path p(scenePath);
    return (p.parent_path() / (p.stem().string() + "-saved.json")).string();
}

// Recent scenes and the scenes and folders of one folder (file_list.h), one click to open.
void drawFileList(PanelContext& ctx) {
    UiFields& f = ctx.fields;
    if (!f.recent.empty() && ImGui::TreeNode("recent")) {
        for (const std::string& path : f.recent)
            if (ImGui::Selectable(path.c_str())) {
                ctx.services.openScene(path);
                break;
            }
        ImGui::TreePop();
    }
    if (!ImGui::TreeNode("files")) return;
    if (f.files.folder.empty()) {
        const std::filesystem::path scene(ctx.state.scenePath);
        f.files = listSceneFolder(ctx.state.scenePath.empty() ? "." : scene.parent_path().string());
    }
    ImGui::TextDisabled("%s", f.files.folder.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("refresh")) f.files = listSceneFolder(f.files.folder);
    if (!f.files.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", f.files.error.c_str());
    ImGui::BeginChild("##files", ImVec2(0.0f, 8.0f * ImGui::GetTextLineHeightWithSpacing()), true);
    std::string next;
    for (const FileEntry& e : f.files.entries) {
        if (e.folder) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.6f, 0.8f, 1.0f, 1.0f));
        if (ImGui::Selectable(e.name.c_str(), e.path == ctx.state.scenePath)) next = e.path;
        if (e.folder) ImGui::PopStyleColor();
        if (!next.empty()) {
            if (e.folder)
                f.files = listSceneFolder(next);
            else
                ctx.services.openScene(next);
            break;
        }
    }
    if (f.files.truncated) ImGui::TextDisabled("(the first %zu entries)", kMaxFileListEntries);
    ImGui::EndChild();
    ImGui::TreePop();
}

void drawSceneSection(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    ImGui::TextDisabled("%s", s.scenePath.empty() ? "(no file)" : s.scenePath.c_str());
    ImGui::InputText("##open", &ctx.fields.openPath);
    ImGui::SameLine();
    if (ImGui::Button("Open")) ctx.services.openScene(ctx.fields.openPath);
    ImGui::TextDisabled(".json, .gltf or .glb; or drop a file on the window");
    drawFileList(ctx);
    ImGui::InputText("##save", &ctx.fields.savePath);
    ImGui::SameLine();
    if (ImGui::Button("Save JSON")) {
        // Never silently replace a file: an existing one waits for the question below (save_policy.h).
        std::error_code ec;
        if (saveRefusal(ctx.fields.savePath).empty() && std::filesystem::exists(ctx.fields.savePath, ec)) {
            ctx.fields.confirmReplace = ctx.fields.savePath;
            ImGui::OpenPopup("Replace file?");
        } else {
            ctx.services.saveScene(ctx.fields.savePath);
        }
    }
    if (ImGui::BeginPopupModal("Replace file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s already exists.", ctx.fields.confirmReplace.c_str());
        ImGui::TextDisabled("Saving replaces it with the scene as it is now.");
        if (ImGui::Button("Replace")) {
            ctx.services.saveScene(ctx.fields.confirmReplace);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGuiKey_Escape)) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    bool stage = hasStage(s.scene);
    if (ImGui::Checkbox("stage: floor, soft background, shadows", &stage)) setStageOn(s, stage);
    ImGui::InputText("##shot", &ctx.fields.screenshotPath);
    ImGui::SameLine();
    if (ImGui::Button("Screenshot")) ctx.services.screenshot(ctx.fields.screenshotPath);
    ImGui::TextDisabled("the rendered image without UI, as 'shadelab render' gives it");
    if (ImGui::Button("Reload shaders (F5)")) ctx.services.reloadShaders("");
    if (!ctx.shaderError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", ctx.shaderError.c_str());
        ImGui::PopStyleColor();
        ImGui::TextDisabled("still running the last good shaders");
    }
}

void drawLessonWindow(PanelContext& ctx, float x, float bottom, float width, bool folded) {
    const Scene& scene = ctx.state.scene;
    if (scene.title.empty() && scene.notes.empty()) return;
    ImGui::SetNextWindowPos(ImVec2(x, bottom), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, 1e6f));
    ImGui::SetNextWindowBgAlpha(0.72f);
    // Fold and unfold only when the probe appears or goes; in between the user's choice stands.
    if (folded != ctx.fields.lessonFolded) ImGui::SetNextWindowCollapsed(folded, ImGuiCond_Always);
    ctx.fields.lessonFolded = folded;
    const std::string title = (scene.title.empty() ? std::string("Lesson") : scene.title) + "###lesson";
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
    if (ImGui::Begin(title.c_str(), nullptr, flags) && !scene.notes.empty())
        ImGui::TextWrapped("%s", scene.notes.c_str());
    ImGui::End();
}

}  // namespace shadelab::app
