// The rendering equation at the probed point (probe/rendering_equation.h), in the probe window: the three
// hemispheres as small images (each scaled to its own brightest texel, sRGB-encoded for display), the
// delta lights ringed where they fall, and the integral's parts written beside the pixel's value.
#include "app/panels.h"

#include "image/encode.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace shadelab::app {
namespace {

float maxChannel(const std::vector<glm::vec3>& image) {
    float m = 0.0f;
    for (const glm::vec3& c : image) m = std::max({m, c.r, c.g, c.b});
    return m;
}

// One hemisphere image at the cursor, `side` window units square, with its caption under it.
void hemisphere(const RenderingEquation& re, const std::vector<glm::vec3>& image, const char* caption, float side,
                float uiScale) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float scale = maxChannel(image);
    const float cell = side / float(re.size);
    for (int j = 0; j < re.size; ++j)
        for (int i = 0; i < re.size; ++i) {
            const glm::vec3 c = scale > 0.0f ? image[size_t(j) * size_t(re.size) + size_t(i)] / scale : glm::vec3(0.0f);
            const ImU32 col = IM_COL32(encodeChannel(c.r, Encoding::Srgb), encodeChannel(c.g, Encoding::Srgb),
                                       encodeChannel(c.b, Encoding::Srgb), 255);
            const ImVec2 p0(at.x + float(i) * cell, at.y + float(j) * cell);
            dl->AddRectFilled(p0, ImVec2(p0.x + cell + 0.5f, p0.y + cell + 0.5f), col);
        }
    // The point, spot and directional lights: deltas, no area of the image; a ring where each falls.
    for (const HemisphereLight& l : re.lights) {
        if (!l.above) continue;
        const ImVec2 c(at.x + l.at.x * side, at.y + l.at.y * side);
        dl->AddCircle(c, 4.0f * uiScale, IM_COL32(0, 0, 0, 255), 12, 3.0f * uiScale);
        dl->AddCircle(c, 4.0f * uiScale, l.visible ? IM_COL32(255, 220, 60, 255) : IM_COL32(255, 70, 50, 255), 12,
                      1.5f * uiScale);
    }
    ImGui::Dummy(ImVec2(side, side));
    ImGui::TextDisabled("%s", caption);
    ImGui::TextDisabled("white = %.3g", double(scale));
}

}  // namespace

void drawRenderingEquation(const RenderingEquation& re, float uiScale) {
    if (!re.hit) {
        ImGui::TextDisabled("the background: no surface, no integral");
        return;
    }
    ImGui::TextUnformatted(
        "L_out = L_e + \xe2\x88\xab f(\xcf\x89_in, \xcf\x89_out) L_in(\xcf\x89_in) cos \xce\xb8 d\xcf\x89");
    const float side = 80.0f * uiScale;
    ImGui::BeginGroup();
    hemisphere(re, re.incoming, re.global ? "L_in (scene)" : "L_in (ambient)", side, uiScale);
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    hemisphere(re, re.brdfCos,
               "f\xc2\xb7"
               "cos \xce\xb8",
               side, uiScale);
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    hemisphere(re, re.product, "product", side, uiScale);
    ImGui::EndGroup();
    const glm::vec3 &e = re.emission, &l = re.lightSum, &i = re.imageIntegral, &t = re.total;
    ImGui::Text("L_e                      %.3f %.3f %.3f", e.r, e.g, e.b);
    ImGui::Text("lights (rings) \xce\xa3 \xcf\x80 f Il cos \xce\xb8 vis  %.3f %.3f %.3f", l.r, l.g, l.b);
    if (re.global) {
        ImGui::Text("\xe2\x88\xab over the images         %.3f %.3f %.3f  \xc2\xb1 %.2g", i.r, i.g, i.b,
                    double(std::max({re.imageError.r, re.imageError.g, re.imageError.b})));
    } else {
        ImGui::Text("Ia \xc2\xb7 ma (stands in for \xe2\x88\xab) %.3f %.3f %.3f", re.ambient.r, re.ambient.g,
                    re.ambient.b);
        ImGui::TextDisabled("(the ambient as sky light would give \xe2\x88\xab = %.3f %.3f %.3f)", i.r, i.g, i.b);
    }
    ImGui::Text("L_out                    %.3f %.3f %.3f", t.r, t.g, t.b);
    if (re.deltaLobes) ImGui::TextDisabled("+ the mirror and glass rays (kr, kt): the ray tree's, not drawn here");
    ImGui::TextDisabled(re.global ? "path traced from the point (Global modes)"
                                  : "the local model: lights are deltas, the rest is Ia\xc2\xb7ma");
}

}  // namespace shadelab::app
