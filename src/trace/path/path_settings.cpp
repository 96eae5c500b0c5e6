// PathSettings validation.
#include "trace/path/path_settings.h"

#include "util/input_error.h"

#include <string>

namespace shadelab::trace {

void validate(const PathSettings& s) {
    if (s.width < 1 || s.height < 1)
        throw SettingError(
            "size", "must be at least 1x1 pixels, got " + std::to_string(s.width) + "x" + std::to_string(s.height));
    if (s.spp < 1 || s.spp > kMaxPathSamples)
        throw SettingError("spp", "the path tracer takes 1 to " + std::to_string(kMaxPathSamples) +
                                      " samples per pixel, got " + std::to_string(s.spp));
    if (s.threads < 0) throw SettingError("threads", "must be >= 0 (0 = every core), got " + std::to_string(s.threads));
    if (s.maxDepth < -1 || s.maxDepth > 64)
        throw SettingError("depth", "must be in [0, 64], got " + std::to_string(s.maxDepth));
    if (s.rouletteDepth < 0)
        throw SettingError("roulette_depth", "must be >= 0, got " + std::to_string(s.rouletteDepth));
    if (s.tileSize < 1) throw SettingError("tile_size", "must be >= 1, got " + std::to_string(s.tileSize));
    if (!(s.timeLimit >= 0.0) || s.timeLimit > kMaxTimeLimit)
        throw SettingError("time_limit",
                           "must be a number of seconds from 0 to 1e7, got " + std::to_string(s.timeLimit));
}

}  // namespace shadelab::trace
