// readFile: the one way shadelab reads a file it is given: scene, model, glTF buffer and image, PNG,
// script, shader. It never blocks and never reads without a bound (docs/cli.md, "Limits and hostile input"). Not for
// writing: that is atomic_file.h.
#pragma once

#include <cstdint>
#include <string>

namespace shadelab {

// Size bounds per kind of file, bytes (docs/cli.md "Limits"). glTF files and their side files have theirs
// in scene/gltf/gltf_limits.h.
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t(64) << 20;    // scene .json
inline constexpr uint64_t kMaxScriptFileBytes = uint64_t(16) << 20;   // viewer --script .json
inline constexpr uint64_t kMaxShaderFileBytes = uint64_t(4) << 20;    // one shader source (hot reload)
inline constexpr uint64_t kMaxPngFileBytes = uint64_t(1) << 30;       // a PNG for compare
inline constexpr uint64_t kDefaultMaxFileBytes = uint64_t(64) << 20;  // anything else (tests, tools)

// Throws InputError(path, reason) naming the problem: a NUL in the path; no such file; anything but a
// regular file (FIFO, device, directory, socket), refused before it is opened and again from the open
// descriptor; a size over `maxBytes`, from fstat and again while reading (a file that grows or lies is
// still bounded). The open never blocks (O_NONBLOCK), so a FIFO cannot hang it.
std::string readFile(const std::string& path, uint64_t maxBytes = kDefaultMaxFileBytes);

// Whether `path` names an existing regular file, without opening it (stat only; a FIFO is never opened).
bool isRegularFile(const std::string& path);

}  // namespace shadelab
