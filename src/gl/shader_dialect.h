// The GLSL dialect shader programs are compiled in: desktop GLSL 3.30 core, or GLSL ES 3.00 (OpenGL ES 3.0,
// WebGL2). The shaders/ text is the same for both; only the prelude ShaderLibrary puts before it differs.
// Not a translator: the shared text keeps to what both dialects accept.
#pragma once

#include <string>
#include <string_view>

namespace shadelab::gl {

enum class ShaderDialect {
    Glsl330,  // "#version 330 core": every native context (design.md §3)
    Essl300,  // "#version 300 es": OpenGL ES 3.x and WebGL2
};

// The dialect of a context whose GL_VERSION string is `glVersion`: ES contexts' versions start with
// "OpenGL ES" (OpenGL ES 3.0 §6.1.5), desktop ones with the version number.
ShaderDialect dialectForVersion(std::string_view glVersion);

// The dialect of the current context (needs loaded entry points and a current context); GLSL ES 3.00 in
// a web build, which has no other.
ShaderDialect currentContextDialect();

// What ShaderLibrary::load puts before the defines and the file: #version, and in GLSL ES the precision of
// every type the shaders declare (ES has no default float precision in fragment shaders, nor for the
// array, shadow, cube-shadow and integer samplers), all highp so that ES computes what desktop GL does.
// Both define SL_FN (functions shared with C++). The ES prelude also defines SL_CLIP_DISTANCE 0: ES 3.0 has
// no gl_ClipDistance (WebGL2 only with an extension), so mirror passes discard the fragments behind the
// mirror plane instead; shaders/frame.glsl defaults it to 1. The desktop prelude is the one shadelab has
// always used, so native programs are the same text as before the ES dialect existed.
std::string_view shaderPrelude(ShaderDialect dialect);

const char* toString(ShaderDialect dialect);

}  // namespace shadelab::gl
