// makeLobePlot: the five specular lobes in the plane of incidence, from the shared shading functions.
#include "app/lobe_plot.h"

#include "app/specular_lobe.h"
#include "shading/lighting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

namespace shadelab::app {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

glm::vec3 inPlane(double degrees) {  // x toward R's side, z along N
    return {float(std::sin(degrees * kDegree)), 0.0f, float(std::cos(degrees * kDegree))};
}

// The specular term one light of intensity 1 adds, for V at outgoing angle θo (degrees).
float lobeValue(LobeModel model, float parameter, const LobePlotSettings& s, double thetaO) {
    using namespace shading;
    const vec3 N(0.0f, 0.0f, 1.0f), L = inPlane(-double(s.incidence)), V = inPlane(thetaO);
    switch (model) {
        case LobeModel::Phong: return specularPhong(N, L, V, parameter);
        case LobeModel::BlinnSame:
        case LobeModel::BlinnEquivalent: return specularBlinnPhong(N, L, V, parameter);
        case LobeModel::Pbr: {
            vec3 spec;
            if (s.layered) {  // glTF's specular layer and index, and its anisotropy
                const vec4 aniso(anisotropyDirection(N, vec4(0.0f), s.aniso), s.aniso.x);
                spec = shadeLightPbrSpecular(N, L, V, vec3(1.0f), vec3(0.0f), s.baseColor, s.metallic, parameter,
                                             s.specLayer, aniso, false, true, vec3(1.0f));
            } else {
                const vec3 f0 = pbrF0(s.baseColor, s.metallic);
                spec = SL_PI * std::max(dot(N, L), 0.0f) * specularGGX(N, L, V, f0, parameter);
            }
            if (s.coat.x > 0.0f) spec = clearcoatLight(spec, N, L, V, vec3(1.0f), s.coat, true);
            return (spec.x + spec.y + spec.z) / 3.0f;
        }
        case LobeModel::Disney: {
            const vec3 spec = shadeLightDisney(N, L, V, vec3(1.0f), s.baseColor, s.metallic, parameter, s.disney0,
                                               s.disney1, false, true, vec3(1.0f));
            return (spec.x + spec.y + spec.z) / 3.0f;
        }
    }
    return 0.0f;
}

// pbr's light through a transmitting surface toward a viewer below it at θo from −N, for the light above at −θi:
// transmissionLight seen from that side (its normal −N, the light behind), the mean of its RGB.
float throughValue(const LobePlotSettings& s, double thetaO) {
    using namespace shading;
    const vec3 N(0.0f, 0.0f, 1.0f), L = inPlane(-double(s.incidence)), V = -inPlane(-thetaO);
    const vec3 tc = pbrDiffuseColor(s.baseColor, s.metallic) * s.transmission.x;
    const vec3 I = transmissionLight(-N, L, V, vec3(1.0f), tc, vec3(1.0f), s.specLayer, s.roughness * s.transmission.y,
                                     true, true);
    return (I.x + I.y + I.z) / 3.0f;
}

}  // namespace

float LobePlot::angleAt(int i) const {
    const int n = settings.samples;
    return n > 1 ? settings.axis * float(i) / float(n - 1) : 0.0f;
}

float LobePlot::polarAngleAt(int i) const {
    const int n = settings.polarSamples;
    return n > 1 ? -90.0f + 180.0f * float(i) / float(n - 1) : 0.0f;
}

LobePlot makeLobePlot(const LobePlotSettings& in) {
    LobePlot plot;
    LobePlotSettings& s = plot.settings;
    s = in;
    s.incidence = std::clamp(std::isfinite(s.incidence) ? s.incidence : 0.0f, 0.0f, 89.0f);
    s.axis = std::clamp(std::isfinite(s.axis) ? s.axis : 90.0f, 0.5f, 90.0f);
    s.samples = std::max(s.samples, 2);
    s.polarSamples = std::max(s.polarSamples, 3);
    s.phongExponent = std::max(s.phongExponent, 0.0f);
    s.roughness = std::clamp(s.roughness, 0.0f, 1.0f);

    const float sp = s.phongExponent, sb = equivalentBlinnExponent(sp);
    char label[96];
    for (int m = 0; m < kLobeModels; ++m) {
        LobeCurve c;
        c.model = LobeModel(m);
        switch (c.model) {
            case LobeModel::Phong:
                c.parameter = sp;
                std::snprintf(label, sizeof label, "(R·V)^%.0f  Phong", double(sp));
                break;
            case LobeModel::BlinnSame:
                c.parameter = sp;
                std::snprintf(label, sizeof label, "(N·H)^%.0f  Blinn-Phong, same s", double(sp));
                break;
            case LobeModel::BlinnEquivalent:
                c.parameter = sb;
                std::snprintf(label, sizeof label, "(N·H)^%.0f  Blinn, equivalent s'", double(sb));
                break;
            case LobeModel::Pbr:
                c.parameter = s.roughness;
                std::snprintf(label, sizeof label, "GGX  pbr, roughness %.2f%s%s%s", double(s.roughness),
                              s.layered && s.aniso.x > 0.0f ? " + aniso" : "", s.coat.x > 0.0f ? " + coat" : "",
                              s.transmission.x > 0.0f ? " + through" : "");
                break;
            case LobeModel::Disney:
                c.parameter = s.roughness;
                std::snprintf(label, sizeof label, "disney, roughness %.2f%s", double(s.roughness),
                              s.disney1.z > 0.0f ? " + coat" : "");
                break;
        }
        c.label = label;
        c.polar.resize(size_t(s.polarSamples));
        for (int i = 0; i < s.polarSamples; ++i)
            c.polar[size_t(i)] = lobeValue(c.model, c.parameter, s, plot.polarAngleAt(i));
        c.value.resize(size_t(s.samples));
        for (int i = 0; i < s.samples; ++i)
            c.value[size_t(i)] = lobeValue(c.model, c.parameter, s, double(s.incidence) - double(plot.angleAt(i)));
        // The peak: the mirror direction itself (where every lobe but an off-specular GGX one peaks) and both
        // sweeps.
        c.peak = lobeValue(c.model, c.parameter, s, double(s.incidence));
        for (float v : c.polar) c.peak = std::max(c.peak, v);
        for (float v : c.value) c.peak = std::max(c.peak, v);
        if (c.peak > 0.0f)
            for (float& v : c.value) v /= c.peak;
        // The light through a transmitting surface, on the polar plot's scale with the reflection.
        float polarPeak = c.peak;
        if (c.model == LobeModel::Pbr && s.transmission.x > 0.0f) {
            c.through.resize(size_t(s.polarSamples));
            for (int i = 0; i < s.polarSamples; ++i) {
                c.through[size_t(i)] = throughValue(s, plot.polarAngleAt(i));
                polarPeak = std::max(polarPeak, c.through[size_t(i)]);
            }
            for (float& v : c.through) v /= polarPeak;
        }
        if (polarPeak > 0.0f)
            for (float& v : c.polar) v /= polarPeak;
        plot.curves.push_back(std::move(c));
    }
    return plot;
}

LobePlotSettings lobeSettingsOf(const Material& m) {
    LobePlotSettings s;
    s.roughness = m.roughness;
    s.metallic = m.metallic;
    s.baseColor = m.baseColor;
    s.disney0 = m.disney.lobes0();
    s.disney1 = m.disney.lobes1();
    s.layered = usesLayeredPbr(m);
    s.specLayer = m.specular.packed(m.ior);
    s.aniso = m.anisotropy.packed();
    s.coat = m.clearcoat.packed();
    s.transmission = transmissionPacked(m);
    return s;
}

float halfWidthAtHalfMaximum(const std::vector<float>& value, float axis) {
    if (value.size() < 2) return axis;
    const float half = 0.5f * value.front();
    const float step = axis / float(value.size() - 1);
    for (size_t i = 1; i < value.size(); ++i) {
        if (value[i] >= half) continue;
        const float a = value[i - 1], b = value[i];
        const float t = a > b ? (a - half) / (a - b) : 0.0f;
        return step * (float(i - 1) + t);
    }
    return axis;
}

glm::vec2 polarDirection(float degrees) {
    return {float(std::sin(double(degrees) * kDegree)), float(std::cos(double(degrees) * kDegree))};
}

PlaneOfIncidence planeOfIncidence(const glm::vec3& Nin, const glm::vec3& Lin, const glm::vec3& Vin) {
    PlaneOfIncidence p;
    const glm::vec3 N = glm::normalize(Nin), L = glm::normalize(Lin), V = glm::normalize(Vin);
    // The tangent toward R's side is −(L's tangential part); with L along N, V's tangential part picks it.
    glm::vec3 t = -(L - glm::dot(N, L) * N);
    if (glm::dot(t, t) < 1e-10f) t = V - glm::dot(N, V) * N;
    if (glm::dot(t, t) < 1e-10f)
        t = std::fabs(N.x) < 0.9f ? glm::cross(N, glm::vec3(1, 0, 0)) : glm::cross(N, glm::vec3(0, 1, 0));
    t = glm::normalize(t);
    const glm::vec3 b = glm::cross(N, t);  // normal of the plane of incidence
    auto project = [&](const glm::vec3& v) {
        const glm::vec2 q(glm::dot(v, t), glm::dot(v, N));
        const float len = glm::length(q);
        return len > 1e-8f ? q / len : glm::vec2(0.0f, 1.0f);
    };
    const glm::vec3 R = 2.0f * glm::dot(N, L) * N - L;
    p.L = project(L);
    p.V = project(V);
    p.R = project(R);
    p.incidence = float(std::acos(std::clamp(double(glm::dot(N, L)), -1.0, 1.0)) / kDegree);
    p.vOutOfPlane = float(std::asin(std::clamp(double(std::fabs(glm::dot(V, b))), 0.0, 1.0)) / kDegree);
    return p;
}

}  // namespace shadelab::app
