#include "app/save_policy.h"

#include "util/input_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace shadelab::app {

std::string saveRefusal(const std::string& path) {
    if (path.empty()) return "no file name given";
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".gltf" || ext == ".glb") return "refusing to save scene JSON over a glTF model; choose a .json name";
    if (ext != ".json") return "scene files end in .json; choose a .json name";
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return "is a folder";
    // The rule of every output (util/input_files.h), said before the overwrite question is even asked.
    if (openInputAt(path)) return "refusing to overwrite an input: the open scene reads this file; choose another name";
    return {};
}

}  // namespace shadelab::app
