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

AlbedoPlot makeAlbedoPlot(const AlbedoPlotSettings& in) {
    using namespace shading;
    AlbedoPlot plot;
    plot.settings = in;
    plot.settings.angles = std::max(in.angles, 2);
    plot.settings.phongExponent = std::max(in.phongExponent, 0.0f);
    plot.settings.roughness = std::clamp(in.roughness, 0.0f, 1.0f);
    for (int i = 0; i < plot.settings.angles; ++i)
        plot.viewAngles.push_back(88.0f * float(i) / float(plot.settings.angles - 1));
    const float s = plot.settings.phongExponent, sb = equivalentBlinnExponent(s), r = plot.settings.roughness;
    const vec3 zero(0.0f), one(1.0f);
    char label[96];
    addAlbedoCurve(plot, "Lambert, white", modelShade(SL_MODEL_PHONG, one, zero, 1.0f, true, false));
    std::snprintf(label, sizeof label, "Phong  s = %.0f", double(s));
    addAlbedoCurve(plot, label, modelShade(SL_MODEL_PHONG, zero, one, s, false, true));
    std::snprintf(label, sizeof label, "Phong  normalised");
    addAlbedoCurve(plot, label, modelShade(SL_MODEL_PHONG, zero, vec3(phongNormalization(s)), s, false, true), true);
    std::snprintf(label, sizeof label, "Blinn-Phong  s' = %.0f", double(sb));
    addAlbedoCurve(plot, label, modelShade(SL_MODEL_BLINN_PHONG, zero, one, sb, false, true));
    std::snprintf(label, sizeof label, "Blinn-Phong  normalised");
    addAlbedoCurve(plot, label,
                   modelShade(SL_MODEL_BLINN_PHONG, zero, vec3(blinnPhongNormalization(sb)), sb, false, true), true);
    std::snprintf(label, sizeof label, "GGX  roughness %.2f", double(r));
    addAlbedoCurve(plot, label, modelShade(SL_MODEL_PBR, zero, one, r, false, true));
    // The same lobe scaled by Filament's multiple-scattering compensation, 1 + F0·(1/(A+B) − 1) from the
    // renderers' own DFG table at this N·V: a white metal then reflects within 1 % of all the light.
    const DfgLut& table = dfgLut();
    std::snprintf(label, sizeof label, "GGX  compensated");
    addAlbedoCurve(
        plot, label,
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
    const vec4 d0(0.0f, 0.5f, 0.0f, 0.0f), d1(0.0f, 0.5f, 0.0f, plot.settings.clearcoatGloss);
    const vec4 coat(0.0f, 0.5f, 1.0f, plot.settings.clearcoatGloss);
    const auto disney = [r](float metallic, vec4 a, vec4 b, bool diffuse, bool specular) {
        return [=](const vec3& L, const vec3& V) {
            const vec3 I = shadeLightDisney(vec3(0.0f, 0.0f, 1.0f), L, V, vec3(1.0f), vec3(1.0f), metallic, r, a, b,
                                            diffuse, specular, vec3(1.0f));
            return (I.x + I.y + I.z) / 3.0f;
        };
    };
    std::snprintf(label, sizeof label, "Disney diffuse, white");
    addAlbedoCurve(plot, label, disney(0.0f, d0, d1, true, false));
    std::snprintf(label, sizeof label, "Disney metal, white");
    addAlbedoCurve(plot, label, disney(1.0f, d0, d1, false, true));
    // The coat alone: a black metal's specular with the coat on, less the same without it.
    const auto withCoat = disney(0.0f, d0, coat, false, true), without = disney(0.0f, d0, d1, false, true);
    std::snprintf(label, sizeof label, "Disney clearcoat");
    addAlbedoCurve(plot, label, [=](const vec3& L, const vec3& V) { return withCoat(L, V) - without(L, V); });
    // glTF's sheen on pbr: the Charlie lobe alone, white, at the material's sheen roughness; it reflects more the
    // nearer the view grazes, and its base keeps the rest (1 − E).
    const float sheenRoughness = std::clamp(plot.settings.sheenRoughness, 0.0f, 1.0f);
    std::snprintf(label, sizeof label, "glTF sheen  roughness %.2f", double(sheenRoughness));
    addAlbedoCurve(plot, label, [sheenRoughness](const vec3& L, const vec3& V) {
        return sheenLobe(vec3(0.0f, 0.0f, 1.0f), L, V, sheenRoughness);
    });
    return plot;
}

}  // namespace shadelab::app
