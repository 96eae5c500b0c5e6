// OpenGL 3.3 core entry points as function pointers, loaded from whichever context is current (EGL,
// OSMesa or GLFW). Include this instead of any GL header. Only gl/, raster/ and app/ may include it.
#pragma once

#include <GL/glcorearb.h>

namespace shadelab::gl {

// Loads every entry point with `getProc`. Returns the name of the first missing one, or nullptr.
using GetProcFn = void* (*)(const char* name);
const char* loadFunctions(GetProcFn getProc);

// Throws std::runtime_error naming `what` and the GL error, if one is pending. Cheap enough for
// once-per-pass checks; individual calls are not checked.
void checkError(const char* what);

}  // namespace shadelab::gl

#define GL_FN(type, name) extern "C" type shadelab_##name;
#include "gl/gl_functions.inc"
#undef GL_FN

// Call sites read like plain GL; the macros route to the loaded pointers, so no symbol in this
// program clashes with libGL/libOpenGL's own exports.
#define glGetString shadelab_glGetString
#define glGetIntegerv shadelab_glGetIntegerv
#define glGetError shadelab_glGetError
#define glViewport shadelab_glViewport
#define glScissor shadelab_glScissor
#define glClear shadelab_glClear
#define glClearColor shadelab_glClearColor
#define glClearBufferfv shadelab_glClearBufferfv
#define glClearBufferuiv shadelab_glClearBufferuiv
#define glEnable shadelab_glEnable
#define glDisable shadelab_glDisable
#define glIsEnabled shadelab_glIsEnabled
#define glDepthFunc shadelab_glDepthFunc
#define glDepthMask shadelab_glDepthMask
#define glCullFace shadelab_glCullFace
#define glFrontFace shadelab_glFrontFace
#define glColorMask shadelab_glColorMask
#define glBlendFunc shadelab_glBlendFunc
#define glBlendColor shadelab_glBlendColor
#define glPixelStorei shadelab_glPixelStorei
#define glReadPixels shadelab_glReadPixels
#define glReadBuffer shadelab_glReadBuffer
#define glDrawBuffers shadelab_glDrawBuffers
#define glFinish shadelab_glFinish
#define glFlush shadelab_glFlush
#define glGenFramebuffers shadelab_glGenFramebuffers
#define glDeleteFramebuffers shadelab_glDeleteFramebuffers
#define glBindFramebuffer shadelab_glBindFramebuffer
#define glFramebufferTexture2D shadelab_glFramebufferTexture2D
#define glFramebufferRenderbuffer shadelab_glFramebufferRenderbuffer
#define glCheckFramebufferStatus shadelab_glCheckFramebufferStatus
#define glBlitFramebuffer shadelab_glBlitFramebuffer
#define glGenRenderbuffers shadelab_glGenRenderbuffers
#define glDeleteRenderbuffers shadelab_glDeleteRenderbuffers
#define glBindRenderbuffer shadelab_glBindRenderbuffer
#define glRenderbufferStorage shadelab_glRenderbufferStorage
#define glGenTextures shadelab_glGenTextures
#define glDeleteTextures shadelab_glDeleteTextures
#define glBindTexture shadelab_glBindTexture
#define glTexImage2D shadelab_glTexImage2D
#define glTexSubImage2D shadelab_glTexSubImage2D
#define glTexParameteri shadelab_glTexParameteri
#define glActiveTexture shadelab_glActiveTexture
#define glGenBuffers shadelab_glGenBuffers
#define glDeleteBuffers shadelab_glDeleteBuffers
#define glBindBuffer shadelab_glBindBuffer
#define glBufferData shadelab_glBufferData
#define glBufferSubData shadelab_glBufferSubData
#define glBindBufferBase shadelab_glBindBufferBase
#define glGenVertexArrays shadelab_glGenVertexArrays
#define glDeleteVertexArrays shadelab_glDeleteVertexArrays
#define glBindVertexArray shadelab_glBindVertexArray
#define glEnableVertexAttribArray shadelab_glEnableVertexAttribArray
#define glVertexAttribPointer shadelab_glVertexAttribPointer
#define glDisableVertexAttribArray shadelab_glDisableVertexAttribArray
#define glVertexAttrib4f shadelab_glVertexAttrib4f
#define glDrawArrays shadelab_glDrawArrays
#define glDrawElements shadelab_glDrawElements
#define glCreateShader shadelab_glCreateShader
#define glShaderSource shadelab_glShaderSource
#define glCompileShader shadelab_glCompileShader
#define glGetShaderiv shadelab_glGetShaderiv
#define glGetShaderInfoLog shadelab_glGetShaderInfoLog
#define glDeleteShader shadelab_glDeleteShader
#define glCreateProgram shadelab_glCreateProgram
#define glAttachShader shadelab_glAttachShader
#define glLinkProgram shadelab_glLinkProgram
#define glGetProgramiv shadelab_glGetProgramiv
#define glGetProgramInfoLog shadelab_glGetProgramInfoLog
#define glDeleteProgram shadelab_glDeleteProgram
#define glUseProgram shadelab_glUseProgram
#define glBindAttribLocation shadelab_glBindAttribLocation
#define glGetUniformLocation shadelab_glGetUniformLocation
#define glGetUniformiv shadelab_glGetUniformiv
#define glGetUniformuiv shadelab_glGetUniformuiv
#define glGetUniformBlockIndex shadelab_glGetUniformBlockIndex
#define glUniformBlockBinding shadelab_glUniformBlockBinding
#define glUniform1i shadelab_glUniform1i
#define glUniform1ui shadelab_glUniform1ui
#define glUniform1f shadelab_glUniform1f
#define glUniform2f shadelab_glUniform2f
#define glUniform3f shadelab_glUniform3f
#define glUniform3fv shadelab_glUniform3fv
#define glUniform4iv shadelab_glUniform4iv
#define glUniform4fv shadelab_glUniform4fv
#define glUniformMatrix4fv shadelab_glUniformMatrix4fv
#define glTexImage3D shadelab_glTexImage3D
#define glFramebufferTextureLayer shadelab_glFramebufferTextureLayer
