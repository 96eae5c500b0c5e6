// The sample grid's rule: which samples-per-pixel counts are a k×k grid.
#include "scene/sample_grid.h"

#include "util/input_error.h"

#include <string>

namespace shadelab {

int gridSamplesPerSide(int spp) {
    int k = 1;
    while (k < kMaxGridSamplesPerSide && (k + 1) * (k + 1) <= spp) ++k;
    if (spp == k * k) return k;
    std::string reason = "expected a perfect square from 1 to " + std::to_string(kMaxGridSamples) +
                         " (1, 4, 9, 16, ...) for the k x k sample grid both renderers share, got " +
                         std::to_string(spp);
    if (spp > 1 && spp < kMaxGridSamples)
        reason += "; nearest: " + std::to_string(k * k) + " or " + std::to_string((k + 1) * (k + 1));
    throw SettingError("spp", reason);
}

}  // namespace shadelab
