// loadEnvironment: path resolution as for mesh sources, the bounded .hdr read, the memory limit from the file's
// size and header, then the prefilter.
#include "scene/environment_load.h"

#include "image/hdr.h"
#include "scene/scene_limits.h"
#include "util/input_error.h"
#include "util/read_file.h"

#include <algorithm>
#include <filesystem>

namespace shadelab {
namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;
// The process around the load (the program and its libraries; measured about 7 MiB for the binary).
constexpr uint64_t kProcessBytes = 8 * kMiB;

// Refuses a load whose estimate exceeds the limit: "<file>: a <what> needs about N MiB to read and prefilter,
// over the limit of M MiB (<name>)".
void requireWithin(const MemoryLimit& limit, uint64_t need, const std::string& path, const std::string& what) {
    if (!limit.bytes || need <= limit.bytes) return;
    throw InputError(path, what + " needs about " + std::to_string((need + kMiB - 1) / kMiB) +
                               " MiB to read and prefilter, over the limit of " + std::to_string(limit.bytes / kMiB) +
                               " MiB" + (limit.name.empty() ? "" : " (" + limit.name + ")"));
}

}  // namespace

uint64_t environmentLoadBytes(int width, int height, uint64_t fileBytes, const shading::PrefilterSettings& settings) {
    const uint64_t pixels = uint64_t(width > 0 ? width : 0) * uint64_t(height > 0 ? height : 0);
    const uint64_t size = uint64_t(settings.size > 0 ? settings.size : 0);
    // prefilterEnvironment: the source cube (6 faces of size² RGB floats) and its box-filtered mips (a third
    // more), and the atlas: 6 faces of (size + 2) columns by at most 2·(size + 2) rows of every level.
    const uint64_t cube = 6 * size * size * 12 * 4 / 3;
    const uint64_t atlas = 6 * (size + 2) * 2 * (size + 2) * 12;
    return kProcessBytes + fileBytes + pixels * 12 + cube + atlas;
}

std::shared_ptr<const shading::PrefilteredEnvironment> loadPrefilteredHdr(const std::string& path,
                                                                          const shading::PrefilterSettings& settings,
                                                                          const MemoryLimit& limit) {
    // The file's size (stat only: readFile refuses what is not a regular file) is held to the limit before it
    // is read, and its pixels, from the header, before they are decoded.
    std::error_code ec;
    const uint64_t fileBytes = isRegularFile(path) ? uint64_t(std::filesystem::file_size(path, ec)) : 0;
    if (!ec) requireWithin(limit, environmentLoadBytes(0, 0, fileBytes, settings), path, "this environment map");
    shading::EquirectMap map;
    {
        const std::string bytes = readFile(path, kMaxHdrFileBytes);  // freed before the prefilter
        const HdrHeader header = parseHdrHeader(bytes, path);
        requireWithin(limit, environmentLoadBytes(header.width, header.height, bytes.size(), settings), path,
                      "a " + std::to_string(header.width) + "x" + std::to_string(header.height) + " environment map");
        HdrImage hdr = parseHdr(bytes, path);
        map.width = hdr.width;
        map.height = hdr.height;
        map.rgb = std::move(hdr.rgb);
    }
    // RGBE reaches 1.7e38; held at kMaxRadiance, a texel still shows white at any exposure, and the prefilter's
    // sums and the renderers' products of it stay finite (scene_limits.h).
    for (float& v : map.rgb) v = std::min(v, kMaxRadiance);
    return std::make_shared<const shading::PrefilteredEnvironment>(shading::prefilterEnvironment(map, settings));
}

void loadEnvironment(Scene& scene, const std::string& baseDir, const shading::PrefilterSettings& settings,
                     const MemoryLimit& limit) {
    if (!scene.environment || scene.environment->hdr.empty()) return;
    const std::string& hdr = scene.environment->hdr;
    const std::filesystem::path source(hdr);
    const std::string path =
        source.is_absolute() || baseDir.empty() ? hdr : (std::filesystem::path(baseDir) / source).string();
    scene.environment->map = loadPrefilteredHdr(path, settings, limit);
}

}  // namespace shadelab
