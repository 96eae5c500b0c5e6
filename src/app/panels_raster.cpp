// Raster shadows & reflections panel: the rasterizer's own settings (scene.raster, raster_settings.h):
// shadow-map size, depth and normal bias, PCF, and the environment-cube size of reflective spheres and
// meshes. The reference ignores them, so they are what to tune against it in Split or Difference.
#include "app/panels.h"

#include "raster/raster_limits.h"

#include <imgui.h>

#include <initializer_list>
#include <string>

namespace shadelab::app {
namespace {

// A combo of sizes in texels; 0 reads `autoLabel`. A size from the file that is not a choice is shown too.
bool sizeCombo(const char* label, int& size, std::initializer_list<int> choices, const std::string& autoLabel) {
    auto name = [&](int v) { return v == 0 ? autoLabel : std::to_string(v); };
    bool changed = false;
    if (ImGui::BeginCombo(label, name(size).c_str())) {
        for (int v : choices) {
            if (ImGui::Selectable(name(v).c_str(), v == size) && v != size) {
                size = v;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

}  // namespace

void drawRasterSection(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    RasterSettings r = s.scene.raster;
    const int autoSize = raster::shadowMapSizeFor(RasterSettings{}, ctx.renderWidth, ctx.renderHeight);
    bool changed =
        sizeCombo("shadow map", r.shadowMapSize, {0, 512, 1024, 2048, 4096}, "auto (" + std::to_string(autoSize) + ")");
    changed |= ImGui::SliderFloat("depth bias", &r.depthBias, 0.0f, 8.0f, "%.2f texels");
    changed |= ImGui::SliderFloat("normal bias", &r.normalBias, 0.0f, 8.0f, "%.2f texels");
    changed |= ImGui::Checkbox("PCF 3x3 (soft edges; the reference's are hard)", &r.pcf);
    changed |= sizeCombo("reflection cube", r.reflectionCubeSize, {32, 64, 128, 256, 512}, "");
    if (changed) setRasterSettings(s, r);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped(
        "Too little bias: acne; too much: shadows detach from their casters. The cube size is "
        "texels per face, one cube per reflective sphere or mesh.");
    ImGui::PopStyleColor();
}

}  // namespace shadelab::app
