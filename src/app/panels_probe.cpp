// Probe window (teaching): at the clicked point, N, V, P and for each light L, R, H, the dot products and
// every term, then the totals for Phong and Blinn-Phong side by side. The arrows are arrow_overlay.cpp.
#include "app/panels.h"

#include "image/encode.h"

#include <imgui.h>

#include <string>

namespace shadelab::app {
namespace {

void rgbCell(const glm::vec3& v) { ImGui::Text("%.3f %.3f %.3f", v.r, v.g, v.b); }

void rowLabel(const char* label) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(label);
}

void lightTable(const ProbeResult& p, bool shadows) {
    const int columns = 1 + int(p.lights.size());
    if (!ImGui::BeginTable("lights", columns, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV)) return;
    ImGui::TableSetupColumn("");
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const std::string name = "L" + std::to_string(i + 1) + " " + p.lights[i].name;
        ImGui::TableSetupColumn(name.c_str());
    }
    ImGui::TableHeadersRow();
    auto scalarRow = [&](const char* label, float ProbeLight::*field) {
        rowLabel(label);
        for (size_t i = 0; i < p.lights.size(); ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            ImGui::Text("%+.4f", p.lights[i].*field);
        }
    };
    auto rgbRow = [&](const char* label, glm::vec3 ProbeLight::*field) {
        rowLabel(label);
        for (size_t i = 0; i < p.lights.size(); ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            rgbCell(p.lights[i].*field);
        }
    };
    scalarRow("N·L", &ProbeLight::NoL);
    scalarRow("R·V", &ProbeLight::RoV);
    scalarRow("N·H", &ProbeLight::NoH);
    scalarRow("(R·V)^s", &ProbeLight::specPhong);
    scalarRow("(N·H)^s", &ProbeLight::specBlinn);
    rgbRow("Il", &ProbeLight::Il);
    if (shadows) {
        rowLabel("visible");
        for (size_t i = 0; i < p.lights.size(); ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            const ProbeLight& l = p.lights[i];
            ImGui::TextUnformatted(l.NoL <= 0.0f ? "faces away" : l.visibility > 0.0f ? "yes" : "no: in shadow");
        }
    }
    rgbRow("diffuse", &ProbeLight::diffuse);
    rgbRow("spec Phong", &ProbeLight::specularPhong);
    rgbRow("spec Blinn", &ProbeLight::specularBlinn);
    ImGui::EndTable();
}

void totalsTable(const ProbeResult& p, ShadingModel current, Encoding encoding) {
    glm::vec3 diffuse(0.0f), specPhong(0.0f), specBlinn(0.0f);
    for (const ProbeLight& l : p.lights) {
        diffuse += l.diffuse;
        specPhong += l.specularPhong;
        specBlinn += l.specularBlinn;
    }
    if (!ImGui::BeginTable("totals", 3, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV)) return;
    // Under pbr neither column is what the image shows (the probe has no pbr column yet).
    const bool phong = current == ShadingModel::Phong, blinn = current == ShadingModel::BlinnPhong;
    ImGui::TableSetupColumn("");
    ImGui::TableSetupColumn(phong ? "Phong (shown)" : "Phong");
    ImGui::TableSetupColumn(blinn ? "Blinn-Phong (shown)" : "Blinn-Phong");
    ImGui::TableHeadersRow();
    rowLabel("Ia ma");
    ImGui::TableSetColumnIndex(1);
    rgbCell(p.ambient);
    ImGui::TableSetColumnIndex(2);
    rgbCell(p.ambient);
    rowLabel("sum diffuse");
    ImGui::TableSetColumnIndex(1);
    rgbCell(diffuse);
    ImGui::TableSetColumnIndex(2);
    rgbCell(diffuse);
    rowLabel("sum specular");
    ImGui::TableSetColumnIndex(1);
    rgbCell(specPhong);
    ImGui::TableSetColumnIndex(2);
    rgbCell(specBlinn);
    rowLabel("I (switches)");
    ImGui::TableSetColumnIndex(1);
    rgbCell(p.totalPhong);
    ImGui::TableSetColumnIndex(2);
    rgbCell(p.totalBlinn);
    rowLabel("8-bit");
    for (int c = 0; c < 2; ++c) {
        const glm::vec3 v = c == 0 ? p.totalPhong : p.totalBlinn;
        ImGui::TableSetColumnIndex(c + 1);
        ImGui::Text("%3d %3d %3d", encodeChannel(v.r, encoding), encodeChannel(v.g, encoding),
                    encodeChannel(v.b, encoding));
    }
    ImGui::EndTable();
}

}  // namespace

void drawProbeWindow(PanelContext& ctx, float x, float top, bool probeOnRight) {
    const ProbeResult& p = *ctx.probe;
    ImGui::SetNextWindowPos(ImVec2(x, top), ImGuiCond_Always, ImVec2(probeOnRight ? 1.0f : 0.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
    if (!ImGui::Begin("Probe###probe", nullptr, flags)) {
        ImGui::End();
        return;
    }
    ImGuiIO& io = ImGui::GetIO();
    if (io.Fonts->Fonts.Size > 1) ImGui::PushFont(io.Fonts->Fonts[1]);
    ImGui::Text("pixel (%d, %d): %s", p.x, p.y, p.hit ? p.label.c_str() : "background");
    if (p.hit) {
        ImGui::Text("P %+.3f %+.3f %+.3f", p.P.x, p.P.y, p.P.z);
        ImGui::Text("N %+.3f %+.3f %+.3f", p.N.x, p.N.y, p.N.z);
        ImGui::Text("V %+.3f %+.3f %+.3f", p.V.x, p.V.y, p.V.z);
        ImGui::Text("s %.1f   ms %.2f %.2f %.2f", p.material.s, p.material.ms.r, p.material.ms.g, p.material.ms.b);
        const bool shadows = ctx.state.scene.terms.shadows;
        if (!p.lights.empty()) lightTable(p, shadows);
        totalsTable(p, ctx.state.scene.model, ctx.state.encoding);
        ImGui::TextDisabled(shadows ? "visible: the reference's shadow ray; no reflections"
                                    : "local terms, as both renderers compute them");
    }
    if (io.Fonts->Fonts.Size > 1) ImGui::PopFont();
    ctx.fields.probeWindowWidth = ImGui::GetWindowWidth();
    ImGui::End();
}

}  // namespace shadelab::app
