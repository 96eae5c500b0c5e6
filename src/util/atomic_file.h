// Atomic file writes: the new content is written where no one can see it (an O_TMPFILE, else a short-named
// temporary that SIGINT/SIGTERM/SIGHUP remove), fsynced, renamed over the target, then the folder fsynced.
// A failure (full disk, read-only folder, signal) leaves the target as it was and no temporary behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace shadelab {

// Test seams; the defaults are what every caller wants.
struct AtomicWriteOptions {
    bool allowTmpFile = true;                        // false: always use a named temporary
    std::function<void(size_t written)> afterChunk;  // called after each chunk (1 MiB) reaches the file
};

// Only regular files are replaced. An existing directory, device, FIFO or socket is refused, also behind a
// symlink; a symlink to a regular file is written through (its target is replaced, the link stays), and a
// dangling symlink is refused. Throws InputError("<path>", "<reason>") on failure.
void writeFileAtomic(const std::string& path, const void* data, size_t size, const AtomicWriteOptions& options = {});
inline void writeFileAtomic(const std::string& path, const std::string& text, const AtomicWriteOptions& options = {}) {
    writeFileAtomic(path, text.data(), text.size(), options);
}

// The checks writeFileAtomic makes before writing, for commands that want to fail before a long render:
// the target's type (as above), and that its folder exists and is writable. Throws the same InputError.
void checkWritableTarget(const std::string& path);

}  // namespace shadelab
