// Program: a linked vertex + fragment shader pair from the ShaderLibrary. Compile and link errors become
// one InputError naming the shader file and line (the GL info log mapped back through #line numbers).
#pragma once

#include "gl/objects.h"
#include "gl/shader_sources.h"

#include <glm/fwd.hpp>
#include <string>

namespace shadelab::gl {

class Program {
public:
    Program() = default;
    static Program build(const ShaderLibrary& lib, const std::string& vertexFile, const std::string& fragmentFile,
                         const std::string& defines = "");

    GLuint id() const { return handle_.id(); }
    explicit operator bool() const { return bool(handle_); }
    GLint uniform(const char* name) const { return glGetUniformLocation(handle_.id(), name); }
    void bindBlock(const char* blockName, GLuint binding) const;

    // Typed uniform setters, the glUniform* call of each type, for this program, which must be the one in use
    // (glUseProgram): GL applies a location to whichever program is current, so a location set under another one
    // silently changes that program instead. Debug builds check it (DCHECK); Release builds make the bare call.
    //
    // A name this program lacks is allowed by default: the specialised variants compile uniforms out, the linker
    // drops unused ones, and GL ignores location -1. Uniform::Required says every variant reads it, and a debug
    // check then fails on a missing one (a misspelt name, a shader that lost it) instead of leaving the uniform at
    // its default of zero without a word.
    enum class Uniform { Optional, Required };
    void set(const char* name, GLint v, Uniform need = Uniform::Optional) const;
    void set(const char* name, GLuint v, Uniform need = Uniform::Optional) const;
    void set(const char* name, float v, Uniform need = Uniform::Optional) const;
    void set(const char* name, const glm::vec2& v, Uniform need = Uniform::Optional) const;
    void set(const char* name, const glm::vec3& v, Uniform need = Uniform::Optional) const;
    void set(const char* name, const glm::vec4& v, Uniform need = Uniform::Optional) const;
    void set(const char* name, const glm::mat4& v, Uniform need = Uniform::Optional) const;
    // Arrays of `count` elements from `v` (uniform ivec4/vec4 name[count]).
    void set(const char* name, const glm::ivec4* v, int count, Uniform need = Uniform::Optional) const;
    void set(const char* name, const glm::vec4* v, int count, Uniform need = Uniform::Optional) const;
    // A sampler uniform: the texture unit it reads (glUniform1i; a sampler set with glUniform1ui is a GL error).
    void setSampler(const char* name, GLuint unit, Uniform need = Uniform::Optional) const;

private:
    // The location of `name` for a setter: checks in debug builds that this program is current and, when
    // `need` is Required, that it has the uniform.
    GLint location(const char* name, Uniform need) const;

    ProgramHandle handle_;
};

// Turns a driver's info log into "file:line: message" using the source-string → file map; exposed for tests.
// Returns the first line that reports an error, rewritten; `line` receives its line number (0 if unknown).
std::string firstLogError(const std::string& log, const ShaderSource& src, std::string* file, int* line);

}  // namespace shadelab::gl
