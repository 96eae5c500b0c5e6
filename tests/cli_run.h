// Runs the shadelab binary from tests (the CLI's, and the viewer window's through app_window_run.h): its exit
// code and output, and the small file helpers they share.
#pragma once

#include "test_output.h"

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

namespace shadelab::test {

struct Result {
    int code = -1;
    std::string out;  // stdout and stderr together
};

// Runs a shell command line, its stderr with its stdout.
inline Result shell(const std::string& cmd) {
    Result r;
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    while (size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

// Runs shadelab with `args`; `env` is prepended to the shell command (e.g. "VAR=value ").
inline Result run(const std::string& args, const std::string& env = "") {
    return shell(env + std::string(SHADELAB_BINARY) + " " + args);
}

inline std::string writeText(const std::string& name, const std::string& text) {
    std::string path = outputPath(name);
    std::ofstream(path) << text;
    return path;
}

inline std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline int lineCount(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

}  // namespace shadelab::test
