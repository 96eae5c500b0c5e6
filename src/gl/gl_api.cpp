// Loads the entry points listed in gl_functions.inc through the current context's GetProcAddress.
#include "gl/gl_api.h"

#include <stdexcept>
#include <string>

#define GL_FN(type, name)           \
    extern "C" {                    \
    type shadelab_##name = nullptr; \
    }
#include "gl/gl_functions.inc"
#undef GL_FN

namespace shadelab::gl {

const char* loadFunctions(GetProcFn getProc) {
#define GL_FN(type, name)                                     \
    shadelab_##name = reinterpret_cast<type>(getProc(#name)); \
    if (!shadelab_##name) return #name;
#include "gl/gl_functions.inc"
#undef GL_FN
    return nullptr;
}

static const char* errorName(GLenum e) {
    switch (e) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "unknown GL error";
    }
}

void checkError(const char* what) {
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) throw std::runtime_error(std::string("OpenGL error in ") + what + ": " + errorName(e));
}

}  // namespace shadelab::gl
