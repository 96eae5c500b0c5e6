// libEGL, loaded with dlopen when the first headless context is made, as libOSMesa is: nothing of shadelab links
// libEGL, so the binary and the Python module start (and trace) on a machine without it, and a wheel needs no
// particular EGL at build time. The entry points are the EGL 1.4 core functions the contexts call; the
// extension functions come through getProcAddress, as EGL specifies.
#pragma once

#include <EGL/egl.h>

namespace shadelab::gl {

struct EglLibrary {
    PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
    PFNEGLGETERRORPROC getError = nullptr;
    PFNEGLQUERYSTRINGPROC queryString = nullptr;
    PFNEGLINITIALIZEPROC initialize = nullptr;
    PFNEGLTERMINATEPROC terminate = nullptr;
    PFNEGLBINDAPIPROC bindApi = nullptr;
    PFNEGLCHOOSECONFIGPROC chooseConfig = nullptr;
    PFNEGLCREATECONTEXTPROC createContext = nullptr;
    PFNEGLDESTROYCONTEXTPROC destroyContext = nullptr;
    PFNEGLMAKECURRENTPROC makeCurrent = nullptr;
};

// The process's libEGL (libEGL.so.1, then libEGL.so), loaded once and kept for the process's life. Throws
// std::runtime_error naming what is missing when the library or one of its entry points is not there.
const EglLibrary& eglLibrary();

}  // namespace shadelab::gl
