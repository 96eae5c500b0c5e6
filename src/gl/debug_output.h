// GL debug output (KHR_debug) in Debug and sanitizer builds: the driver calls back on every GL error (message
// type GL_DEBUG_TYPE_ERROR; not the shader compiler's, which Program::build reports) during the call that caused it,
// and the message is recorded here and printed to stderr, so that a test can fail on a GL error where it happened
// instead of at a later glGetError, or never (most calls are not checked; gl::checkError runs once per pass). Release
// builds (NDEBUG) install nothing: their GL calls and output are as without this file.
#pragma once

#include "gl/gl_api.h"

#include <string>
#include <vector>

namespace shadelab::gl {

// Whether this build installs the callback on the contexts it creates: builds without NDEBUG.
#ifdef NDEBUG
inline constexpr bool kDebugOutputBuild = false;
#else
inline constexpr bool kDebugOutputBuild = true;
#endif

// Installs the error callback on the current context, when kDebugOutputBuild and the context offers
// GL_KHR_debug (Mesa's llvmpipe does, through EGL and OSMesa). Returns whether it did. finishContextInfo calls
// it for every headless context.
bool installDebugOutput(GetProcFn getProc);

// Whether the current context has debug output on (GL_DEBUG_OUTPUT), i.e. whether GL errors get recorded.
bool debugOutputActive();

// The GL errors recorded since the last call on any context, oldest first, and forgets them. Each reads
// "<source> error <id>: <driver's message>". At most kMaxRecordedErrors are kept (and printed, the rest only counted);
// a last entry then says how many more there were.
std::vector<std::string> takeDebugErrors();
inline constexpr size_t kMaxRecordedErrors = 64;

}  // namespace shadelab::gl
