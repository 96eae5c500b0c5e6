// Backend selection for headless contexts: the order of design.md §3, the override, the error that
// lists what was tried.
#include "gl/headless_context.h"

#include "gl/debug_output.h"
#include "gl/gl_api.h"
#include "gl/shader_dialect.h"
#include "util/input_error.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace shadelab::gl {

void finishContextInfo(ContextInfo& info, void* (*getProc)(const char*)) {
    if (const char* missing = loadFunctions(getProc))
        throw std::runtime_error(std::string("OpenGL entry point ") + missing + " not found");
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    info.renderer = str(GL_RENDERER);
    info.version = str(GL_VERSION);
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (dialectForVersion(info.version) == ShaderDialect::Essl300) {
        if (major < 3) throw std::runtime_error(info.version + " is older than the OpenGL ES 3.0 shadelab needs");
    } else if (major * 10 + minor < 33) {
        throw std::runtime_error("OpenGL " + info.version + " is older than the 3.3 core profile shadelab needs");
    }
    installDebugOutput(getProc);  // Debug and sanitizer builds only; Release leaves the context as it is
}

namespace {

GlBackend resolveForced(GlBackend forced) {
    if (forced == GlBackend::Auto) {
        if (const char* env = std::getenv(kGlBackendEnv); env && *env) {
            const std::optional<GlBackend> named = parseGlBackend(env);
            if (!named)
                throw UsageError(std::string(kGlBackendEnv) + ": unknown GL backend '" + env + "'; expected " +
                                 nameChoices(kGlBackendNames));
            forced = *named;
        }
    }
    return forced;
}

bool gpuDeviceNodePresent() {
    std::error_code ec;
    if (std::filesystem::exists("/dev/nvidia0", ec)) return true;
    for (std::filesystem::directory_iterator it("/dev/dri", ec), end; !ec && it != end; it.increment(ec))
        if (it->path().filename().string().rfind("renderD", 0) == 0) return true;
    return false;
}

}  // namespace

bool softwareContextExpected(GlBackend forced) {
    if (resolveForced(forced) == GlBackend::OSMesa) return true;
    if (const char* soft = std::getenv("LIBGL_ALWAYS_SOFTWARE"); soft && *soft && std::string(soft) != "0") return true;
    return !gpuDeviceNodePresent();
}

std::unique_ptr<HeadlessContext> createHeadlessContext(GlBackend forced, std::vector<std::string>* log) {
    forced = resolveForced(forced);
    struct Attempt {
        GlBackend backend;
        std::unique_ptr<HeadlessContext> (*create)();
    };
    const Attempt order[] = {{GlBackend::EglDevice, createEglDeviceContext},
                             {GlBackend::EglSurfaceless, createEglSurfacelessContext},
                             {GlBackend::OSMesa, createOSMesaContext}};
    std::string tried;
    for (const Attempt& a : order) {
        if (forced != GlBackend::Auto && forced != a.backend) continue;
        try {
            std::unique_ptr<HeadlessContext> ctx = a.create();
            if (log) log->push_back(std::string("gl: ") + toString(a.backend) + ": ok, " + ctx->info().device);
            return ctx;
        } catch (const std::exception& e) {
            if (log) log->push_back(std::string("gl: ") + toString(a.backend) + ": " + e.what());
            if (!tried.empty()) tried += "; ";
            tried += std::string(toString(a.backend)) + " (" + e.what() + ")";
        }
    }
    throw ContextError("no headless OpenGL context could be created; tried " + tried +
                       ". Install Mesa's drivers: apt-get install libegl-mesa0 libgl1-mesa-dri libosmesa6");
}

}  // namespace shadelab::gl
