// View panel: Raster / Traced / Split / Difference, the encoding, the display (exposure and view transform), the
// reference's progress, and the
// raster-vs-reference metrics (design.md §4 gates) once the reference is complete.
#include "app/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace shadelab::app {
namespace {

void metricsTable(const CompareResult& r) {
    // The numbers behind the words, with the verdict under the strict gates CI uses, folded away: in front
    // of a class a bare "FAIL" on the lesson scene reads as a fault, which it is not.
    if (!ImGui::TreeNode("metrics", "metrics per region (%s under the design.md section 4 gates)",
                         r.pass ? "within" : "outside"))
        return;
    if (ImGui::BeginTable("metrics", 4, ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_BordersInnerH)) {
        ImGui::TableSetupColumn("region");
        ImGui::TableSetupColumn("mean");
        ImGui::TableSetupColumn("max");
        ImGui::TableSetupColumn("> 3/255");
        ImGui::TableHeadersRow();
        const std::pair<const char*, const RegionStats*> rows[] = {
            {"interior", &r.interior}, {"silhouette", &r.band}, {"all", &r.all}};
        for (const auto& [name, st] : rows) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted(name);
            ImGui::TableSetColumnIndex(1);
            ImGui::Text("%.3f", st->mean);
            ImGui::TableSetColumnIndex(2);
            ImGui::Text("%d", st->max);
            ImGui::TableSetColumnIndex(3);
            ImGui::Text("%.3f%%", 100.0 * st->fractionOver());
        }
        ImGui::EndTable();
    }
    if (r.interior.max > 0)
        ImGui::TextDisabled("interior max at (%d, %d) in %s", r.interior.maxX, r.interior.maxY,
                            channelName(r.interior.maxChannel));
    ImGui::TextDisabled("coverage mismatches %lld (%lld outside the band)", (long long)r.coverageMismatches,
                        (long long)r.mismatchesOutsideBand);
    for (const std::string& reason : r.reasons) ImGui::TextWrapped("- %s", reason.c_str());
    ImGui::TreePop();
}

// Global and Local | Global: which light to show, and how far the path tracer has got.
void drawGlobalStatus(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    if (s.mode == ViewMode::LocalGlobal) {
        float split = ctx.wipe;
        if (ImGui::SliderFloat("wipe", &split, 0.0f, 1.0f, "%.2f")) setSplitPosition(s, split);
        ImGui::TextDisabled("left local (raster), right global (path traced); drag the line");
    }
    int part = int(s.globalPart);
    ImGui::TextDisabled("light");
    const char* parts[] = {"all", "direct", "indirect only"};
    for (int i = 0; i < 3; ++i) {
        ImGui::SameLine();
        if (ImGui::RadioButton(parts[i], &part, i)) setGlobalPart(s, trace::PathPart(i));
    }
    const GlobalInfo& g = ctx.global;
    bool denoise = s.globalDenoise;
    if (ImGui::Checkbox("denoised preview (D)", &denoise)) setGlobalDenoise(s, denoise);
    if (s.globalDenoise && g.denoisedSamples > 0) {
        ImGui::SameLine();
        ImGui::TextDisabled("at %d samples; the probe reads the raw estimate", g.denoisedSamples);
    }
    if (!g.error.empty()) {
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "path tracer: %s", g.error.c_str());
        return;
    }
    char overlay[96];
    if (g.samples == 0)
        std::snprintf(overlay, sizeof overlay, "first sample %.0f%%", 100.0 * g.passProgress);
    else if (g.samples == 1)  // one sample per pixel measures no noise yet
        std::snprintf(overlay, sizeof overlay, "1 sample, noise -, %.0f s", g.seconds);
    else
        std::snprintf(overlay, sizeof overlay, "%d samples, noise %.1f/255, %.0f s", g.samples, g.noise8, g.seconds);
    const float fraction = g.samples == 0 ? g.passProgress : std::min(1.0f, float(g.samples) / 256.0f);
    ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), overlay);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped(
        "path tracer, %d thread(s) at low priority; the ambient term is off (light bounces instead); "
        "refines until %d samples, restarts on every change",
        g.threads, g.maxSamples);
    ImGui::PopStyleColor();
}

}  // namespace

void drawViewSection(PanelContext& ctx) {
    ViewerState& s = ctx.state;
    int mode = int(s.mode);
    const char* names[] = {"Raster", "Traced", "Split", "Difference", "Global", "Local | Global"};
    for (int i = 0; i < 6; ++i) {
        if (i && i != 4) ImGui::SameLine();
        if (ImGui::RadioButton(names[i], &mode, i)) setMode(s, ViewMode(i));
    }
    ImGui::TextDisabled("camera");
    ImGui::SameLine();
    if (ImGui::SmallButton("fit (F)")) frameAll(s);
    ImGui::SameLine();
    if (ImGui::SmallButton("file (R)")) resetCamera(s);
    for (size_t i = 0; i < s.scene.modelCameras.size() && i < 8; ++i) {
        ImGui::SameLine();
        const std::string label = "glTF " + std::to_string(i);
        if (ImGui::SmallButton(label.c_str())) useCamera(s, s.scene.modelCameras[i]);
    }
    ImGui::Checkbox("captions on the image (C)", &ctx.fields.captions);
    ImGui::SameLine();
    ImGui::Checkbox("light markers", &ctx.fields.lightMarkers);
    ImGui::Checkbox("smooth edges when still (16 samples)", &ctx.fields.smooth);
    // The scene's raster.movingPreview (raster_settings.h): a quarter of the pixels while the camera moves.
    bool preview = s.scene.raster.movingPreview;
    if (ImGui::Checkbox("half-size preview while the camera moves", &preview)) {
        RasterSettings r = s.scene.raster;
        r.movingPreview = preview;
        setRasterSettings(s, r);
    }
    int encoding = s.encoding == Encoding::Srgb ? 0 : 1;
    ImGui::TextDisabled("encoding");
    ImGui::SameLine();
    if (ImGui::RadioButton("sRGB", &encoding, 0)) setEncoding(s, Encoding::Srgb);
    ImGui::SameLine();
    if (ImGui::RadioButton("linear", &encoding, 1)) setEncoding(s, Encoding::Linear);
    // The scene's display (image/view_transform.h): what the window and every screenshot show, never what is
    // rendered; the difference view and the probe read the raw values.
    DisplaySettings display = s.scene.display;
    float stops = float(display.exposure);
    if (ImGui::SliderFloat("exposure (stops)", &stops, float(kMinExposure), float(kMaxExposure), "%+.1f")) {
        // Hundredths of a stop, as a double: a saved scene reads "-3.2", not the float's -3.200000047683716.
        display.exposure = std::round(double(stops) * 100.0) / 100.0;
        setDisplay(s, display);
    }
    int transform = display.transform == ViewTransform::Filmic ? 1 : 0;
    const char* transforms[] = {"standard (clamp)", "filmic (ACES fit)"};
    if (ImGui::Combo("view transform", &transform, transforms, 2)) {
        display.transform = transform == 1 ? ViewTransform::Filmic : ViewTransform::Standard;
        setDisplay(s, display);
    }
    if (!display.isStandard() && ImGui::SmallButton("standard display (0 stops, clamp)"))
        setDisplay(s, DisplaySettings{});
    if (s.mode == ViewMode::Split) {
        float split = ctx.wipe;
        if (ImGui::SliderFloat("wipe", &split, 0.0f, 1.0f, "%.2f")) setSplitPosition(s, split);
        ImGui::TextDisabled("left raster, right reference; drag the line");
    }
    if (s.mode == ViewMode::Difference) {
        int gain = s.heatGain;
        if (ImGui::SliderInt("gain", &gain, 1, 64)) setHeatGain(s, gain);
    }
    if (s.mode == ViewMode::Raster) return;
    if (isGlobal(s.mode)) {
        drawGlobalStatus(ctx);
        return;
    }

    const ReferenceInfo& ref = ctx.reference;
    if (!ref.error.empty()) {
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "reference: %s", ref.error.c_str());
        return;
    }
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s %.0f%%  %.1f s", ref.complete ? "done" : "tracing", 100.0 * ref.progress,
                  ref.seconds);
    ImGui::ProgressBar(ref.progress, ImVec2(-1.0f, 0.0f), overlay);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("CPU reference, %d thread(s) at low priority; restarts on every change", ref.threads);
    ImGui::PopStyleColor();
    if (s.mode == ViewMode::Difference) {
        if (ctx.metrics) {
            ImGui::TextWrapped("%s", ctx.metricsWords.c_str());
            metricsTable(*ctx.metrics);
        } else
            ImGui::TextDisabled("metrics when the reference is complete");
    }
}

}  // namespace shadelab::app
