// The viewer's file list (opening a file once meant typing a whole path): the scenes and folders of one
// folder, read once and kept until the folder changes or the user refreshes. Plain data, no ImGui.
#pragma once

#include <string>
#include <vector>

namespace shadelab::app {

struct FileEntry {
    std::string name;  // as shown: a folder ends in '/'
    std::string path;  // to open, or to list next
    bool folder = false;
};

struct FileList {
    std::string folder;              // absolute, normalised
    std::vector<FileEntry> entries;  // "../" first (unless at the root), then folders, then scene files, by name
    std::string error;               // why the folder could not be read; empty when it was
    bool truncated = false;          // more than kMaxEntries
};

inline constexpr size_t kMaxFileListEntries = 500;

// Lists `folder`: sub-folders (hidden ones left out) and .json, .gltf and .glb files, case-insensitively.
FileList listSceneFolder(const std::string& folder);

// Puts `path` first in `recent`, without duplicates, keeping at most `limit`.
void rememberRecent(std::vector<std::string>& recent, const std::string& path, size_t limit = 8);

}  // namespace shadelab::app
