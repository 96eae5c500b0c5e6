// The viewer's plots, no window: the equivalent Blinn exponent, the lobe plots and the
// directional-albedo curves.
#include "app/albedo_plot.h"
#include "app/lobe_plot.h"
#include "app/specular_lobe.h"
#include "scene/material.h"
#include "shading/lighting.h"
#include "shading/sheen_lut.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

using namespace shadelab;
using namespace shadelab::app;

// ---- Equivalent Blinn exponent -------------------------------------------------------------------------

TEST(AppState, EquivalentBlinnExponentMatchesHalfMaximum) {
    for (float s : {1.0f, 4.0f, 32.0f, 200.0f, 2048.0f}) {
        const float sb = equivalentBlinnExponent(s);
        const double halfAngle = std::acos(std::pow(0.5, 1.0 / s));  // Phong's half maximum
        EXPECT_NEAR(std::pow(std::cos(halfAngle / 2.0), double(sb)), 0.5, 1e-4) << s;
        EXPECT_NEAR(equivalentPhongExponent(sb), s, 1e-3f * s) << s;
        // Better than the classic 4s everywhere, and much better than the same exponent (negative control).
        EXPECT_LT(lobeRmsDifference(s, sb), lobeRmsDifference(s, fourTimesRule(s))) << s;
        EXPECT_GT(lobeRmsDifference(s, s), 5.0f * lobeRmsDifference(s, sb)) << s;
    }
    EXPECT_NEAR(equivalentBlinnExponent(512.0f), 4.0f * 512.0f + std::log(2.0f), 0.01f);
    EXPECT_EQ(equivalentBlinnExponent(0.0f), 0.0f);
    EXPECT_EQ(equivalentPhongExponent(1.5f), 0.0f);
    const std::vector<float> lobe = phongLobe(8.0f, 91);
    EXPECT_EQ(lobe.front(), 1.0f);
    EXPECT_NEAR(lobe.back(), 0.0f, 1e-6f);
}

// ---- Lobe plots -----------------------------------------------------------------------------------------

namespace {

// The lobe plot's former, rescaled axis: four times Phong's half-maximum angle, within [5, 90] degrees.
// Its curve looked the same for every s >= 32 (the negative control below).
float oldRescaledAxis(float s) {
    const double halfMax = std::acos(std::exp2(-1.0 / double(s))) * 180.0 / M_PI;
    return float(std::clamp(4.0 * halfMax, 5.0, 90.0));
}

// True when every width is smaller than the one before.
bool strictlyShrinking(const std::vector<float>& widths) {
    for (size_t i = 1; i < widths.size(); ++i)
        if (!(widths[i] < widths[i - 1])) return false;
    return true;
}

const float kExponents[] = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048};

}  // namespace

TEST(LobePlot, HalfWidthReadFromTheDataShrinksAsShininessGrows) {
    // What the panel draws on its fixed 0..90° axis: the half-width, as a fraction of the plot's width, must
    // shrink at every step from s = 1 to 2048, for each lecture lobe.
    for (LobeModel m : {LobeModel::Phong, LobeModel::BlinnSame, LobeModel::BlinnEquivalent}) {
        std::vector<float> screen;
        for (float s : kExponents) {
            LobePlotSettings settings;
            settings.phongExponent = s;
            const LobePlot plot = makeLobePlot(settings);
            ASSERT_EQ(plot.curves[size_t(m)].value.size(), size_t(settings.samples));
            const float hwhm = halfWidthAtHalfMaximum(plot.curves[size_t(m)].value, plot.settings.axis);
            screen.push_back(hwhm / plot.settings.axis);
            if (m == LobeModel::Phong) {  // the closed form: cos(a)^s = 1/2
                EXPECT_NEAR(hwhm, std::acos(std::exp2(-1.0 / s)) * 180.0 / M_PI, 0.05) << s;
            }
        }
        // Blinn-Phong at the same s = 1 and 2 stays above half beyond 90° (cos(a/2)^s = 1/2 at a = 120°, 90°):
        // it is checked from s = 4 on.
        if (m == LobeModel::BlinnSame) screen.erase(screen.begin(), screen.begin() + 2);
        EXPECT_TRUE(strictlyShrinking(screen)) << "model " << int(m) << ": " << testing::PrintToString(screen);
        EXPECT_LT(screen.back(), m == LobeModel::BlinnSame ? 0.04f : 0.02f) << "s = 2048 must look narrow on screen";
    }
    // Equivalent exponents give Phong's half-width (the rule of specular_lobe.h), same exponents a wider one.
    LobePlotSettings settings;
    settings.phongExponent = 64.0f;
    const LobePlot plot = makeLobePlot(settings);
    const auto hw = [&](LobeModel m) { return halfWidthAtHalfMaximum(plot.curves[size_t(m)].value, 90.0f); };
    EXPECT_NEAR(hw(LobeModel::BlinnEquivalent), hw(LobeModel::Phong), 0.05f);
    EXPECT_GT(hw(LobeModel::BlinnSame), 1.8f * hw(LobeModel::Phong));
}

// The pbr lobe follows glTF's layers: a clear coat adds its sharp lobe (the polar curve at the mirror direction gains
// against the base's broad one), anisotropy changes the lobe in the plane of incidence, and a transmitting material's
// light through the surface is drawn below it, peaking straight through (at θo = θi from −N), on one scale with the
// reflection. Controls: no layer leaves the curve as before and draws nothing below.
TEST(LobePlot, ThePbrLobeFollowsGltfsLayers) {
    Material base;
    base.baseColor = glm::vec3(0.8f, 0.3f, 0.2f);
    base.roughness = 0.6f;
    const auto plotOf = [](const Material& m) {
        LobePlotSettings settings = lobeSettingsOf(m);
        settings.incidence = 40.0f;
        return makeLobePlot(settings);
    };
    const LobePlot plain = plotOf(base);
    const LobeCurve& p = plain.curves[size_t(LobeModel::Pbr)];
    EXPECT_TRUE(p.through.empty());
    // The mirror direction's value against a broad direction's, both relative to the peak.
    const int mirror = int(std::lround((40.0f + 90.0f) / 180.0f * float(plain.settings.polarSamples - 1)));
    const int broad = int(std::lround((10.0f + 90.0f) / 180.0f * float(plain.settings.polarSamples - 1)));
    Material coated = base;
    coated.clearcoat = Clearcoat{1.0f, 0.05f};
    const LobePlot coatPlot = plotOf(coated);
    const LobeCurve& c = coatPlot.curves[size_t(LobeModel::Pbr)];
    EXPECT_LT(c.polar[size_t(broad)] / c.polar[size_t(mirror)], 0.5f * p.polar[size_t(broad)] / p.polar[size_t(mirror)])
        << "the coat's sharp lobe at the mirror direction";
    EXPECT_NE(c.label.find("+ coat"), std::string::npos);
    Material brushed = base;
    brushed.anisotropy = Anisotropy{0.9f, 0.0f};
    EXPECT_NE(plotOf(brushed).curves[size_t(LobeModel::Pbr)].polar, p.polar);
    Material glass = base;
    glass.roughness = 0.2f;  // a narrow lobe: its off-specular shift stays small
    glass.transmission = Transmission{1.0f};
    const LobePlot through = plotOf(glass);
    const LobeCurve& t = through.curves[size_t(LobeModel::Pbr)];
    ASSERT_EQ(t.through.size(), size_t(through.settings.polarSamples));
    const size_t top = size_t(std::max_element(t.through.begin(), t.through.end()) - t.through.begin());
    EXPECT_NEAR(through.polarAngleAt(int(top)), 40.0f, 2.0f) << "straight through, mirrored";
    EXPECT_FLOAT_EQ(std::max(*std::max_element(t.through.begin(), t.through.end()),
                             *std::max_element(t.polar.begin(), t.polar.end())),
                    1.0f);
    EXPECT_NE(t.label.find("+ through"), std::string::npos);
}

TEST(LobePlot, TheOldRescaledAxisAndAConstantLobeFailTheCheck) {
    // Negative controls for the check above: on the old axis the on-screen width stopped shrinking at s = 32,
    // and a lobe that never changes cannot shrink.
    std::vector<float> rescaled, constant;
    for (float s : kExponents) {
        LobePlotSettings settings;
        settings.phongExponent = s;
        settings.axis = oldRescaledAxis(s);
        const LobePlot plot = makeLobePlot(settings);
        rescaled.push_back(halfWidthAtHalfMaximum(plot.curves[0].value, plot.settings.axis) / plot.settings.axis);
        LobePlotSettings fixed;
        fixed.phongExponent = 32.0f;
        const LobePlot same = makeLobePlot(fixed);
        constant.push_back(halfWidthAtHalfMaximum(same.curves[0].value, 90.0f) / 90.0f);
    }
    EXPECT_FALSE(strictlyShrinking(rescaled));
    EXPECT_FALSE(strictlyShrinking(constant));
    EXPECT_NEAR(rescaled[6], rescaled.back(), 0.01f);  // s = 64 and 2048 looked alike
}

TEST(LobePlot, PolarLobesPeakAtTheMirrorDirectionAndNarrowWithRoughness) {
    LobePlotSettings settings;
    settings.incidence = 40.0f;
    settings.phongExponent = 50.0f;
    settings.roughness = 0.3f;
    const LobePlot plot = makeLobePlot(settings);
    for (const LobeCurve& c : plot.curves) {
        size_t best = 0;
        for (size_t i = 0; i < c.polar.size(); ++i)
            if (c.polar[i] > c.polar[best]) best = i;
        EXPECT_NEAR(plot.polarAngleAt(int(best)), 40.0f, 3.0f) << c.label;
        EXPECT_NEAR(c.polar[best], 1.0f, 1e-6f) << c.label;
        EXPECT_GT(c.peak, 0.0f) << c.label;
    }
    // The pbr lobe narrows as roughness falls (its half-width read from the Cartesian data).
    std::vector<float> widths;
    for (float r : {1.0f, 0.7f, 0.5f, 0.3f, 0.2f, 0.1f}) {
        settings.roughness = r;
        const LobePlot p = makeLobePlot(settings);
        widths.push_back(halfWidthAtHalfMaximum(p.curves[size_t(LobeModel::Pbr)].value, 90.0f));
    }
    EXPECT_TRUE(strictlyShrinking(widths));
    // disney's lobe narrows with roughness too, and anisotropy widens it in the plane of incidence (which here
    // holds the tangent along which it stretches); a coat adds its sharp peak (the label says so).
    std::vector<float> disney;
    for (float r : {1.0f, 0.7f, 0.5f, 0.3f, 0.2f}) {
        settings.roughness = r;
        disney.push_back(halfWidthAtHalfMaximum(makeLobePlot(settings).curves[size_t(LobeModel::Disney)].value, 90.0f));
    }
    EXPECT_TRUE(strictlyShrinking(disney));
    settings.roughness = 0.4f;
    const float isotropic =
        halfWidthAtHalfMaximum(makeLobePlot(settings).curves[size_t(LobeModel::Disney)].value, 90.0f);
    settings.disney0.w = 0.9f;
    const float stretched =
        halfWidthAtHalfMaximum(makeLobePlot(settings).curves[size_t(LobeModel::Disney)].value, 90.0f);
    EXPECT_GT(stretched, 1.3f * isotropic);
    settings.disney1.z = 1.0f;
    EXPECT_NE(makeLobePlot(settings).curves[size_t(LobeModel::Disney)].label.find("+ coat"), std::string::npos);
    // The probe's vectors in the plane of incidence: L on the left, R its mirror, V out of the plane.
    const glm::vec3 N(0, 1, 0), L = glm::normalize(glm::vec3(-1, 1, 0)), V = glm::normalize(glm::vec3(0.5f, 1, 0.5f));
    const PlaneOfIncidence pi = planeOfIncidence(N, L, V);
    EXPECT_NEAR(pi.incidence, 45.0f, 1e-3f);
    EXPECT_NEAR(pi.L.x, -pi.R.x, 1e-6f);
    EXPECT_LT(pi.L.x, 0.0f);
    EXPECT_NEAR(pi.vOutOfPlane, std::asin(0.5f / glm::length(glm::vec3(0.5f, 1, 0.5f))) * 180.0f / M_PI, 1e-3f);
}

TEST(AlbedoPlot, CurvesTellWhichModelsKeepTheirEnergy) {
    AlbedoPlotSettings settings;
    settings.phongExponent = 64.0f;
    settings.roughness = 1.0f;
    const AlbedoPlot plot = makeAlbedoPlot(settings);
    ASSERT_EQ(plot.curves.size(), 11u);
    for (float v : plot.curves[0].albedo) EXPECT_NEAR(v, 1.0f, 3e-3f);  // Lambert
    EXPECT_NEAR(plot.curves[1].albedo.front(), 2.0f / 65.0f, 2e-3f);    // Phong: 2/(s+1)
    EXPECT_NEAR(plot.curves[2].albedo.front(), 66.0f / 65.0f, 5e-3f);   // normalised
    for (float v : plot.curves[5].albedo) EXPECT_LT(v, 0.999f);         // GGX loses
    // With compensation a white metal keeps its energy (within 1 %), away from grazing angles.
    EXPECT_EQ(plot.curves[6].label, "GGX  compensated");
    for (size_t i = 0; i < plot.viewAngles.size(); ++i)
        if (plot.viewAngles[i] <= 75.0f) {
            EXPECT_NEAR(plot.curves[6].albedo[i], 1.0f, 0.015f) << plot.viewAngles[i];
        }
    // disney: its diffuse keeps more than Lambert toward grazing on a rough surface (the retro-reflection), its
    // white metal is a GGX lobe that loses more than pbr's (the separable Smith term shadows more than the
    // height-correlated one, Heitz 2014), and the coat alone reflects a few per cent, more toward grazing.
    EXPECT_EQ(plot.curves[7].label, "Disney diffuse, white");
    EXPECT_GT(plot.curves[7].albedo.back(), plot.curves[7].albedo.front());
    EXPECT_GT(plot.curves[7].albedo.back(), 1.0f);
    for (size_t i = 0; i < plot.viewAngles.size(); ++i) {
        EXPECT_LT(plot.curves[8].albedo[i], 0.999f);
        EXPECT_LE(plot.curves[8].albedo[i], plot.curves[5].albedo[i] + 1e-3f) << plot.viewAngles[i];
        EXPECT_GT(plot.curves[8].albedo[i], 0.6f * plot.curves[5].albedo[i]) << plot.viewAngles[i];
    }
    EXPECT_GT(plot.curves[9].albedo.front(), 0.005f);
    EXPECT_LT(plot.curves[9].albedo.front(), 0.05f);
    EXPECT_GT(plot.curves[9].albedo.back(), plot.curves[9].albedo.front());
    // glTF's sheen alone: the albedo the renderers read from their table (to 0.03 on the plot's coarse quadrature,
    // up to 80°), rising toward grazing; another roughness's table row does not match (negative control).
    EXPECT_EQ(plot.curves[10].label, "glTF sheen  roughness 0.50");
    float offRow = 0.0f;
    for (size_t i = 0; i < plot.viewAngles.size(); ++i) {
        if (plot.viewAngles[i] > 80.0f) continue;
        const float mu = std::cos(plot.viewAngles[i] * float(M_PI) / 180.0f);
        EXPECT_NEAR(plot.curves[10].albedo[i], shading::sheenAlbedoAt(mu, 0.5f), 0.03f) << plot.viewAngles[i];
        offRow = std::max(offRow, std::abs(plot.curves[10].albedo[i] - shading::sheenAlbedoAt(mu, 0.2f)));
    }
    EXPECT_GT(offRow, 0.05f);
    EXPECT_GT(plot.curves[10].albedo.back(), plot.curves[10].albedo.front());
    // The hook: a curve from any shade function.
    AlbedoPlot copy = plot;
    addAlbedoCurve(copy, "half Lambert",
                   [](const shading::vec3& L, const shading::vec3&) { return 0.5f * std::max(L.z, 0.0f); });
    EXPECT_NEAR(copy.curves.back().albedo[3], 0.5f, 2e-3f);
}

// The plot shown before lends the curves whose inputs did not change: for a change of each input, the plot
// made with it equals the plot made from nothing, curve for curve and value for value. The curves that
// depend on the changed input do change (so a curve lent when it should not be would be seen), and a previous
// plot of other view angles lends nothing.
TEST(AlbedoPlot, CurvesLentByThePreviousPlotEqualCurvesIntegratedAgain) {
    const auto same = [](const AlbedoPlot& a, const AlbedoPlot& b) {
        if (a.curves.size() != b.curves.size() || a.viewAngles != b.viewAngles) return false;
        for (size_t k = 0; k < a.curves.size(); ++k)
            if (a.curves[k].label != b.curves[k].label || a.curves[k].albedo != b.curves[k].albedo ||
                a.curves[k].dashed != b.curves[k].dashed)
                return false;
        return true;
    };
    AlbedoPlotSettings base;
    base.phongExponent = 40.0f;
    base.roughness = 0.3f;
    base.clearcoatGloss = 0.8f;
    base.sheenRoughness = 0.4f;
    base.quadrature = {48, 24};  // coarser than the panel's: the lending, not the integral, is under test
    const AlbedoPlot before = makeAlbedoPlot(base);
    struct Change {
        const char* what;
        void (*apply)(AlbedoPlotSettings&);
        std::vector<size_t> changed;  // the curves that depend on it
    };
    const std::vector<Change> changes = {
        {"s", [](AlbedoPlotSettings& s) { s.phongExponent = 90.0f; }, {1, 2, 3, 4}},
        {"roughness", [](AlbedoPlotSettings& s) { s.roughness = 0.6f; }, {5, 6, 7, 8, 9}},
        {"coat gloss", [](AlbedoPlotSettings& s) { s.clearcoatGloss = 0.2f; }, {9}},
        {"sheen roughness", [](AlbedoPlotSettings& s) { s.sheenRoughness = 0.9f; }, {10}},
        {"nothing", [](AlbedoPlotSettings&) {}, {}},
    };
    for (const Change& c : changes) {
        AlbedoPlotSettings next = base;
        c.apply(next);
        const AlbedoPlot fresh = makeAlbedoPlot(next), lent = makeAlbedoPlot(next, &before);
        EXPECT_TRUE(same(lent, fresh)) << c.what;
        for (size_t k = 0; k < fresh.curves.size(); ++k) {
            const bool depends = std::find(c.changed.begin(), c.changed.end(), k) != c.changed.end();
            EXPECT_EQ(fresh.curves[k].albedo != before.curves[k].albedo, depends) << c.what << ", curve " << k;
        }
    }
    // Another set of view angles: nothing is lent, and the plot is still right.
    AlbedoPlotSettings fewer = base;
    fewer.angles = 7;
    EXPECT_TRUE(same(makeAlbedoPlot(fewer, &before), makeAlbedoPlot(fewer)));
    // A normalised lobe's albedo is the lobe's times its constant.
    for (size_t i = 0; i < before.viewAngles.size(); ++i)
        EXPECT_FLOAT_EQ(before.curves[2].albedo[i], shading::phongNormalization(40.0f) * before.curves[1].albedo[i]);
}
