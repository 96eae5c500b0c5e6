// Where shader text comes from: the copies embedded at build time, or a folder on disk (viewer hot reload,
// SHADELAB_SHADER_DIR). Resolves `#include "x.glsl"` and keeps a map from GLSL source-string numbers back
// to file names, so compile errors name the file and line.
#pragma once

#include "gl/shader_dialect.h"

#include <string>
#include <vector>

namespace shadelab::gl {

struct EmbeddedShader {
    const char* name;  // file name under shaders/
    const char* text;
};
const std::vector<EmbeddedShader>& embeddedShaders();

// Environment variable naming a folder to read shaders from instead of the embedded copies.
inline constexpr const char* kShaderDirEnv = "SHADELAB_SHADER_DIR";

struct ShaderSource {
    std::string text;                // ready for glShaderSource: #version, prelude, includes expanded
    std::vector<std::string> files;  // files[i] is GLSL source-string number i in #line directives
};

class ShaderLibrary {
public:
    // Empty `dir`: SHADELAB_SHADER_DIR if set, else the embedded copies.
    explicit ShaderLibrary(std::string dir = "", ShaderDialect dialect = ShaderDialect::Glsl330);

    // The same files in another dialect (a renderer picks the one of its context: currentContextDialect()).
    ShaderLibrary withDialect(ShaderDialect dialect) const;
    ShaderDialect dialect() const { return dialect_; }

    // Reads `name` and everything it includes. Throws InputError naming the file on a missing file or
    // include. `defines` lines are added after the dialect's prelude (shaderPrelude), e.g. "#define SHADOWS 1".
    ShaderSource load(const std::string& name, const std::string& defines = "") const;

    // Where files come from, for messages: a folder path, or "embedded".
    std::string origin() const { return dir_.empty() ? "embedded" : dir_; }

private:
    std::string readRaw(const std::string& name) const;
    void expand(const std::string& name, ShaderSource& out, int depth) const;
    std::string dir_;
    ShaderDialect dialect_ = ShaderDialect::Glsl330;
};

}  // namespace shadelab::gl
