// Viewer: what is drawn over the image: the probe's arrow labels and its ray tree, the light markers with a
// spot's cone, the captions and the toast.
#include "app/viewer.h"

#include "app/captions.h"
#include "app/light_markers.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab::app {

// Labels inside the image only: an arrow cut at the image's edge must not label the panel beside it. Under
// the windows, as the arrows are: the probe window stays readable over them.
void Viewer::drawArrowLabels(const std::vector<ArrowLabel>& labels) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    for (const ArrowLabel& l : labels) {
        const ImVec2 at(l.position.x / layout_.fbScale + 6.0f * shape_.uiScale,
                        l.position.y / layout_.fbScale - 10.0f * shape_.uiScale);
        if (at.x < layout_.imageX || at.y < layout_.imageY || at.x > layout_.imageX + layout_.imageW ||
            at.y > layout_.imageY + layout_.imageH)
            continue;
        const ImU32 color = ImGui::ColorConvertFloat4ToU32(ImVec4(l.color.r, l.color.g, l.color.b, 1.0f));
        dl->AddText(ImVec2(at.x + 1.0f, at.y + 1.0f), IM_COL32(0, 0, 0, 255), l.text.c_str());
        dl->AddText(at, color, l.text.c_str());
    }
}

// The ray tree as arrows in the view, each labelled at its middle; the ray whose algebra the probe window
// shows drawn wider. Rays that leave the scene are drawn as long as the eye is from the probed point.
void Viewer::drawRayTree() {
    const float escape = glm::length(probe_.result->P - rayTree_.view->primary.origin);
    std::vector<ArrowSegment> segments;
    for (const RayTreeSegment& s : rayTreeSegments(state_.scene, rayTree_.view->record, escape)) {
        const bool chosen = s.ray == fields_.rayTreeRay;
        segments.push_back({s.from, s.to, s.color, s.label, 0.5f, chosen ? 1.6f : 0.8f});
    }
    drawArrowLabels(arrows_->draw(state_.scene, segments, layout_.renderWidth, layout_.renderHeight, layout_.fbRect,
                                  shape_.fbHeight, layout_.fbScale * shape_.uiScale));
}

// A marker per light (light_markers.h): a disc in the light's colour, an arrow for a directional light, and
// its name; the one under the pointer or being dragged is ringed.
void Viewer::drawLightMarkers() {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const std::vector<LightMarker> markers = lightMarkers(state_.scene, layout_.renderWidth, layout_.renderHeight);
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const int hover =
        pointer_.light >= 0 ? pointer_.light : markerAt(markers, imagePixelF(mouse.x, mouse.y), markerPickRadius());
    const float r = 7.0f * shape_.uiScale;
    for (const LightMarker& m : markers) {
        if (!m.visible) continue;
        const ImVec2 at = windowPoint(m.shown);
        const Light& light = state_.scene.lights[size_t(m.light)];
        const glm::vec3 c = splitIntensity(light.color).color;
        const ImU32 fill = ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
        if (m.clamped) {  // outside the image: a pointer from the edge toward where the light is
            const glm::vec2 d = glm::normalize(m.pixel - m.shown);
            const ImVec2 p0(at.x + d.x * (r + 9.0f * shape_.uiScale), at.y + d.y * (r + 9.0f * shape_.uiScale));
            const ImVec2 side(-d.y * 5.0f * shape_.uiScale, d.x * 5.0f * shape_.uiScale);
            const ImVec2 base(at.x + d.x * (r + 2.0f * shape_.uiScale), at.y + d.y * (r + 2.0f * shape_.uiScale));
            dl->AddTriangleFilled(p0, ImVec2(base.x + side.x, base.y + side.y),
                                  ImVec2(base.x - side.x, base.y - side.y), IM_COL32(255, 255, 255, 220));
        } else if (light.type != LightType::Point) {  // directional and spot: an arrow along the light
            const ImVec2 tip = windowPoint(m.arrowTip);
            if (!m.coneRim.empty()) {  // a spot's outer cone: its rim, and two edges from the light to it
                std::vector<ImVec2> rim;
                for (const glm::vec2& p : m.coneRim) rim.push_back(windowPoint(p));
                dl->AddPolyline(rim.data(), int(rim.size()), IM_COL32(0, 0, 0, 160), ImDrawFlags_Closed,
                                3.0f * shape_.uiScale);
                dl->AddPolyline(rim.data(), int(rim.size()), fill, ImDrawFlags_Closed, 1.5f * shape_.uiScale);
                // The cone's outline from the light: the rim points seen at the widest angles either side.
                glm::vec2 axis(0.0f);
                for (const ImVec2& p : rim) axis += glm::vec2(p.x - at.x, p.y - at.y) / float(rim.size());
                size_t lo = 0, hi = 0;
                float loA = INFINITY, hiA = -INFINITY;
                for (size_t k = 0; k < rim.size(); ++k) {
                    const glm::vec2 d(rim[k].x - at.x, rim[k].y - at.y);
                    const float a = std::atan2(axis.x * d.y - axis.y * d.x, glm::dot(axis, d));
                    if (a < loA) loA = a, lo = k;
                    if (a > hiA) hiA = a, hi = k;
                }
                for (size_t k : {lo, hi}) dl->AddLine(at, rim[k], fill, 1.0f * shape_.uiScale);
            }
            dl->AddLine(at, tip, IM_COL32(0, 0, 0, 200), 4.0f * shape_.uiScale);
            dl->AddLine(at, tip, fill, 2.0f * shape_.uiScale);
            dl->AddCircleFilled(tip, 3.0f * shape_.uiScale, fill);
        }
        dl->AddCircleFilled(at, r + 1.5f * shape_.uiScale, IM_COL32(0, 0, 0, 200));
        dl->AddCircleFilled(at, r, fill);
        if (m.light == hover)
            dl->AddCircle(at, r + 4.0f * shape_.uiScale, IM_COL32(255, 220, 60, 255), 0, 2.0f * shape_.uiScale);
        const std::string name = "L" + std::to_string(m.light + 1);
        const bool leftSide =
            at.x > layout_.imageX + layout_.imageW - 40.0f * shape_.uiScale;  // keep the name inside the image
        const ImVec2 text(leftSide ? at.x - r - 22.0f * shape_.uiScale : at.x + r + 3.0f * shape_.uiScale, at.y - r);
        dl->AddText(ImVec2(text.x + 1.0f, text.y + 1.0f), IM_COL32(0, 0, 0, 255), name.c_str());
        dl->AddText(text, IM_COL32(255, 255, 255, 255), name.c_str());
    }
}

// kMarkerPickRadius window units, in image pixels.
float Viewer::markerPickRadius() const {
    return kMarkerPickRadius * shape_.uiScale * float(layout_.renderWidth) / std::max(layout_.imageW, 1.0f);
}

ImVec2 Viewer::windowPoint(glm::vec2 pixel) const {
    return ImVec2(layout_.imageX + pixel.x / float(layout_.renderWidth) * layout_.imageW,
                  layout_.imageY + pixel.y / float(layout_.renderHeight) * layout_.imageH);
}

glm::vec2 Viewer::imagePixelF(float windowX, float windowY) const {
    return {(windowX - layout_.imageX) / layout_.imageW * float(layout_.renderWidth),
            (windowY - layout_.imageY) / layout_.imageH * float(layout_.renderHeight)};
}

// Captions over the image, under every ImGui window (the background draw list): the model, the terms and
// the mode at the top left, and in Split and Local | Global the two sides' names either side of the wipe.
// One type size for all of them, whatever they say: a long caption wraps, it never shrinks, so it reads the
// same from the back of the room.
void Viewer::drawCaptions() {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    ImFont* font = window_.captionFont ? window_.captionFont : ImGui::GetFont();
    const float size = font->FontSize * ImGui::GetIO().FontGlobalScale;
    const float pad = 4.0f * shape_.uiScale, margin = 10.0f * shape_.uiScale;
    const float left = visibleLeft(), right = layout_.imageX + layout_.imageW;
    auto extentOf = [&](const char* text, float wrap) { return font->CalcTextSizeA(size, 1e9f, wrap, text); };
    auto box = [&](ImVec2 at, ImVec2 extent, const char* text, float wrap) {
        dl->AddRectFilled(at, ImVec2(at.x + extent.x + 2.0f * pad, at.y + extent.y + 2.0f * pad),
                          IM_COL32(0, 0, 0, 150), 3.0f * shape_.uiScale);
        dl->AddText(font, size, ImVec2(at.x + pad, at.y + pad), IM_COL32(255, 255, 255, 235), text, nullptr, wrap);
        return extent.y + 2.0f * pad;
    };
    const std::string caption =
        imageCaption(state_, GlobalCaption{global_->samples(), global_->noise8(), showsDenoised()});
    // Below the row where lights outside the frame put their markers (light_markers.h).
    const float top =
        layout_.imageY + margin +
        (fields_.lightMarkers ? 2.0f * kMarkerInset * layout_.imageH / float(layout_.renderHeight) : 0.0f);
    const float wrap = std::max(right - left - 2.0f * (margin + pad), 1.0f);
    const float height = box(ImVec2(left + margin, top), extentOf(caption.c_str(), wrap), caption.c_str(), wrap);
    const WipeCaptions sides = wipeCaptions(state_.mode);
    if (!hasWipe(state_.mode)) return;
    // Each label wraps to the room on its side of the wipe; one whose longest word does not fit is left out.
    const float wipe = layout_.imageX + wipeFraction() * layout_.imageW, gap = 6.0f * shape_.uiScale;
    const float leftWrap = std::max(wipe - gap - left - 2.0f * pad, 1.0f);
    const float rightWrap = std::max(right - wipe - gap - 2.0f * pad, 1.0f);
    const ImVec2 leftExtent = extentOf(sides.left, leftWrap), rightExtent = extentOf(sides.right, rightWrap);
    // ImGui breaks a word wider than the wrap: such a label counts as wider than its side, so it is left out.
    auto widthOn = [&](const char* text, float room, float extent) {
        std::string word;
        float widest = 0.0f;
        for (const char* c = text;; ++c) {
            if (*c != ' ' && *c != '\0') {
                word += *c;
                continue;
            }
            widest = std::max(widest, extentOf(word.c_str(), 0.0f).x);
            word.clear();
            if (*c == '\0') break;
        }
        return (widest > room ? 1e9f : extent) + 2.0f * pad;
    };
    const WipeLabelPlacement at = placeWipeLabels(left, right, wipe, gap, widthOn(sides.left, leftWrap, leftExtent.x),
                                                  widthOn(sides.right, rightWrap, rightExtent.x));
    const float y = top + height + gap;
    if (at.leftShown) box(ImVec2(at.leftX, y), leftExtent, sides.left, leftWrap);
    if (at.rightShown) box(ImVec2(at.rightX, y), rightExtent, sides.right, rightWrap);
}

// Over every window (the foreground list), centred at the bottom of what the panel leaves of the image: at UI
// scale 2 the panel's own status line can be scrolled out of view, and a class must see a refused save.
void Viewer::drawToast() {
    if (status_.message.empty() || glfwGetTime() - status_.time >= kStatusSeconds) return;
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    ImFont* font = ImGui::GetFont();
    const float size = font->FontSize * ImGui::GetIO().FontGlobalScale;
    const float pad = 6.0f * shape_.uiScale, margin = 12.0f * shape_.uiScale;
    const float left = visibleLeft(), right = layout_.imageX + layout_.imageW;
    const float wrap = std::max(right - left - 2.0f * (margin + pad), 1.0f);
    const ImVec2 extent = font->CalcTextSizeA(size, 1e9f, wrap, status_.message.c_str());
    const float x = std::max(left + margin, 0.5f * (left + right) - 0.5f * extent.x - pad);
    const float y = std::max(layout_.imageY, layout_.imageY + layout_.imageH - margin - extent.y - 2.0f * pad);
    dl->AddRectFilled(ImVec2(x, y), ImVec2(x + extent.x + 2.0f * pad, y + extent.y + 2.0f * pad),
                      status_.error ? IM_COL32(150, 30, 30, 230) : IM_COL32(25, 95, 45, 230), 4.0f * shape_.uiScale);
    dl->AddText(font, size, ImVec2(x + pad, y + pad), IM_COL32(255, 255, 255, 255), status_.message.c_str(), nullptr,
                wrap);
}

}  // namespace shadelab::app
