// Program: a linked vertex + fragment shader pair from the ShaderLibrary. Compile and link errors become
// one InputError naming the shader file and line (the GL info log mapped back through #line numbers).
#pragma once

#include "gl/objects.h"
#include "gl/shader_sources.h"

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

private:
    ProgramHandle handle_;
};

// Turns a driver's info log into "file:line: message" using the source-string → file map; exposed for tests.
// Returns the first line that reports an error, rewritten; `line` receives its line number (0 if unknown).
std::string firstLogError(const std::string& log, const ShaderSource& src, std::string* file, int* line);

}  // namespace shadelab::gl
