// TraceSettings validation and the derived values (grid size, thread count).
#include "trace/trace_settings.h"

#include "scene/sample_grid.h"
#include "util/input_error.h"

#include <string>
#include <thread>

namespace shadelab::trace {

int samplesPerAxis(const TraceSettings& s) { return gridSamplesPerSide(s.spp); }

void validate(const TraceSettings& s) {
    if (s.width < 1 || s.height < 1)
        throw SettingError(
            "size", "must be at least 1x1 pixels, got " + std::to_string(s.width) + "x" + std::to_string(s.height));
    gridSamplesPerSide(s.spp);
    if (s.threads < 0) throw SettingError("threads", "must be >= 0 (0 = every core), got " + std::to_string(s.threads));
    if (s.maxDepth < -1 || s.maxDepth > 64)
        throw SettingError("depth", "must be in [0, 64], got " + std::to_string(s.maxDepth));
    if (!(s.rayTree.minWeight >= 0.0f && s.rayTree.minWeight <= 1.0f))
        throw SettingError("ray_tree.min_weight", "must be in [0, 1], got " + std::to_string(s.rayTree.minWeight));
    if (s.rayTree.maxRays < -1)
        throw SettingError("ray_tree.max_rays", "must be >= 0 secondary rays per sample (-1 = no limit), got " +
                                                    std::to_string(s.rayTree.maxRays));
    if (s.tileSize < 1) throw SettingError("tile_size", "must be >= 1, got " + std::to_string(s.tileSize));
}

int resolveThreads(const TraceSettings& s) {
    if (s.threads > 0) return s.threads;
    const unsigned n = std::thread::hardware_concurrency();
    return n > 0 ? int(n) : 1;
}

}  // namespace shadelab::trace
