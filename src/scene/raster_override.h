// RasterOverride: some of RasterSettings' fields (raster_settings.h), as a scene file's "raster" object, a
// viewer script's setRaster action or the command-line flags give them; the fields left out keep their
// values. Its JSON reader checks the ranges of raster_settings.h and names the JSON path in errors.
#pragma once

#include "scene/raster_settings.h"

#include <optional>

namespace shadelab {

class JsonNode;

struct RasterOverride {
    std::optional<int> shadowMapSize;  // 0 = auto, else [kMinShadowMapSize, kMaxShadowMapSize]
    std::optional<float> depthBias;    // shadow-map texels, [0, kMaxShadowBias]
    std::optional<float> normalBias;   // shadow-map texels, [0, kMaxShadowBias]
    std::optional<bool> pcf;
    std::optional<int> reflectionCubeSize;  // texels per face, [kMinReflectionCubeSize, kMaxReflectionCubeSize]
    std::optional<bool> movingPreview;

    void applyTo(RasterSettings& r) const;
};

// Reads whichever of "shadowMapSize" ("auto", 0 or an integer in range), "depthBias", "normalBias", "pcf"
// "reflectionCubeSize" and "movingPreview" object `n` holds; other keys are the caller's to warn about or refuse.
RasterOverride parseRasterOverride(const JsonNode& n);

}  // namespace shadelab
