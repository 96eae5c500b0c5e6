// Shader compilation and linking with file-and-line error messages (Dear ImGui's CheckShader does the same).
#include "gl/program.h"

#include "util/check.h"
#include "util/input_error.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <vector>

namespace shadelab::gl {
namespace {

std::string infoLog(GLuint object, bool isShader) {
    GLint length = 0;
    if (isShader)
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> buf(size_t(length) + 1, '\0');
    if (isShader)
        glGetShaderInfoLog(object, length, nullptr, buf.data());
    else
        glGetProgramInfoLog(object, length, nullptr, buf.data());
    return buf.data();
}

GLuint compile(GLenum stage, const ShaderSource& src, const std::string& name) {
    GLuint shader = glCreateShader(stage);
    const char* text = src.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return shader;
    std::string log = infoLog(shader, true);
    glDeleteShader(shader);
    std::string file = name;
    int line = 0;
    std::string message = firstLogError(log, src, &file, &line);
    throw InputError("shaders/" + file, line > 0 ? "line " + std::to_string(line) : "", message);
}

}  // namespace

std::string firstLogError(const std::string& log, const ShaderSource& src, std::string* file, int* line) {
    // Mesa: "0:12(5): error: ...", NVIDIA: "0(12) : error C1008: ...".
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream in(log);
    std::string l, first;
    while (std::getline(in, l)) {
        std::smatch m;
        if (std::regex_match(l, m, mesa) || std::regex_match(l, m, nvidia)) {
            if (m[3].str().find("error") == std::string::npos) continue;
            size_t index = std::stoul(m[1].str());
            if (index < src.files.size()) *file = src.files[index];
            *line = std::stoi(m[2].str());
            return m[3].str();
        }
        if (first.empty() && !l.empty()) first = l;
    }
    *line = 0;
    return first.empty() ? "compilation failed with no log" : first;
}

Program Program::build(const ShaderLibrary& lib, const std::string& vertexFile, const std::string& fragmentFile,
                       const std::string& defines) {
    ShaderSource vs = lib.load(vertexFile, defines);
    ShaderSource fs = lib.load(fragmentFile, defines);
    GLuint v = compile(GL_VERTEX_SHADER, vs, vertexFile);
    GLuint f = 0;
    try {
        f = compile(GL_FRAGMENT_SHADER, fs, fragmentFile);
    } catch (...) {
        glDeleteShader(v);
        throw;
    }
    Program p;
    p.handle_ = ProgramHandle::create();
    GLuint id = p.handle_.id();
    glAttachShader(id, v);
    glAttachShader(id, f);
    glLinkProgram(id);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = GL_FALSE;
    glGetProgramiv(id, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log = infoLog(id, false);
        throw InputError("shaders/" + vertexFile + " + " + fragmentFile,
                         "link failed: " + log.substr(0, log.find('\n')));
    }
    return p;
}

void Program::bindBlock(const char* blockName, GLuint binding) const {
    GLuint index = glGetUniformBlockIndex(handle_.id(), blockName);
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(handle_.id(), index, binding);
}

GLint Program::location(const char* name, Uniform need) const {
    const GLint loc = uniform(name);
    if (kDcheckEnabled) {
        GLint current = 0;
        glGetIntegerv(GL_CURRENT_PROGRAM, &current);
        if (GLuint(current) != handle_.id()) {
            std::fprintf(stderr, "Program::set(\"%s\"): program %u is not current (program %d is)\n", name,
                         handle_.id(), current);
            std::abort();
        }
        if (need == Uniform::Required && loc < 0) {
            std::fprintf(stderr, "Program::set(\"%s\"): program %u has no active uniform of that name\n", name,
                         handle_.id());
            std::abort();
        }
    }
    return loc;
}

void Program::set(const char* name, GLint v, Uniform need) const { glUniform1i(location(name, need), v); }
void Program::set(const char* name, GLuint v, Uniform need) const { glUniform1ui(location(name, need), v); }
void Program::set(const char* name, float v, Uniform need) const { glUniform1f(location(name, need), v); }
void Program::set(const char* name, const glm::vec2& v, Uniform need) const {
    glUniform2f(location(name, need), v.x, v.y);
}
void Program::set(const char* name, const glm::vec3& v, Uniform need) const {
    glUniform3fv(location(name, need), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec4& v, Uniform need) const {
    glUniform4fv(location(name, need), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat4& v, Uniform need) const {
    glUniformMatrix4fv(location(name, need), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::ivec4* v, int count, Uniform need) const {
    glUniform4iv(location(name, need), count, glm::value_ptr(v[0]));
}
void Program::set(const char* name, const glm::vec4* v, int count, Uniform need) const {
    glUniform4fv(location(name, need), count, glm::value_ptr(v[0]));
}
void Program::setSampler(const char* name, GLuint unit, Uniform need) const {
    glUniform1i(location(name, need), GLint(unit));
}

}  // namespace shadelab::gl
