// The raster-against-reference comparison's policy, in one place for the CLI (--renderer both), the viewer
// (Split, Difference) and the tests: what each renderer hands over, and the depth the reference is traced
// at. Not the gates or the metrics (compare/image_compare.h); it renders nothing and links neither renderer.
#pragma once

#include "image/image.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace shadelab {

// One renderer's side of a comparison: the 8-bit image and, per pixel, the object it shows (scene/coverage.h).
struct Rendered {
    Image8 pixels;
    std::vector<uint32_t> coverage;  // empty when coverage was not asked for
    uint64_t nonFinite = 0;          // pixels that had a NaN or infinite channel before conversion (toImage8)
};

// The reference's secondary-ray depth when it is compared with the rasterizer: `requested` (a render
// request's depth) if given, else the scene's maxDepth capped at 1, because the rasterizer reflects once.
int comparisonDepth(const Scene& scene, std::optional<int> requested = std::nullopt);

}  // namespace shadelab
