// The two GLSL dialects' preludes and the choice between them.
#include "gl/shader_dialect.h"

#include "gl/gl_api.h"

namespace shadelab::gl {

ShaderDialect dialectForVersion(std::string_view glVersion) {
    return glVersion.rfind("OpenGL ES", 0) == 0 ? ShaderDialect::Essl300 : ShaderDialect::Glsl330;
}

ShaderDialect currentContextDialect() {
#ifdef __EMSCRIPTEN__
    return ShaderDialect::Essl300;
#else
    const GLubyte* version = glGetString(GL_VERSION);
    return version ? dialectForVersion(reinterpret_cast<const char*>(version)) : ShaderDialect::Glsl330;
#endif
}

std::string_view shaderPrelude(ShaderDialect dialect) {
    switch (dialect) {
        case ShaderDialect::Essl300:
            return "#version 300 es\n"
                   "precision highp float;\n"
                   "precision highp int;\n"
                   "precision highp sampler2D;\n"
                   "precision highp sampler2DArray;\n"
                   "precision highp sampler2DShadow;\n"
                   "precision highp sampler2DArrayShadow;\n"
                   "precision highp samplerCube;\n"
                   "precision highp samplerCubeShadow;\n"
                   "precision highp sampler3D;\n"
                   "precision highp isampler2D;\n"
                   "precision highp usampler2D;\n"
                   "#define SL_CLIP_DISTANCE 0\n"
                   "#define SL_FN\n";
        case ShaderDialect::Glsl330: break;
    }
    return "#version 330 core\n#define SL_FN\n";
}

const char* toString(ShaderDialect dialect) {
    return dialect == ShaderDialect::Essl300 ? "GLSL ES 3.00" : "GLSL 3.30 core";
}

}  // namespace shadelab::gl
