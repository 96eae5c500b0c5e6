#include "app/file_list.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fs = std::filesystem;

namespace shadelab::app {
namespace {

bool isScene(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".json" || ext == ".gltf" || ext == ".glb";
}

}  // namespace

FileList listSceneFolder(const std::string& folder) {
    FileList list;
    std::error_code ec;
    const fs::path dir = fs::absolute(folder.empty() ? fs::path(".") : fs::path(folder), ec).lexically_normal();
    list.folder = dir.string();
    if (dir.has_parent_path() && dir != dir.root_path())
        list.entries.push_back({"../", dir.parent_path().string(), true});
    std::vector<FileEntry> folders, files;
    fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        list.error = ec.message();
        return list;
    }
    for (const fs::directory_entry& e : it) {
        const std::string name = e.path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code typeError;
        if (e.is_directory(typeError))
            folders.push_back({name + "/", e.path().string(), true});
        else if (isScene(e.path()) && e.is_regular_file(typeError))
            files.push_back({name, e.path().string(), false});
        if (folders.size() + files.size() >= kMaxFileListEntries) {
            list.truncated = true;
            break;
        }
    }
    const auto byName = [](const FileEntry& a, const FileEntry& b) { return a.name < b.name; };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    list.entries.insert(list.entries.end(), folders.begin(), folders.end());
    list.entries.insert(list.entries.end(), files.begin(), files.end());
    return list;
}

void rememberRecent(std::vector<std::string>& recent, const std::string& path, size_t limit) {
    recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
    recent.insert(recent.begin(), path);
    if (recent.size() > limit) recent.resize(limit);
}

}  // namespace shadelab::app
