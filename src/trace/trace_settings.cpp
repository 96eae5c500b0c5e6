// TraceSettings validation and the derived values (grid size, thread count).
#include "trace/trace_settings.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

namespace shadelab::trace {

int samplesPerAxis(const TraceSettings& s) {
    int k = int(std::lround(std::sqrt(double(s.spp))));
    while (k * k > s.spp) --k;
    while ((k + 1) * (k + 1) <= s.spp) ++k;
    return k;
}

void validate(const TraceSettings& s) {
    if (s.width < 1 || s.height < 1)
        throw std::invalid_argument("image size must be at least 1x1, got " + std::to_string(s.width) + "x" +
                                    std::to_string(s.height));
    if (s.spp < 1 || s.spp > 4096)
        throw std::invalid_argument("--spp must be in [1, 4096], got " + std::to_string(s.spp));
    const int k = samplesPerAxis(s);
    if (k * k != s.spp)
        throw std::invalid_argument(
            "--spp must be a perfect square (1, 4, 9, 16, ...) for the fixed k x k "
            "sample grid both renderers share, got " +
            std::to_string(s.spp) + "; nearest: " + std::to_string(k * k) + " or " + std::to_string((k + 1) * (k + 1)));
    if (s.threads < 0)
        throw std::invalid_argument("--threads must be >= 0 (0 = all cores), got " + std::to_string(s.threads));
    if (s.maxDepth < -1 || s.maxDepth > 64)
        throw std::invalid_argument("--depth must be in [0, 64], got " + std::to_string(s.maxDepth));
    if (!(s.rayTree.minWeight >= 0.0f && s.rayTree.minWeight <= 1.0f))
        throw std::invalid_argument("ray-tree minimum weight must be in [0, 1], got " +
                                    std::to_string(s.rayTree.minWeight));
    if (s.rayTree.maxRays < -1)
        throw std::invalid_argument("ray-tree budget must be >= 0 secondary rays per sample (-1 = no limit), got " +
                                    std::to_string(s.rayTree.maxRays));
    if (s.tileSize < 1) throw std::invalid_argument("tile size must be >= 1, got " + std::to_string(s.tileSize));
}

int resolveThreads(const TraceSettings& s) {
    if (s.threads > 0) return s.threads;
    const unsigned n = std::thread::hardware_concurrency();
    return n > 0 ? int(n) : 1;
}

}  // namespace shadelab::trace
