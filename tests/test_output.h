// Where tests leave their evidence: build/test-output/<test binary>/, created on demand. A failing test
// writes its images and numbers here and prints the paths.
#pragma once

#include <filesystem>
#include <string>

namespace shadelab::test {

inline std::string outputPath(const std::string& name) {
    std::filesystem::path dir(SHADELAB_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

inline std::string sourcePath(const std::string& relative) {
    return (std::filesystem::path(SHADELAB_SOURCE_DIR) / relative).string();
}

}  // namespace shadelab::test
