// loadEnvironment: path resolution as for mesh sources, the bounded .hdr read, then the prefilter.
#include "scene/environment_load.h"

#include "image/hdr.h"
#include "scene/scene_limits.h"

#include <algorithm>
#include <filesystem>

namespace shadelab {

std::shared_ptr<const shading::PrefilteredEnvironment> loadPrefilteredHdr(const std::string& path,
                                                                          const shading::PrefilterSettings& settings) {
    HdrImage hdr = readHdr(path);
    shading::EquirectMap map;
    map.width = hdr.width;
    map.height = hdr.height;
    map.rgb = std::move(hdr.rgb);
    // RGBE reaches 1.7e38; held at kMaxRadiance, a texel still shows white at any exposure, and the prefilter's
    // sums and the renderers' products of it stay finite (scene_limits.h).
    for (float& v : map.rgb) v = std::min(v, kMaxRadiance);
    return std::make_shared<const shading::PrefilteredEnvironment>(shading::prefilterEnvironment(map, settings));
}

void loadEnvironment(Scene& scene, const std::string& baseDir, const shading::PrefilterSettings& settings) {
    if (!scene.environment || scene.environment->hdr.empty()) return;
    const std::string& hdr = scene.environment->hdr;
    const std::filesystem::path source(hdr);
    const std::string path =
        source.is_absolute() || baseDir.empty() ? hdr : (std::filesystem::path(baseDir) / source).string();
    scene.environment->map = loadPrefilteredHdr(path, settings);
}

}  // namespace shadelab
