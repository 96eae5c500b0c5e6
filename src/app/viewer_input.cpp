// Viewer input: orbit/pan/zoom and click-to-probe on the image, the split wipe, keyboard shortcuts, and
// drag and drop of scene files. Everything goes through the viewer_state.h actions.
#include "app/viewer.h"

#include "app/light_markers.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace shadelab::app {
namespace {

constexpr float kRadiansPerPixel = 0.008f;
constexpr float kClickSlop = 3.0f;  // window units a press may move and still count as a click

bool sceneExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".json" || ext == ".gltf" || ext == ".glb";
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
    if (viewer)
        for (int i = 0; i < count; ++i) viewer->queueDrop(paths[i]);
}

// Installed before Dear ImGui's own, which calls it in turn: every press is kept until the next frame, so a
// press and release that arrive together (a presenter's clicker, xdotool, a frame slept through while
// idle) still count. ImGui 1.86 sees only the key state at the frame, which would miss them.
void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
    if (viewer && action == GLFW_PRESS) viewer->queueKey(key, mods);
}

}  // namespace

void installInputCallbacks(GLFWwindow* window) {
    glfwSetDropCallback(window, onDrop);
    glfwSetKeyCallback(window, onKey);
}

void Viewer::queueKey(int key, int mods) { queued_.keys.push_back({key, mods}); }

void Viewer::queueDrop(const std::string& path) { queued_.drops.push_back(path); }

void Viewer::handleDrops() {
    std::vector<std::string> drops;
    drops.swap(queued_.drops);
    for (const std::string& path : drops) {
        if (!sceneExtension(path)) {
            setStatus(path + ": not a scene (.json, .gltf or .glb)", true);
            continue;
        }
        openScene(path);
        break;  // one scene at a time: the first that is one
    }
}

glm::ivec2 Viewer::imagePixelAt(float windowX, float windowY) const {
    return {int(std::floor((windowX - layout_.imageX) / layout_.imageW * float(layout_.renderWidth))),
            int(std::floor((windowY - layout_.imageY) / layout_.imageH * float(layout_.renderHeight)))};
}

void Viewer::handleMouse() {
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 m = io.MousePos;
    const bool overImage = m.x >= layout_.imageX && m.x < layout_.imageX + layout_.imageW && m.y >= layout_.imageY &&
                           m.y < layout_.imageY + layout_.imageH;
    if (!io.WantCaptureMouse && overImage) {
        int marker = -1;
        if (fields_.lightMarkers && ImGui::IsMouseClicked(0)) {
            // A spot's arrow tip aims it (unless its own disc is under the pointer too); elsewhere a light's
            // marker moves the light, not the camera.
            const std::vector<LightMarker> markers =
                lightMarkers(state_.scene, layout_.renderWidth, layout_.renderHeight);
            const glm::vec2 at = imagePixelF(m.x, m.y);
            marker = aimHandleAt(state_.scene, markers, at, markerPickRadius());
            pointer_.aiming = marker >= 0 && markerAt(markers, at, markerPickRadius()) != marker;
            if (!pointer_.aiming) marker = markerAt(markers, at, markerPickRadius());
        }
        if (marker >= 0) {
            pointer_.light = marker;
        } else if (ImGui::IsMouseClicked(0)) {
            pointer_.leftDown = true;
            pointer_.dragged = false;
            pointer_.pressX = m.x;
            pointer_.pressY = m.y;
            const float wipe = layout_.imageX + wipeFraction() * layout_.imageW;
            pointer_.splitting = hasWipe(state_.mode) && std::fabs(m.x - wipe) < 8.0f * shape_.uiScale;
        }
        if (ImGui::IsMouseClicked(1) || ImGui::IsMouseClicked(2)) pointer_.panning = true;
        if (io.MouseWheel != 0.0f) {
            OrbitCamera o = state_.orbit;
            orbitZoom(o, io.MouseWheel);
            applyOrbit(state_, o);
        }
    }
    if (pointer_.light >= 0) {
        if (!ImGui::IsMouseDown(0) || size_t(pointer_.light) >= state_.scene.lights.size()) {
            pointer_.light = -1;
        } else if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) {
            const glm::vec2 at = imagePixelF(m.x, m.y);
            setLight(state_, pointer_.light,
                     pointer_.aiming
                         ? aimedSpot(state_.scene, layout_.renderWidth, layout_.renderHeight, pointer_.light, at)
                         : draggedLight(state_.scene, layout_.renderWidth, layout_.renderHeight, pointer_.light, at));
        }
    }
    if (pointer_.leftDown) {
        if (!ImGui::IsMouseDown(0)) {
            pointer_.leftDown = false;
            if (!pointer_.dragged && !pointer_.splitting) clickAt(pointer_.pressX, pointer_.pressY);
            pointer_.splitting = false;
        } else {
            if (std::fabs(m.x - pointer_.pressX) + std::fabs(m.y - pointer_.pressY) > kClickSlop)
                pointer_.dragged = true;
            if (pointer_.dragged && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
                if (pointer_.splitting) {
                    setSplitPosition(state_, (m.x - layout_.imageX) / layout_.imageW);
                } else {
                    OrbitCamera o = state_.orbit;
                    orbitRotate(o, -io.MouseDelta.x * kRadiansPerPixel, io.MouseDelta.y * kRadiansPerPixel);
                    applyOrbit(state_, o);
                }
            }
        }
    }
    if (pointer_.panning) {
        if (!ImGui::IsMouseDown(1) && !ImGui::IsMouseDown(2)) {
            pointer_.panning = false;
        } else if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) {
            OrbitCamera o = state_.orbit;
            orbitPan(o, io.MouseDelta.x, io.MouseDelta.y, layout_.imageH);
            applyOrbit(state_, o);
        }
    }
}

// A click without a drag: select the object under the cursor (the rasterizer's coverage id there) and put
// the probe on that pixel; the background clears both.
void Viewer::clickAt(float windowX, float windowY) {
    const glm::ivec2 p = imagePixelAt(windowX, windowY);
    if (p.x < 0 || p.y < 0 || p.x >= layout_.renderWidth || p.y >= layout_.renderHeight) return;
    const uint32_t id = coverageAt(p.x, p.y);
    select(state_, id);
    if (id != 0)
        setProbe(state_, p.x, p.y);
    else
        clearProbe(state_);
}

void Viewer::handleKeys() {
    std::vector<KeyPress> keys;
    keys.swap(queued_.keys);
    if (ImGui::GetIO().WantCaptureKeyboard) return;  // a text field has the keyboard
    for (const KeyPress& k : keys) {
        const bool ctrl = (k.mods & GLFW_MOD_CONTROL) != 0, shift = (k.mods & GLFW_MOD_SHIFT) != 0;
        if (ctrl) {
            if (k.key == GLFW_KEY_Z) shift ? redo() : undo();
            if (k.key == GLFW_KEY_Y) redo();
            continue;
        }
        if (k.key >= GLFW_KEY_0 && k.key <= GLFW_KEY_0 + kProgressionSteps)
            applyProgression(state_, k.key - GLFW_KEY_0);
        if (k.key >= GLFW_KEY_KP_0 && k.key <= GLFW_KEY_KP_0 + kProgressionSteps)
            applyProgression(state_, k.key - GLFW_KEY_KP_0);
        switch (k.key) {
            case GLFW_KEY_F: frameAll(state_); break;
            case GLFW_KEY_R: resetCamera(state_); break;
            case GLFW_KEY_F5: reloadShaders(""); break;
            case GLFW_KEY_B:
                setModel(state_,
                         state_.scene.model == ShadingModel::Phong ? ShadingModel::BlinnPhong : ShadingModel::Phong);
                break;
            case GLFW_KEY_P:  // pbr and back to Phong: the pbr-vs-phong lesson flips between them
                setModel(state_, isPhysicallyBased(state_.scene.model) ? ShadingModel::Phong : ShadingModel::Pbr);
                break;
            case GLFW_KEY_V: setMode(state_, ViewMode((int(state_.mode) + 1) % 6)); break;
            case GLFW_KEY_TAB: shape_.showPanel = !shape_.showPanel; break;
            case GLFW_KEY_C: fields_.captions = !fields_.captions; break;
            case GLFW_KEY_T: setRayTree(state_, !state_.probe.rayTree); break;
            case GLFW_KEY_D: setGlobalDenoise(state_, !state_.globalDenoise); break;
            case GLFW_KEY_F11: shape_.overlayPanel = !shape_.overlayPanel; break;
            case GLFW_KEY_ESCAPE:
                clearProbe(state_);
                select(state_, 0);
                break;
            default: break;
        }
    }
}

}  // namespace shadelab::app
