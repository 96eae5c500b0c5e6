// Probe window (teaching): at the clicked point, N, V, P and for each light L, R, H, the dot products and
// every term of the current model (under pbr: D, V, F and the diffuse and specular parts), then the totals
// for Phong, Blinn-Phong and pbr side by side, the shown one marked. The arrows are arrow_overlay.cpp.
#include "app/panels.h"

#include "app/arrow_overlay.h"
#include "app/probe_diagram.h"
#include "image/encode.h"

#include <imgui.h>
#include <imgui_internal.h>  // MovingWindow: whether the user is dragging the probe window

#include <algorithm>
#include <cstdio>
#include <string>

namespace shadelab::app {
namespace {

void rgbCell(const glm::vec3& v) { ImGui::Text("%.3f %.3f %.3f", v.r, v.g, v.b); }

void rowLabel(const char* label) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(label);
}

void lightTable(const ProbeResult& p, bool shadows, ShadingModel shown) {
    const bool disney = shown == ShadingModel::Disney, pbr = isPhysicallyBased(shown);
    const int columns = 1 + int(p.lights.size());
    if (!ImGui::BeginTable("lights", columns, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV)) return;
    ImGui::TableSetupColumn("");
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const std::string name = "L" + std::to_string(i + 1) + " " + p.lights[i].name;
        ImGui::TableSetupColumn(name.c_str());
    }
    ImGui::TableHeadersRow();
    // `litOnly`: the BRDF's factors mean nothing where the light is behind the surface (N·L <= 0).
    auto scalarRow = [&](const char* label, float ProbeLight::*field, bool litOnly = false) {
        rowLabel(label);
        for (size_t i = 0; i < p.lights.size(); ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            if (litOnly && p.lights[i].NoL <= 0.0f)
                ImGui::TextDisabled("-");
            else
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
    auto vectorRow = [&](const char* label, glm::vec3 ProbeLight::*field) {
        rowLabel(label);
        for (size_t i = 0; i < p.lights.size(); ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            const glm::vec3& v = p.lights[i].*field;
            ImGui::Text("%+.3f %+.3f %+.3f", v.x, v.y, v.z);
        }
    };
    vectorRow("L", &ProbeLight::L);
    vectorRow("R", &ProbeLight::R);
    vectorRow("H", &ProbeLight::H);
    scalarRow("N·L", &ProbeLight::NoL);
    if (!pbr) scalarRow("R·V", &ProbeLight::RoV);
    scalarRow("N·H", &ProbeLight::NoH);
    if (shown == ShadingModel::Pbr) {
        // glTF 2.0 Appendix B: f_spec = D · V · F, with V = G2 / (4 N·L N·V) (lighting.glsl).
        scalarRow("D  GGX", &ProbeLight::D, true);
        scalarRow("V  Smith", &ProbeLight::Vis, true);
        rgbRow("F  Schlick", &ProbeLight::F);
    } else if (!disney) {
        scalarRow("(R·V)^s", &ProbeLight::specPhong);
        scalarRow("(N·H)^s", &ProbeLight::specBlinn);
    }
    rgbRow("Il", &ProbeLight::Il);
    if (shadows) {
        rowLabel("visible");
        for (size_t i = 0; i < p.lights.size(); ++i) {
            ImGui::TableSetColumnIndex(int(i) + 1);
            const ProbeLight& l = p.lights[i];
            // A light behind a transmitting pbr surface shines through it when nothing blocks it.
            const bool through = shown == ShadingModel::Pbr && p.material.transmission.on() && l.NoL < 0.0f;
            ImGui::TextUnformatted(through         ? (l.visibility > 0.0f ? "behind: through" : "behind, in shadow")
                                   : l.NoL <= 0.0f ? "faces away"
                                   : l.visibility > 0.0f ? "yes"
                                                         : "no: in shadow");
        }
    }
    if (disney) {
        // Burley 2012: each lobe's part of this light's term (they sum to it).
        rgbRow("diffuse+subsurf", &ProbeLight::diffuseDisney);
        rgbRow("sheen", &ProbeLight::sheenDisney);
        rgbRow("spec GTR2 aniso", &ProbeLight::specularDisney);
        rgbRow("clearcoat GTR1", &ProbeLight::clearcoatDisney);
    } else if (pbr) {
        rgbRow("diffuse (1-F)", &ProbeLight::diffusePbr);
        rgbRow("spec pi·DVF·N·L", &ProbeLight::specularPbr);
        if (p.material.transmission.on()) rgbRow("through (transmission)", &ProbeLight::transmissionPbr);
        if (p.material.sheen.on()) rgbRow("sheen (Charlie)", &ProbeLight::sheenPbr);
        if (p.material.clearcoat.factor > 0.0f) rgbRow("clear coat", &ProbeLight::clearcoatPbr);
    } else {
        rgbRow("diffuse", &ProbeLight::diffuse);
        rgbRow("spec Phong", &ProbeLight::specularPhong);
        rgbRow("spec Blinn", &ProbeLight::specularBlinn);
    }
    ImGui::EndTable();
}

void totalsTable(const ProbeResult& p, ShadingModel current, Encoding encoding) {
    struct Column {
        const char* name;
        ShadingModel model;
        glm::vec3 diffuse{0.0f}, specular{0.0f}, total{0.0f};
    };
    Column cols[] = {{"Phong", ShadingModel::Phong},
                     {"Blinn-Phong", ShadingModel::BlinnPhong},
                     {"pbr", ShadingModel::Pbr},
                     {"disney", ShadingModel::Disney}};
    for (const ProbeLight& l : p.lights) {
        cols[0].diffuse += l.diffuse, cols[1].diffuse += l.diffuse,
            cols[2].diffuse += l.diffusePbr + l.sheenPbr + l.transmissionPbr;
        cols[0].specular += l.specularPhong, cols[1].specular += l.specularBlinn,
            cols[2].specular += l.specularPbr + l.clearcoatPbr;
        cols[3].diffuse += l.diffuseDisney + l.sheenDisney;
        cols[3].specular += l.specularDisney + l.clearcoatDisney;
    }
    cols[0].total = p.totalPhong, cols[1].total = p.totalBlinn, cols[2].total = p.totalPbr;
    cols[3].total = p.totalDisney;
    if (!ImGui::BeginTable("totals", 5, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV)) return;
    ImGui::TableSetupColumn("");
    for (const Column& c : cols) {
        const std::string name = std::string(c.name) + (c.model == current ? " (shown)" : "");
        ImGui::TableSetupColumn(name.c_str());
    }
    ImGui::TableHeadersRow();
    auto row = [&](const char* label, glm::vec3 Column::*field) {
        rowLabel(label);
        for (int c = 0; c < 4; ++c) {
            ImGui::TableSetColumnIndex(c + 1);
            if (cols[c].model == current) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, IM_COL32(60, 80, 120, 160));
            rgbCell(cols[c].*field);
        }
    };
    rowLabel("Ia ma");
    for (int c = 0; c < 4; ++c) {
        ImGui::TableSetColumnIndex(c + 1);
        if (cols[c].model == current) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, IM_COL32(60, 80, 120, 160));
        rgbCell(p.ambient);
    }
    row("sum diffuse", &Column::diffuse);
    row("sum specular", &Column::specular);
    row(p.unlit ? "I (unlit colour)" : "I (switches)", &Column::total);
    rowLabel("8-bit");
    for (int c = 0; c < 4; ++c) {
        const glm::vec3 v = cols[c].total;
        ImGui::TableSetColumnIndex(c + 1);
        if (cols[c].model == current) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, IM_COL32(60, 80, 120, 160));
        ImGui::Text("%3d %3d %3d", encodeChannel(v.r, encoding), encodeChannel(v.g, encoding),
                    encodeChannel(v.b, encoding));
    }
    ImGui::EndTable();
}

// The display colour the 3D overlay gives a vector (arrow_overlay.h), by its letter.
glm::vec3 arrowColor(const ProbeResult& p, const std::string& name) {
    for (const Arrow& a : probeArrows(p))
        if (!a.label.empty() && a.label[0] == name[0]) return a.color;
    return glm::vec3(1.0f);
}

// The plane-of-incidence figure (probe_diagram.h): N up, L left, R right, V and H where they fall, each at
// its true angle from N and full length, with the angles written at the tips.
void diagram(const ProbeResult& p, float uiScale) {
    const ProbeDiagram d = probeDiagram(p, 0);
    if (d.arrows.empty()) return;
    const float radius = 62.0f * uiScale, pad = 18.0f * uiScale;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 base(origin.x + radius + pad + 30.0f * uiScale, origin.y + radius + pad);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddLine(ImVec2(base.x - radius - pad, base.y), ImVec2(base.x + radius + pad, base.y),
                IM_COL32(150, 150, 150, 255),
                2.0f * uiScale);  // the surface
    dl->AddCircle(base, radius, IM_COL32(90, 90, 90, 160), 48, 1.0f);
    for (const DiagramArrow& a : d.arrows) {
        const glm::vec3 c = arrowColor(p, a.name);
        const ImU32 col = ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
        const ImVec2 tip(base.x + a.dir.x * radius, base.y - a.dir.y * radius);
        dl->AddLine(base, tip, col, 2.5f * uiScale);
        dl->AddCircleFilled(tip, 3.5f * uiScale, col);
        char text[32];
        if (a.name == "N")
            std::snprintf(text, sizeof text, "N");
        else
            std::snprintf(text, sizeof text, "%s %.0f\xc2\xb0", a.name.c_str(), a.angleDeg);
        const ImVec2 at(tip.x + a.dir.x * 8.0f * uiScale - (a.dir.x < 0.0f ? 40.0f * uiScale : 0.0f),
                        tip.y - a.dir.y * 8.0f * uiScale - 7.0f * uiScale);
        dl->AddText(at, col, text);
    }
    ImGui::Dummy(ImVec2(2.0f * (radius + pad) + 60.0f * uiScale, radius + pad + 6.0f * uiScale));
    ImGui::TextDisabled("angles from N; V is %.0f\xc2\xb0 out of the plane of N and L%s", d.vOutOfPlaneDeg,
                        d.lit ? "" : "; L is below the surface (unlit)");
}

// The ray tree the tracer followed from this pixel (drawn in the view), a ray per line; a click on one
// writes its intersection as the lecture solves it, with the tracer's numbers.
void rayTreeSection(PanelContext& ctx) {
    bool on = ctx.state.probe.rayTree;
    if (ImGui::Checkbox("ray tree in the view (T)", &on)) setRayTree(ctx.state, on);
    if (!ctx.rayTree) return;
    const RayTreePanel& t = *ctx.rayTree;
    ImGui::SameLine();
    ImGui::TextDisabled("%zu rays; traced from the eye of the click", t.rays.size());
    const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
    const float listHeight = std::min(float(t.rays.size()), 8.0f) * rowHeight + 4.0f;
    if (ImGui::BeginChild("rays", ImVec2(0.0f, listHeight), false)) {
        for (size_t k = 0; k < t.rays.size(); ++k)
            if (ImGui::Selectable(t.rays[k].c_str(), ctx.fields.rayTreeRay == int(k))) ctx.fields.rayTreeRay = int(k);
    }
    ImGui::EndChild();
    const size_t chosen = size_t(std::clamp(ctx.fields.rayTreeRay, 0, std::max(int(t.algebra.size()) - 1, 0)));
    if (chosen < t.algebra.size())
        for (const std::string& line : t.algebra[chosen]) ImGui::TextUnformatted(line.c_str());
}

}  // namespace

void drawProbeWindow(PanelContext& ctx, float x, float y, bool room) {
    const ProbeResult& p = *ctx.probe;
    // Beside the point, following it as the camera moves, until the user drags the window by its title bar
    // (then it stays where it was put, until the probe is cleared); the title bar's arrow folds it.
    if (!ctx.fields.probeWindowMoved) ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    if (room != ctx.fields.probeWindowHadRoom) ImGui::SetNextWindowCollapsed(!room, ImGuiCond_Always);
    ctx.fields.probeWindowHadRoom = room;
    ImGui::SetNextWindowBgAlpha(0.8f);
    const ImGuiWindowFlags flags =
        ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
    if (!ImGui::Begin("Probe###probe", nullptr, flags)) {
        ImGui::End();
        return;
    }
    if (ImGui::GetCurrentContext()->MovingWindow == ImGui::GetCurrentWindow()) ctx.fields.probeWindowMoved = true;
    ImGuiIO& io = ImGui::GetIO();
    if (io.Fonts->Fonts.Size > 1) ImGui::PushFont(io.Fonts->Fonts[1]);
    // Compact (PanelContext::compactProbe): the key rows, the rest a click away, so that the window
    // fits beside the point inside what the panel leaves of the image.
    const bool compact = ctx.compactProbe;
    ImGui::Text("pixel (%d, %d): %s", p.x, p.y, p.hit ? p.label.c_str() : "background");
    if (p.hit) {
        ImGui::Text("P %+.3f %+.3f %+.3f", p.P.x, p.P.y, p.P.z);
        ImGui::Text("N %+.3f %+.3f %+.3f", p.N.x, p.N.y, p.N.z);
        ImGui::Text("V %+.3f %+.3f %+.3f", p.V.x, p.V.y, p.V.z);
        // The model this point is shaded with: its material's own, else the scene's.
        const ShadingModel shown = modelOf(p.material, ctx.state.scene.model);
        const bool pbr = isPhysicallyBased(shown);
        // F0: pbr's mix(0.04, baseColor, metallic), or disney's from its specular and specularTint.
        const glm::vec3 f0 = shown == ShadingModel::Disney ? p.disneyF0 : p.pbrF0;
        if (pbr)
            ImGui::Text("roughness %.3f  metallic %.2f   c_diff %.2f %.2f %.2f   F0 %.2f %.2f %.2f",
                        p.material.roughness, p.material.metallic, p.pbrDiffuseColor.r, p.pbrDiffuseColor.g,
                        p.pbrDiffuseColor.b, f0.r, f0.g, f0.b);
        else
            ImGui::Text("s %.1f   ms %.2f %.2f %.2f", p.material.s, p.material.ms.r, p.material.ms.g, p.material.ms.b);
        const ImGuiTreeNodeFlags open = compact ? 0 : ImGuiTreeNodeFlags_DefaultOpen;
        if (ImGui::TreeNodeEx("plane of incidence", open, "plane of incidence (light 1)")) {
            diagram(p, ctx.uiScale);
            ImGui::TreePop();
        }
        const bool shadows = ctx.state.scene.terms.shadows;
        if (compact) {
            // The key row always; the per-light and per-model tables a click away.
            const ShadingModel m = shown;
            const glm::vec3 total = m == ShadingModel::Disney       ? p.totalDisney
                                    : m == ShadingModel::Pbr        ? p.totalPbr
                                    : m == ShadingModel::BlinnPhong ? p.totalBlinn
                                                                    : p.totalPhong;
            ImGui::Text("N\xc2\xb7L %+.3f   total %.3f %.3f %.3f", p.lights.empty() ? 0.0f : p.lights[0].NoL, total.r,
                        total.g, total.b);
        }
        // In compact form each table sits under a folded node.
        auto folded = [&](const char* id, const char* label, const auto& draw) {
            if (!compact) {
                draw();
            } else if (ImGui::TreeNodeEx(id, 0, "%s", label)) {
                draw();
                ImGui::TreePop();
            }
        };
        if (!p.lights.empty()) folded("lights", "each light", [&] { lightTable(p, shadows, shown); });
        folded("totals", "terms, every model", [&] { totalsTable(p, shown, ctx.state.encoding); });
        ctx.fields.equationOpen = ImGui::TreeNodeEx("equation", 0, "rendering equation at this point");
        if (ctx.fields.equationOpen) {
            if (ctx.equation)
                drawRenderingEquation(*ctx.equation, ctx.uiScale);
            else
                ImGui::TextDisabled("computing...");
            ImGui::TreePop();
        }
        if (ImGui::TreeNodeEx("raytree", ctx.state.probe.rayTree ? ImGuiTreeNodeFlags_DefaultOpen : 0,
                              "rays: r(t) = o + t\xc2\xb7"
                              "d")) {
            rayTreeSection(ctx);
            ImGui::TreePop();
        }
        if (ctx.probeGlobal && ctx.probeGlobal->samples > 0) {
            // The path tracer's estimate of the same pixel: what the local terms plus ambient approximate.
            const GlobalEstimate& g = *ctx.probeGlobal;
            ImGui::Text("global (path traced) %.3f %.3f %.3f", g.mean.r, g.mean.g, g.mean.b);
            ImGui::TextDisabled("  \xc2\xb1 %.3f %.3f %.3f (standard error, %d samples)", g.standardError.r,
                                g.standardError.g, g.standardError.b, g.samples);
        }
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 24.0f * ImGui::GetFontSize());
        ImGui::TextDisabled(shadows ? "visible: the reference's shadow ray; no reflections"
                                    : "local terms, as both renderers compute them");
        ImGui::PopTextWrapPos();
    }
    if (io.Fonts->Fonts.Size > 1) ImGui::PopFont();
    ctx.fields.probeWindowWidth = ImGui::GetWindowWidth();
    ctx.fields.probeWindowHeight = ImGui::GetWindowHeight();
    ImGui::End();
}

}  // namespace shadelab::app
