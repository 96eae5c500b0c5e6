// The KHR_debug error callback of debug_output.h: installed synchronous, for errors only, and recording into a
// process-wide list that any thread's context may append to.
#include "gl/debug_output.h"

#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace shadelab::gl {
namespace {

std::mutex gMutex;
std::vector<std::string> gErrors;  // guarded by gMutex
size_t gDropped = 0;               // errors past kMaxRecordedErrors, guarded by gMutex

const char* sourceName(GLenum source) {
    switch (source) {
        case GL_DEBUG_SOURCE_API: return "API";
        case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
        case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
        case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
        case GL_DEBUG_SOURCE_APPLICATION: return "application";
        default: return "other";
    }
}

void APIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum, GLsizei length, const GLchar* message,
                             const void*) {
    if (type != GL_DEBUG_TYPE_ERROR || source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    std::string text = std::string(sourceName(source)) + " error " + std::to_string(id) + ": ";
    text.append(message, length >= 0 ? size_t(length) : std::strlen(message));
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    std::lock_guard<std::mutex> lock(gMutex);
    if (gErrors.size() >= kMaxRecordedErrors) {
        ++gDropped;  // counted, not printed: a loop of one wrong call would flood stderr
        return;
    }
    std::fprintf(stderr, "shadelab: GL debug output: %s\n", text.c_str());
    gErrors.push_back(std::move(text));
}

// GL_KHR_debug in the current context's extension list (glGetStringi: the core profile has no single string).
bool hasKhrDebug(GetProcFn getProc) {
    auto getStringi = reinterpret_cast<PFNGLGETSTRINGIPROC>(getProc("glGetStringi"));
    if (!getStringi) return false;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLubyte* name = getStringi(GL_EXTENSIONS, GLuint(i));
        if (name && std::strcmp(reinterpret_cast<const char*>(name), "GL_KHR_debug") == 0) return true;
    }
    return false;
}

}  // namespace

bool installDebugOutput(GetProcFn getProc) {
    if (!kDebugOutputBuild || !hasKhrDebug(getProc)) return false;
    auto callback = reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKPROC>(getProc("glDebugMessageCallback"));
    auto control = reinterpret_cast<PFNGLDEBUGMESSAGECONTROLPROC>(getProc("glDebugMessageControl"));
    if (!callback || !control) return false;
    // Errors only: performance hints and the like would cost a call each and say nothing a test checks. Not the
    // shader compiler's: a shader that fails to compile is an input error Program::build reports with its file
    // and line (a broken shader in SHADELAB_SHADER_DIR), not a wrong GL call.
    control(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
    control(GL_DONT_CARE, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    control(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
    callback(onDebugMessage, nullptr);
    // Synchronous: the callback runs inside the failing call, on its thread, so the record is in call order.
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glEnable(GL_DEBUG_OUTPUT);
    return glIsEnabled(GL_DEBUG_OUTPUT) == GL_TRUE;
}

bool debugOutputActive() { return kDebugOutputBuild && glIsEnabled(GL_DEBUG_OUTPUT) == GL_TRUE; }

std::vector<std::string> takeDebugErrors() {
    std::lock_guard<std::mutex> lock(gMutex);
    std::vector<std::string> errors;
    errors.swap(gErrors);
    if (gDropped) errors.push_back("and " + std::to_string(gDropped) + " more GL errors");
    gDropped = 0;
    return errors;
}

}  // namespace shadelab::gl
