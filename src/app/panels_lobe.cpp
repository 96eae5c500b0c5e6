// The Material panel's plots: the specular lobe of every model against the angle between
// R and V on a fixed axis, the same lobes as the textbook's polar figure in the plane of incidence (with the
// probe's L, V and R), and the directional albedo of every model. The data is lobe_plot.h and albedo_plot.h;
// this file only draws it.
#include "app/panels.h"

#include "app/lobe_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab::app {
namespace {

const ImU32 kLobeColors[kLobeModels] = {
    IM_COL32(255, 170, 60, 255),   // Phong
    IM_COL32(120, 150, 255, 230),  // Blinn-Phong, same exponent
    IM_COL32(90, 220, 110, 200),   // Blinn-Phong, equivalent exponent
    IM_COL32(240, 100, 180, 255),  // pbr
    IM_COL32(80, 220, 230, 255),   // disney
};
const float kLobeThickness[kLobeModels] = {2.0f, 2.0f, 6.0f, 2.0f, 2.0f};
// Drawn in this order: the wide equivalent Blinn lobe first, the thin Phong lobe it matches over it.
const LobeModel kDrawOrder[kLobeModels] = {LobeModel::BlinnEquivalent, LobeModel::BlinnSame, LobeModel::Pbr,
                                           LobeModel::Disney, LobeModel::Phong};
const ImU32 kGrid = IM_COL32(70, 70, 80, 255);
const ImU32 kBackground = IM_COL32(25, 25, 30, 255);

void dashedPolyline(ImDrawList* dl, const std::vector<ImVec2>& pts, ImU32 color, float thickness, float dash) {
    float run = 0.0f;
    for (size_t i = 1; i < pts.size(); ++i) {
        const float len = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
        if (std::fmod(run, 2.0f * dash) < dash) dl->AddLine(pts[i - 1], pts[i], color, thickness);
        run += len;
    }
}

void arrow(ImDrawList* dl, ImVec2 from, ImVec2 to, ImU32 color, const char* label, float scale) {
    dl->AddLine(from, to, color, 2.0f * scale);
    const float dx = to.x - from.x, dy = to.y - from.y, len = std::max(std::hypot(dx, dy), 1e-3f);
    const ImVec2 u(dx / len, dy / len), n(-u.y, u.x);
    const float head = 7.0f * scale;
    dl->AddTriangleFilled(to, ImVec2(to.x - u.x * head + n.x * head * 0.5f, to.y - u.y * head + n.y * head * 0.5f),
                          ImVec2(to.x - u.x * head - n.x * head * 0.5f, to.y - u.y * head - n.y * head * 0.5f), color);
    dl->AddText(ImVec2(to.x + u.x * 4.0f * scale - 4.0f * scale, to.y + u.y * 4.0f * scale - 16.0f * scale), color,
                label);
}

// The Cartesian plot: lobe / peak against the angle between R and V, from 0 to the fixed axis.
void drawCartesian(const LobePlot& plot, float width, float height, float scale) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const float labelH = ImGui::GetTextLineHeight();
    const ImVec2 p1(p0.x + width, p0.y + height);
    dl->AddRectFilled(p0, p1, kBackground);
    const float axis = plot.settings.axis;
    const float tick = axis >= 60.0f ? 30.0f : axis >= 20.0f ? 10.0f : axis >= 8.0f ? 2.0f : 1.0f;
    for (float a = tick; a < axis - 1e-3f; a += tick) {
        const float x = p0.x + width * a / axis;
        dl->AddLine(ImVec2(x, p0.y), ImVec2(x, p1.y), kGrid);
    }
    const float halfY = p1.y - 0.5f * height;
    dl->AddLine(ImVec2(p0.x, halfY), ImVec2(p1.x, halfY), kGrid);
    for (LobeModel m : kDrawOrder) {
        const LobeCurve& c = plot.curves[size_t(m)];
        std::vector<ImVec2> pts;
        for (size_t i = 0; i < c.value.size(); ++i)
            pts.emplace_back(p0.x + width * plot.angleAt(int(i)) / axis, p1.y - height * std::min(c.value[i], 1.0f));
        dl->AddPolyline(pts.data(), int(pts.size()), kLobeColors[size_t(m)], 0, kLobeThickness[size_t(m)] * scale);
    }
    char buf[32];
    for (float a = 0.0f; a <= axis + 1e-3f; a += tick) {
        std::snprintf(buf, sizeof buf, "%.0f°", double(a));
        const float w = ImGui::CalcTextSize(buf).x;
        const float x = std::clamp(p0.x + width * a / axis - 0.5f * w, p0.x, p1.x - w);
        dl->AddText(ImVec2(x, p1.y + 1.0f), IM_COL32(150, 150, 160, 255), buf);
    }
    ImGui::Dummy(ImVec2(width, height + labelH + 2.0f));
}

// The polar plot in the plane of incidence: the surface, N, L, R (and the probe's V), and each lobe with its
// value as the radius (the textbook figure).
void drawPolar(const LobePlot& plot, const PlaneOfIncidence* probe, float width, float height, float scale) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const float base = 18.0f * scale;
    const float radius = std::min(0.5f * width - 14.0f * scale, (height - base - 22.0f * scale) / 1.08f);
    // A transmitting pbr material's light through the surface is drawn below it: the plot grows by a radius.
    const std::vector<float>& through = plot.curves[size_t(LobeModel::Pbr)].through;
    if (!through.empty()) height += radius;
    const ImVec2 p1(p0.x + width, p0.y + height);
    dl->AddRectFilled(p0, p1, kBackground);
    const ImVec2 c(p0.x + 0.5f * width, p0.y + height - base - (through.empty() ? 0.0f : radius));
    auto at = [&](glm::vec2 d, float r) { return ImVec2(c.x + d.x * r * radius, c.y - d.y * r * radius); };
    dl->AddRectFilled(ImVec2(p0.x, c.y), p1, IM_COL32(45, 42, 38, 255));  // the material below the surface
    dl->AddLine(ImVec2(p0.x, c.y), ImVec2(p1.x, c.y), IM_COL32(160, 150, 130, 255), 1.5f * scale);
    for (float r : {0.5f, 1.0f}) {
        std::vector<ImVec2> arc;
        for (int i = 0; i <= 90; ++i) arc.push_back(at(polarDirection(-90.0f + 2.0f * float(i)), r));
        dl->AddPolyline(arc.data(), int(arc.size()), kGrid, 0, 1.0f);
    }
    for (LobeModel m : kDrawOrder) {
        const LobeCurve& curve = plot.curves[size_t(m)];
        std::vector<ImVec2> pts;
        for (size_t i = 0; i < curve.polar.size(); ++i)
            pts.push_back(at(polarDirection(plot.polarAngleAt(int(i))), std::min(curve.polar[i], 1.0f)));
        dl->AddPolyline(pts.data(), int(pts.size()), kLobeColors[size_t(m)], 0, kLobeThickness[size_t(m)] * scale);
    }
    if (!through.empty()) {  // below the surface, θo measured from −N
        std::vector<ImVec2> pts;
        for (size_t k = 0; k < through.size(); ++k) {
            const glm::vec2 d = polarDirection(plot.polarAngleAt(int(k)));
            pts.push_back(at({d.x, -d.y}, std::min(through[k], 1.0f)));
        }
        const size_t pbr = size_t(LobeModel::Pbr);
        dl->AddPolyline(pts.data(), int(pts.size()), kLobeColors[pbr], 0, kLobeThickness[pbr] * scale);
        dl->AddText(ImVec2(p0.x + 4.0f * scale, p1.y - ImGui::GetTextLineHeight() - 2.0f * scale),
                    IM_COL32(200, 190, 170, 255), "through the surface (pbr)");
    }
    const float i = plot.settings.incidence;
    const ImU32 white = IM_COL32(235, 235, 235, 255), yellow = IM_COL32(255, 225, 90, 255);
    arrow(dl, c, at({0.0f, 1.0f}, 1.08f), IM_COL32(150, 200, 255, 255), "N", scale);
    arrow(dl, c, at(probe ? probe->L : polarDirection(-i), 1.08f), yellow, "L", scale);
    arrow(dl, c, at(probe ? probe->R : polarDirection(i), 1.08f), IM_COL32(255, 150, 90, 255), "R", scale);
    if (probe) arrow(dl, c, at(probe->V, 0.85f), white, "V", scale);
    ImGui::Dummy(ImVec2(width, height));
}

void drawAlbedo(const AlbedoPlot& plot, float width, float height, float scale) {
    // Lambert, Phong ×2, Blinn-Phong ×2, GGX ×2, then disney's diffuse, metal and coat.
    static const ImU32 colors[] = {IM_COL32(170, 170, 170, 255),
                                   kLobeColors[0],
                                   kLobeColors[0],
                                   kLobeColors[2],
                                   kLobeColors[2],
                                   kLobeColors[3],
                                   kLobeColors[3],
                                   IM_COL32(150, 200, 230, 255),
                                   kLobeColors[4],
                                   IM_COL32(200, 240, 250, 255)};
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const ImVec2 p1(p0.x + width, p0.y + height);
    dl->AddRectFilled(p0, p1, kBackground);
    float top = 1.25f;
    for (const AlbedoCurve& c : plot.curves)
        for (float v : c.albedo) top = std::max(top, std::min(v * 1.05f, 3.0f));
    auto y = [&](float v) { return p1.y - height * std::min(v, top) / top; };
    for (float v : {0.5f, 1.0f, 1.5f, 2.0f, 2.5f})
        if (v < top)
            dl->AddLine(ImVec2(p0.x, y(v)), ImVec2(p1.x, y(v)), v == 1.0f ? IM_COL32(120, 120, 130, 255) : kGrid);
    for (float a : {30.0f, 60.0f})
        dl->AddLine(ImVec2(p0.x + width * a / 90.0f, p0.y), ImVec2(p0.x + width * a / 90.0f, p1.y), kGrid);
    for (size_t k = 0; k < plot.curves.size(); ++k) {
        const AlbedoCurve& c = plot.curves[k];
        std::vector<ImVec2> pts;
        for (size_t i = 0; i < c.albedo.size(); ++i)
            pts.emplace_back(p0.x + width * plot.viewAngles[i] / 90.0f, y(c.albedo[i]));
        const ImU32 color = colors[std::min(k, std::size(colors) - 1)];
        if (c.dashed)
            dashedPolyline(dl, pts, color, 2.0f * scale, 5.0f * scale);
        else
            dl->AddPolyline(pts.data(), int(pts.size()), color, 0, 2.0f * scale);
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::TextDisabled("view angle 0° to 90° (grid 30°), albedo 0 to %.2f;", double(top));
    ImGui::TextDisabled("light line at 1: all the light reflected");
    if (!ImGui::BeginTable("albedo", 3, ImGuiTableFlags_SizingFixedFit)) return;
    ImGui::TableSetupColumn("white lobe", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("at 0°");
    char last[32];
    std::snprintf(last, sizeof last, "at %.0f°", double(plot.viewAngles.back()));
    ImGui::TableSetupColumn(last);
    ImGui::TableHeadersRow();
    for (size_t k = 0; k < plot.curves.size(); ++k) {
        const AlbedoCurve& c = plot.curves[k];
        ImGui::PushStyleColor(ImGuiCol_Text,
                              ImGui::ColorConvertU32ToFloat4(colors[std::min(k, std::size(colors) - 1)]));
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::Text("%s%s", c.dashed ? "- - " : "", c.label.c_str());
        ImGui::TableSetColumnIndex(1);
        ImGui::Text("%.3f", double(c.albedo.front()));
        ImGui::TableSetColumnIndex(2);
        ImGui::Text("%.3f", double(c.albedo.back()));
        ImGui::PopStyleColor();
    }
    ImGui::EndTable();
}

}  // namespace

void drawLobePlots(PanelContext& ctx, const Material& m, float phongExponent) {
    UiFields& f = ctx.fields;
    const float scale = ctx.uiScale;

    // The angle of incidence: the probe's first lit light when the probe is on this object, else the slider.
    std::optional<PlaneOfIncidence> probePlane;
    const ProbeResult* p = ctx.probe;
    if (p && p->hit && p->objectId == ctx.state.selected)
        for (const ProbeLight& l : p->lights)
            if (l.NoL > 0.0f) {
                probePlane = planeOfIncidence(p->N, l.L, p->V);
                break;
            }

    if (!ImGui::TreeNodeEx("Specular lobe", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const float width = ImGui::GetContentRegionAvail().x;  // inside the tree node's indent
    LobePlotSettings settings = lobeSettingsOf(m);
    settings.phongExponent = phongExponent;
    settings.axis = f.lobeAxis;
    if (probePlane) {
        settings.incidence = probePlane->incidence;
        ImGui::Text("incidence %.1f°: the probe's first lit light", double(settings.incidence));
    } else {
        ImGui::SliderFloat("incidence  N to L", &f.lobeIncidence, 0.0f, 89.0f, "%.0f°");
        settings.incidence = f.lobeIncidence;
    }
    ImGui::SliderFloat("axis  zoom", &f.lobeAxis, 5.0f, 90.0f, "0 to %.0f°", ImGuiSliderFlags_Logarithmic);
    const LobePlot plot = makeLobePlot(settings);
    drawCartesian(plot, width, 120.0f * scale, scale);
    ImGui::TextDisabled("angle R to V; lobe / its peak; half-width at ½:");
    const float column = ImGui::GetCursorPosX() + width - ImGui::CalcTextSize("HWHM 00.0°").x;
    for (LobeModel model :
         {LobeModel::Phong, LobeModel::BlinnSame, LobeModel::BlinnEquivalent, LobeModel::Pbr, LobeModel::Disney}) {
        const LobeCurve& c = plot.curves[size_t(model)];
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::ColorConvertU32ToFloat4(kLobeColors[size_t(model)]));
        ImGui::TextUnformatted(c.label.c_str());
        ImGui::SameLine(column);
        const float hwhm = halfWidthAtHalfMaximum(c.value, plot.settings.axis);
        if (hwhm >= plot.settings.axis)
            ImGui::Text("> %.0f°", double(plot.settings.axis));
        else
            ImGui::Text("HWHM %.1f°", double(hwhm));
        ImGui::PopStyleColor();
    }
    drawPolar(plot, probePlane ? &*probePlane : nullptr, width, 170.0f * scale, scale);
    if (probePlane)
        ImGui::TextDisabled("plane of incidence of the probe; V is %.0f° out of it", double(probePlane->vOutOfPlane));
    else
        ImGui::TextDisabled("plane of incidence: radius = lobe / peak at each V");
    ImGui::TreePop();

    if (!ImGui::TreeNode("Directional albedo (energy)")) return;
    AlbedoPlotSettings wanted;
    wanted.phongExponent = phongExponent;
    wanted.roughness = m.roughness;
    wanted.clearcoatGloss = m.disney.clearcoatGloss;
    wanted.sheenRoughness = m.sheen.roughness;
    // Integrating the curves takes tens of milliseconds: while a control is held (a shininess drag) the plot
    // keeps its curves and follows when it is let go, so the drag's frames stay the picture's.
    const bool stale = f.albedo && !(f.albedo->settings == wanted);
    const bool held = ImGui::IsAnyItemActive();
    if (!f.albedo || (stale && !held)) f.albedo = makeAlbedoPlot(wanted, f.albedo ? &*f.albedo : nullptr);
    drawAlbedo(*f.albedo, width, 140.0f * scale, scale);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped(
        "White lobes (ms = 1, F0 = 1): the fraction of the light from all directions reflected "
        "toward V. Dashed: normalised lobes.%s",
        stale && held ? " (Follows when the control is let go.)" : "");
    ImGui::PopStyleColor();
    ImGui::TreePop();
}

}  // namespace shadelab::app
