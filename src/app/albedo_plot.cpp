// makeAlbedoPlot: directional albedo per model, from the shared shading functions.
#include "app/albedo_plot.h"

#include "app/specular_lobe.h"
#include "shading/dfg_lut.h"
#include "shading/ibl_lookup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab::app {
namespace {

AlbedoShade modelShade(int model, shading::vec3 md, shading::vec3 ms, float s, bool diffuse, bool specular) {
    return [=](const shading::vec3& L, const shading::vec3& V) {
        const shading::vec3 I = shading::shadeLight(shading::vec3(0.0f, 0.0f, 1.0f), L, V, shading::vec3(1.0f), md, ms,
                                                    s, model, diffuse, specular);
        return (I.x + I.y + I.z) / 3.0f;
    };
}

}  // namespace

void addAlbedoCurve(AlbedoPlot& plot, const std::string& label, const AlbedoShade& shade, bool dashed) {
    AlbedoCurve c;
    c.label = label;
    c.dashed = dashed;
    for (float degrees : plot.viewAngles)
        c.albedo.push_back(shading::directionalAlbedo(
            shade, float(std::cos(double(degrees) * 3.14159265358979 / 180.0)), plot.settings.quadrature));
    plot.curves.push_back(std::move(c));
}

AlbedoPlot makeAlbedoPlot(const AlbedoPlotSettings& in, const AlbedoPlot* previous) {
    using namespace shading;
    AlbedoPlot plot;
    plot.settings = in;
    plot.settings.angles = std::max(in.angles, 2);
    plot.settings.phongExponent = std::max(in.phongExponent, 0.0f);
    plot.settings.roughness = std::clamp(in.roughness, 0.0f, 1.0f);
    plot.settings.sheenRoughness = std::clamp(in.sheenRoughness, 0.0f, 1.0f);
    for (int i = 0; i < plot.settings.angles; ++i)
        plot.viewAngles.push_back(88.0f * float(i) / float(plot.settings.angles - 1));
    const AlbedoPlotSettings& now = plot.settings;
    // A curve of `previous` is taken as it is when the inputs it depends on are the same: the integrals are the
    // plot's whole cost (20 view angles × 4,608 samples per curve), and a slider drag changes one input.
    const bool comparable = previous && previous->settings.angles == now.angles &&
                            previous->settings.quadrature.theta == now.quadrature.theta &&
                            previous->settings.quadrature.phi == now.quadrature.phi && previous->curves.size() == 11;
    const AlbedoPlotSettings* was = comparable ? &previous->settings : nullptr;
    const bool sameS = was && was->phongExponent == now.phongExponent;
    const bool sameR = was && was->roughness == now.roughness;
    const bool sameCoat = sameR && was->clearcoatGloss == now.clearcoatGloss;
    const bool sameSheen = was && was->sheenRoughness == now.sheenRoughness;
    const auto curve = [&](bool same, const std::string& label, const AlbedoShade& shade, bool dashed = false) {
        if (same)
            plot.curves.push_back(previous->curves[plot.curves.size()]);
        else
            addAlbedoCurve(plot, label, shade, dashed);
    };
    // A normalised lobe is the lobe times a constant, so its albedo is the lobe's times that constant.
    const auto scaled = [&](bool same, const std::string& label, float factor) {
        if (same) {
            plot.curves.push_back(previous->curves[plot.curves.size()]);
            return;
        }
        AlbedoCurve c = plot.curves.back();
        c.label = label;
        c.dashed = true;
        for (float& v : c.albedo) v *= factor;
        plot.curves.push_back(std::move(c));
    };
    const float s = now.phongExponent, sb = equivalentBlinnExponent(s), r = now.roughness;
    const vec3 zero(0.0f), one(1.0f);
    char label[96];
    curve(bool(was), "Lambert, white", modelShade(SL_MODEL_PHONG, one, zero, 1.0f, true, false));
    std::snprintf(label, sizeof label, "Phong  s = %.0f", double(s));
    curve(sameS, label, modelShade(SL_MODEL_PHONG, zero, one, s, false, true));
    scaled(sameS, "Phong  normalised", phongNormalization(s));
    std::snprintf(label, sizeof label, "Blinn-Phong  s' = %.0f", double(sb));
    curve(sameS, label, modelShade(SL_MODEL_BLINN_PHONG, zero, one, sb, false, true));
    scaled(sameS, "Blinn-Phong  normalised", blinnPhongNormalization(sb));
    std::snprintf(label, sizeof label, "GGX  roughness %.2f", double(r));
    curve(sameR, label, modelShade(SL_MODEL_PBR, zero, one, r, false, true));
    // The same lobe scaled by Filament's multiple-scattering compensation, 1 + F0·(1/(A+B) − 1) from the
    // renderers' own DFG table at this N·V: a white metal then reflects within 1 % of all the light.
    const DfgLut& table = dfgLut();
    curve(
        sameR, "GGX  compensated",
        [r, &table](const vec3& L, const vec3& V) {
            IblLookup lookup;
            lookup.dfg = &table;
            const vec3 comp = energyCompensation(vec3(1.0f), lookup.dfgAt(std::max(V.z, 0.0f), r));
            const vec3 I = shadeLightScaled(vec3(0.0f, 0.0f, 1.0f), L, V, vec3(1.0f), vec3(0.0f), vec3(1.0f), r,
                                            SL_MODEL_PBR, false, true, comp);
            return (I.x + I.y + I.z) / 3.0f;
        },
        true);
    // disney (Burley 2012): each lobe of shadeLightDisney alone, at the material's roughness and coat gloss.
    const vec4 d0(0.0f, 0.5f, 0.0f, 0.0f), d1(0.0f, 0.5f, 0.0f, now.clearcoatGloss);
    const vec4 coat(0.0f, 0.5f, 1.0f, now.clearcoatGloss);
    const auto disney = [r](float metallic, vec4 a, vec4 b, bool diffuse, bool specular) {
        return [=](const vec3& L, const vec3& V) {
            const vec3 I = shadeLightDisney(vec3(0.0f, 0.0f, 1.0f), L, V, vec3(1.0f), vec3(1.0f), metallic, r, a, b,
                                            diffuse, specular, vec3(1.0f));
            return (I.x + I.y + I.z) / 3.0f;
        };
    };
    curve(sameR, "Disney diffuse, white", disney(0.0f, d0, d1, true, false));
    curve(sameR, "Disney metal, white", disney(1.0f, d0, d1, false, true));
    // The coat alone: a black metal's specular with the coat on, less the same without it.
    const auto withCoat = disney(0.0f, d0, coat, false, true), without = disney(0.0f, d0, d1, false, true);
    curve(sameCoat, "Disney clearcoat", [=](const vec3& L, const vec3& V) { return withCoat(L, V) - without(L, V); });
    // glTF's sheen on pbr: the Charlie lobe alone, white, at the material's sheen roughness; it reflects more the
    // nearer the view grazes, and its base keeps the rest (1 − E).
    const float sheenRoughness = now.sheenRoughness;
    std::snprintf(label, sizeof label, "glTF sheen  roughness %.2f", double(sheenRoughness));
    curve(sameSheen, label, [sheenRoughness](const vec3& L, const vec3& V) {
        return sheenLobe(vec3(0.0f, 0.0f, 1.0f), L, V, sheenRoughness);
    });
    return plot;
}

}  // namespace shadelab::app
