// EGL headless contexts: the device platform (EGL_EXT_platform_device) and Mesa's surfaceless
// platform, OpenGL 3.3 core, or OpenGL ES 3 for checking the ES dialect. Contexts are made current with no
// surface (EGL_KHR_surfaceless_context).
#include "gl/egl_library.h"
#include "gl/headless_context.h"

#include <EGL/eglext.h>

#include <cstring>
#include <string>

namespace shadelab::gl {
namespace {

std::string eglErrorName(EGLint e) {
    switch (e) {
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error " + std::to_string(e);
    }
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

template <typename Fn>
Fn eglProc(const char* name) {
    return reinterpret_cast<Fn>(eglLibrary().getProcAddress(name));
}

class EglContext : public HeadlessContext {
public:
    EglContext(EGLDisplay display, GlBackend backend, const std::string& device) : display_(display) {
        info_.backend = backend;
        info_.device = device;
    }

    // Initialises the display, creates a 3.3 core context (`es`: an OpenGL ES 3.0 or later one) and makes it
    // current. Throws on failure; the destructor then releases whatever was made.
    void init(bool es = false) {
        EGLint major = 0, minor = 0;
        if (!egl_.initialize(display_, &major, &minor))
            throw std::runtime_error("eglInitialize failed: " + eglErrorName(egl_.getError()));
        initialized_ = true;
        const char* api = es ? "OpenGL ES 3" : "OpenGL 3.3 core";
        if (!egl_.bindApi(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
            throw std::runtime_error(std::string("eglBindAPI for ") + api + " failed");

        EGLConfig config = nullptr;
        EGLint count = 0;
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                        0, EGL_NONE};
        if (!egl_.chooseConfig(display_, configAttribs, &config, 1, &count) || count == 0) {
            if (!hasExtension(egl_.queryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
                throw std::runtime_error(std::string("no EGL config supports ") + api);
            config = EGL_NO_CONFIG_KHR;
        }
        const EGLint coreAttribs[] = {
            EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        const EGLint esAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
        context_ = egl_.createContext(display_, config, EGL_NO_CONTEXT, es ? esAttribs : coreAttribs);
        if (context_ == EGL_NO_CONTEXT)
            throw std::runtime_error(std::string("eglCreateContext (") + api +
                                     ") failed: " + eglErrorName(egl_.getError()));
        if (!egl_.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("eglMakeCurrent without a surface failed: " + eglErrorName(egl_.getError()));
        finishContextInfo(info_,
                          [](const char* name) { return reinterpret_cast<void*>(eglLibrary().getProcAddress(name)); });
    }

    void makeCurrent() override {
        if (!egl_.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("eglMakeCurrent failed: " + eglErrorName(egl_.getError()));
    }
    void release() override {
        if (!egl_.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT))
            throw std::runtime_error("eglMakeCurrent(EGL_NO_CONTEXT) failed: " + eglErrorName(egl_.getError()));
    }

    ~EglContext() override {
        if (context_ != EGL_NO_CONTEXT) {
            egl_.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            egl_.destroyContext(display_, context_);
        }
        if (initialized_) egl_.terminate(display_);
    }

private:
    const EglLibrary& egl_ = eglLibrary();  // throws, before anything is made, where libEGL is missing
    EGLDisplay display_;
    EGLContext context_ = EGL_NO_CONTEXT;
    bool initialized_ = false;
};

PFNEGLGETPLATFORMDISPLAYEXTPROC platformDisplayFn(const char* needed) {
    const char* client = eglLibrary().queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(client, needed)) throw std::runtime_error(std::string(needed) + " not supported");
    auto fn = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (!fn) throw std::runtime_error("eglGetPlatformDisplayEXT missing");
    return fn;
}

}  // namespace

std::unique_ptr<HeadlessContext> createEglDeviceContext() {
    auto getPlatformDisplay = platformDisplayFn("EGL_EXT_platform_device");
    auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    if (!queryDevices || !queryDeviceString) throw std::runtime_error("EGL_EXT_device_enumeration missing");

    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!queryDevices(16, devices, &count) || count == 0) throw std::runtime_error("no EGL devices");

    // Hardware devices first, then Mesa's software device (design.md §3).
    std::string failures;
    for (int pass = 0; pass < 2; ++pass) {
        for (EGLint i = 0; i < count; ++i) {
            const char* ext = queryDeviceString(devices[i], EGL_EXTENSIONS);
            bool software = hasExtension(ext, "EGL_MESA_device_software");
            if (software != (pass == 1)) continue;
            std::string name = "EGL device " + std::to_string(i) + (software ? " (software)" : " (hardware)");
            const char* drm = hasExtension(ext, "EGL_EXT_device_drm")
                                  ? queryDeviceString(devices[i], EGL_DRM_DEVICE_FILE_EXT)
                                  : nullptr;
            if (drm) name += std::string(" ") + drm;
            EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
            if (display == EGL_NO_DISPLAY) {
                failures += name + ": no display; ";
                continue;
            }
            try {
                auto ctx = std::make_unique<EglContext>(display, GlBackend::EglDevice, name);
                ctx->init();
                return ctx;
            } catch (const std::exception& e) {
                failures += name + ": " + e.what() + "; ";
            }
        }
    }
    throw std::runtime_error(failures.empty() ? "no usable EGL device" : failures.substr(0, failures.size() - 2));
}

std::unique_ptr<HeadlessContext> createEglEsContext() {
    auto getPlatformDisplay = platformDisplayFn("EGL_MESA_platform_surfaceless");
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) throw std::runtime_error("no surfaceless display");
    auto ctx = std::make_unique<EglContext>(display, GlBackend::EglSurfaceless, "EGL surfaceless display, OpenGL ES");
    ctx->init(true);
    return ctx;
}

std::unique_ptr<HeadlessContext> createEglSurfacelessContext() {
    auto getPlatformDisplay = platformDisplayFn("EGL_MESA_platform_surfaceless");
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) throw std::runtime_error("no surfaceless display");
    auto ctx = std::make_unique<EglContext>(display, GlBackend::EglSurfaceless, "EGL surfaceless display");
    ctx->init();
    return ctx;
}

}  // namespace shadelab::gl
