// A current OpenGL 3.3+ core context with no window and no X server (design.md §3), and for tests an
// OpenGL ES 3 one. Tries the EGL device
// platform (hardware first, then Mesa's software device), EGL surfaceless, then OSMesa.
// Rendering goes into the renderer's own framebuffer objects; these contexts have no default surface.
#pragma once

#include "util/name_table.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadelab::gl {

enum class GlBackend { Auto, EglDevice, EglSurfaceless, OSMesa };

// The words of --gl-backend and of kGlBackendEnv.
inline constexpr EnumName<GlBackend> kGlBackendNames[] = {
    {GlBackend::Auto, "auto"},
    {GlBackend::EglDevice, "egl-device"},
    {GlBackend::EglSurfaceless, "egl-surfaceless"},
    {GlBackend::OSMesa, "osmesa"},
};

inline const char* toString(GlBackend b) { return nameOf(kGlBackendNames, b); }
inline std::optional<GlBackend> parseGlBackend(std::string_view name) { return lookupName(kGlBackendNames, name); }

// The environment variable that forces a backend when no flag does.
inline constexpr const char* kGlBackendEnv = "SHADELAB_GL_BACKEND";

struct ContextInfo {
    GlBackend backend = GlBackend::Auto;
    std::string device;    // what the backend picked, e.g. "EGL device 0 (software)"
    std::string renderer;  // GL_RENDERER
    std::string version;   // GL_VERSION
};

// No backend worked. The message lists every backend tried and why it failed.
class ContextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    const ContextInfo& info() const { return info_; }

    // A new context is current on the thread that created it. Threads that take turns with one context (the
    // Python package's Renderer, whose renders may come from any Python thread) release it after use and make
    // it current before: a context is current on at most one thread at a time. Both throw std::runtime_error.
    virtual void makeCurrent() = 0;
    virtual void release() = 0;

protected:
    ContextInfo info_;
};

// Creates and makes current. `forced` = Auto reads kGlBackendEnv, then tries all in order.
// `log`, when set, receives one line per attempt.
std::unique_ptr<HeadlessContext> createHeadlessContext(GlBackend forced = GlBackend::Auto,
                                                       std::vector<std::string>* log = nullptr);

// Whether createHeadlessContext(forced) will give Mesa's software rasterizer, judged before creating it and
// without loading a driver: OSMesa forced, LIBGL_ALWAYS_SOFTWARE set, or no GPU device node (/dev/dri/renderD*,
// /dev/nvidia0). A guess for choosing set-up work that pays only on the CPU, never for correctness.
bool softwareContextExpected(GlBackend forced = GlBackend::Auto);

// Backend implementations (egl_context.cpp, osmesa_context.cpp). Each throws std::runtime_error with
// a short reason on failure and leaves nothing current.
std::unique_ptr<HeadlessContext> createEglDeviceContext();
std::unique_ptr<HeadlessContext> createEglSurfacelessContext();
std::unique_ptr<HeadlessContext> createOSMesaContext();

// An OpenGL ES 3.0 or later context on Mesa's EGL surfaceless platform: what a web build's WebGL2 gives, on
// this machine, so the GLSL ES dialect (gl/shader_dialect.h) is tested natively. Not a --gl-backend: every
// native render uses OpenGL 3.3 core.
std::unique_ptr<HeadlessContext> createEglEsContext();

// Loads GL entry points and fills renderer/version after a backend made its context current.
void finishContextInfo(ContextInfo& info, void* (*getProc)(const char*));

}  // namespace shadelab::gl
