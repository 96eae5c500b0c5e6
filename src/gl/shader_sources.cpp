// ShaderLibrary: embedded or on-disk shader text with #include expansion and #line bookkeeping.
#include "gl/shader_sources.h"

#include "util/input_error.h"
#include "util/read_file.h"

#include <cstdlib>
#include <sstream>

namespace shadelab::gl {

ShaderLibrary::ShaderLibrary(std::string dir, ShaderDialect dialect) : dir_(std::move(dir)), dialect_(dialect) {
    if (dir_.empty())
        if (const char* env = std::getenv(kShaderDirEnv)) dir_ = env;
}

ShaderLibrary ShaderLibrary::withDialect(ShaderDialect dialect) const {
    ShaderLibrary copy = *this;
    copy.dialect_ = dialect;
    return copy;
}

std::string ShaderLibrary::readRaw(const std::string& name) const {
    if (!dir_.empty()) return readFile(dir_ + "/" + name, kMaxShaderFileBytes);
    for (const EmbeddedShader& s : embeddedShaders())
        if (name == s.name) return s.text;
    throw InputError("shaders/" + name, "no such shader");
}

void ShaderLibrary::expand(const std::string& name, ShaderSource& out, int depth) const {
    if (depth > 8) throw InputError("shaders/" + name, "#include nested too deeply");
    const int fileIndex = int(out.files.size());
    out.files.push_back(name);
    std::istringstream in(readRaw(name));
    std::string line;
    int lineNo = 0;
    out.text += "#line 1 " + std::to_string(fileIndex) + "\n";
    while (std::getline(in, line)) {
        ++lineNo;
        size_t p = line.find_first_not_of(" \t");
        if (p != std::string::npos && line.compare(p, 8, "#include") == 0) {
            size_t a = line.find('"', p), b = a == std::string::npos ? a : line.find('"', a + 1);
            if (b == std::string::npos)
                throw InputError("shaders/" + name, "line " + std::to_string(lineNo), "malformed #include");
            expand(line.substr(a + 1, b - a - 1), out, depth + 1);
            out.text += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(fileIndex) + "\n";
            continue;
        }
        out.text += line;
        out.text += '\n';
    }
}

ShaderSource ShaderLibrary::load(const std::string& name, const std::string& defines) const {
    ShaderSource out;
    // The prelude defines SL_FN, which marks functions shared with C++ (shaders/lighting.glsl), where it
    // means `inline`.
    out.text = std::string(shaderPrelude(dialect_)) + defines;
    if (!defines.empty() && defines.back() != '\n') out.text += '\n';
    expand(name, out, 0);
    return out;
}

}  // namespace shadelab::gl
