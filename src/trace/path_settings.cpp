// PathSettings validation.
#include "trace/path_settings.h"

#include <stdexcept>
#include <string>

namespace shadelab::trace {

void validate(const PathSettings& s) {
    if (s.width < 1 || s.height < 1)
        throw std::invalid_argument("image size must be at least 1x1, got " + std::to_string(s.width) + "x" +
                                    std::to_string(s.height));
    if (s.spp < 1 || s.spp > 1 << 20)
        throw std::invalid_argument("--spp must be in [1, 1048576], got " + std::to_string(s.spp));
    if (s.threads < 0)
        throw std::invalid_argument("--threads must be >= 0 (0 = all cores), got " + std::to_string(s.threads));
    if (s.maxDepth < -1 || s.maxDepth > 64)
        throw std::invalid_argument("--depth must be in [0, 64], got " + std::to_string(s.maxDepth));
    if (s.rouletteDepth < 0)
        throw std::invalid_argument("roulette depth must be >= 0, got " + std::to_string(s.rouletteDepth));
    if (s.tileSize < 1) throw std::invalid_argument("tile size must be >= 1, got " + std::to_string(s.tileSize));
    if (!(s.timeLimit >= 0.0) || s.timeLimit > 1e7)
        throw std::invalid_argument("--time-limit must be a number of seconds >= 0, got " +
                                    std::to_string(s.timeLimit));
}

}  // namespace shadelab::trace
