// Viewer setup and teardown: the GLFW window (OpenGL 3.3 core, forward compatible, vsync, resizable,
// sized for the panel plus the image), the GL entry points, Dear ImGui with a readable font, the renderers.
#include "app/viewer.h"

#include "gl/shader_sources.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace shadelab::app {
namespace {

constexpr float kFontSize = 17.0f;  // pixels at UI scale 1: readable when projected
std::string g_glfwError = "no error reported";

void onGlfwError(int code, const char* what) {
    g_glfwError = std::string(what) + " (GLFW error " + std::to_string(code) + ")";
}

void* getProc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string windowTitle(const ViewerState& s) {
    std::string name = s.scene.title;
    if (name.empty() && !s.scenePath.empty()) name = std::filesystem::path(s.scenePath).filename().string();
    return name.empty() ? "shadelab" : "shadelab: " + name;
}

}  // namespace

void installInputCallbacks(GLFWwindow* window);  // viewer_input.cpp: drops and key presses

int runViewer(const ViewerOptions& options, ViewerState state, std::optional<Script> script) {
    Viewer viewer(options, std::move(state), std::move(script));
    return viewer.run();
}

std::string shaderSourceDir() {
    if (const char* env = std::getenv("SHADELAB_SHADER_DIR"); env && *env) return env;
#ifdef SHADELAB_SOURCE_DIR
    return std::string(SHADELAB_SOURCE_DIR) + "/shaders";
#else
    return "shaders";
#endif
}

Viewer::Viewer(const ViewerOptions& options, ViewerState state, std::optional<Script> script)
    : options_(options), state_(std::move(state)) {
    if (script) player_.emplace(std::move(*script));
    history_.reset(state_);
    if (!state_.scenePath.empty()) rememberRecent(fields_.recent, state_.scenePath);
    fields_.openPath = state_.scenePath;
    fields_.savePath = defaultSavePath(state_.scenePath);
    try {
        initWindow();
        initImGui();
        // The embedded shaders (or $SHADELAB_SHADER_DIR), exactly as `shadelab render` uses them.
        const gl::ShaderLibrary shaders;
        raster_ = std::make_unique<raster::RasterRenderer>(shaders);
        raster_->setPartialRedraw(true);  // a material edit redraws only the objects it changes
        imageView_ = std::make_unique<ImageView>(shaders);
        panelCache_ = std::make_unique<PanelCache>(PanelCache::modeFromEnvironment());
        imageView_->buildAll();  // a broken shader stops the viewer before its window shows
        arrows_ = std::make_unique<ArrowOverlay>(shaders);
        reference_ = std::make_unique<ReferenceRenderer>();
        global_ = std::make_unique<GlobalRenderer>(reference_->meshCache());
        accumulation_ = std::make_unique<Accumulation>(shaders);
        if (options_.verbose) std::fprintf(stderr, "shadelab: shaders from %s\n", shaders.origin().c_str());
    } catch (...) {
        shutdown();
        throw;
    }
}

Viewer::~Viewer() { shutdown(); }

// GL objects go while their context is current; then ImGui, the window and GLFW.
void Viewer::shutdown() {
    if (window_.handle) glfwMakeContextCurrent(window_.handle);
    global_.reset();     // joins the path tracer's threads (it borrows the reference's BVH cache)
    reference_.reset();  // joins the tracer threads, then deletes its textures
    arrows_.reset();
    imageView_.reset();
    raster_.reset();
    if (window_.imguiReady) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    window_.imguiReady = false;
    if (window_.handle) glfwDestroyWindow(window_.handle);
    window_.handle = nullptr;
    glfwTerminate();
}

void Viewer::initWindow() {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) throw std::runtime_error("cannot open a window: " + g_glfwError);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0);  // no MSAA anywhere near a capture (design.md §4)
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);

    float contentScale = 1.0f, unused = 1.0f;
    int screenW = 1920, screenH = 1080;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        glfwGetMonitorContentScale(monitor, &contentScale, &unused);
        if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) screenW = mode->width, screenH = mode->height;
    }
    shape_.uiScale = options_.uiScale > 0.0f ? options_.uiScale
                     : options_.projector    ? 2.0f
                                             : std::clamp(contentScale, 1.0f, 3.0f);
    shape_.overlayPanel = options_.projector;
    const int panel = shape_.overlayPanel ? 0 : int(kViewerPanelWidth * shape_.uiScale);
    // Default: a 16:9 image area of up to 1280x720 next to the panel, as `shadelab render` frames it.
    // In projector mode: a 16:9 window as wide as the screen allows, the panel over it.
    const int imageW =
        shape_.overlayPanel ? int(0.95f * float(screenW)) : std::min(1280, int(0.95f * float(screenW)) - panel);
    int w = panel + imageW,
        h = shape_.overlayPanel ? imageW * 9 / 16 : std::max(imageW * 9 / 16, int(720 * shape_.uiScale));
    if (options_.width > 0) {
        w = options_.width + panel;
        h = std::max(options_.height, int(600 * shape_.uiScale));
    }
    // Never larger than the screen: a fixed --size then shows scaled down, but renders at full size.
    w = std::min(w, screenW);
    h = std::min(h, screenH);
    window_.handle = glfwCreateWindow(w, h, windowTitle(state_).c_str(), nullptr, nullptr);
    if (!window_.handle) throw std::runtime_error("cannot create an OpenGL 3.3 core window: " + g_glfwError);
    glfwMakeContextCurrent(window_.handle);
    glfwSwapInterval(1);
    if (const char* missing = gl::loadFunctions(getProc))
        throw std::runtime_error(std::string("the window's OpenGL lacks ") + missing);
    glfwSetWindowUserPointer(window_.handle, this);
    installInputCallbacks(window_.handle);
    if (options_.verbose)
        std::fprintf(stderr, "shadelab: GL_RENDERER %s\nshadelab: GL_VERSION %s\n",
                     reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                     reinterpret_cast<const char*>(glGetString(GL_VERSION)));
}

void Viewer::initImGui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the same layout every start, and nothing written next to the scene
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 4.0f;
    style.FrameRounding = 3.0f;
    style.GrabRounding = 3.0f;
    style.WindowBorderSize = 0.0f;
    style.ScaleAllSizes(shape_.uiScale);
    // Glyphs rasterised at framebuffer resolution, shown at window units (sharp on HiDPI).
    int fbW = 0, fbH = 0, winW = 0, winH = 0;
    glfwGetFramebufferSize(window_.handle, &fbW, &fbH);
    glfwGetWindowSize(window_.handle, &winW, &winH);
    const float fbScale = winW > 0 && fbW > 0 ? float(fbW) / float(winW) : 1.0f;
    const float pixels = std::round(kFontSize * shape_.uiScale * fbScale);
    const char* sans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    const char* mono = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
    // Latin-1 and the letters the probe's algebra writes: Greek (Δ, δ), superscript T, arrows, ± and √.
    static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x1D40, 0x1D40,
                                      0x2190, 0x21FF, 0x2200, 0x22FF, 0};
    if (std::filesystem::exists(sans))
        io.Fonts->AddFontFromFileTTF(sans, pixels, nullptr, kRanges);
    else {
        ImFontConfig config;
        config.SizePixels = std::round(13.0f * shape_.uiScale * fbScale);
        io.Fonts->AddFontDefault(&config);
    }
    // The probe's tables: monospaced and a little smaller, so the window covers less of the image.
    if (std::filesystem::exists(mono)) io.Fonts->AddFontFromFileTTF(mono, std::round(0.88f * pixels), nullptr, kRanges);
    // The captions on the image: half as large again, to read from the back of a classroom.
    if (std::filesystem::exists(sans))
        window_.captionFont = io.Fonts->AddFontFromFileTTF(sans, std::round(1.5f * pixels));
    io.FontGlobalScale = 1.0f / fbScale;
    ImGui_ImplGlfw_InitForOpenGL(window_.handle, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    window_.imguiReady = true;
}

}  // namespace shadelab::app
