// Atomic file writes: write to a temporary file in the same folder, fsync, then rename over the target.
// A failure (full disk, read-only folder) leaves the target as it was and no temporary behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace shadelab {

// Throws InputError("<path>", "<reason>") on failure.
void writeFileAtomic(const std::string& path, const void* data, size_t size);
inline void writeFileAtomic(const std::string& path, const std::string& text) {
    writeFileAtomic(path, text.data(), text.size());
}

}  // namespace shadelab
