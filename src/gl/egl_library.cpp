#include "gl/egl_library.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace shadelab::gl {
namespace {

template <typename Fn>
void bind(void* lib, const char* name, Fn& fn) {
    fn = reinterpret_cast<Fn>(dlsym(lib, name));
    if (!fn) throw std::runtime_error(std::string("libEGL lacks ") + name);
}

EglLibrary load() {
    void* lib = nullptr;
    for (const char* name : {"libEGL.so.1", "libEGL.so"})
        if ((lib = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
    if (!lib) throw std::runtime_error("libEGL.so.1 not found (Debian package libegl1)");
    // Never closed: drivers register exit handlers and thread-local state that must outlive every context.
    EglLibrary egl;
    bind(lib, "eglGetProcAddress", egl.getProcAddress);
    bind(lib, "eglGetError", egl.getError);
    bind(lib, "eglQueryString", egl.queryString);
    bind(lib, "eglInitialize", egl.initialize);
    bind(lib, "eglTerminate", egl.terminate);
    bind(lib, "eglBindAPI", egl.bindApi);
    bind(lib, "eglChooseConfig", egl.chooseConfig);
    bind(lib, "eglCreateContext", egl.createContext);
    bind(lib, "eglDestroyContext", egl.destroyContext);
    bind(lib, "eglMakeCurrent", egl.makeCurrent);
    return egl;
}

}  // namespace

const EglLibrary& eglLibrary() {
    // Loaded once; a failure is remembered and thrown again, so every context attempt says the same thing.
    static std::once_flag once;
    static EglLibrary library;
    static std::string failure;
    std::call_once(once, [] {
        try {
            library = load();
        } catch (const std::exception& e) {
            failure = e.what();
        }
    });
    if (!failure.empty()) throw std::runtime_error(failure);
    return library;
}

}  // namespace shadelab::gl
