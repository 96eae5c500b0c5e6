// RasterOverride: applying it, and reading it from JSON with the scene loader's path-naming errors.
#include "scene/raster_override.h"

#include "scene/json_reader.h"

#include <cmath>
#include <string>

namespace shadelab {

void RasterOverride::applyTo(RasterSettings& r) const {
    if (shadowMapSize) r.shadowMapSize = *shadowMapSize;
    if (depthBias) r.depthBias = *depthBias;
    if (normalBias) r.normalBias = *normalBias;
    if (pcf) r.pcf = *pcf;
    if (reflectionCubeSize) r.reflectionCubeSize = *reflectionCubeSize;
    if (movingPreview) r.movingPreview = *movingPreview;
}

namespace {

// "auto" or 0 (both auto), or a whole number of texels in [kMinShadowMapSize, kMaxShadowMapSize].
int shadowMapSize(const JsonNode& n) {
    const nlohmann::json& j = n.json();
    if (j.is_string() && j.get<std::string>() == "auto") return 0;
    if (j.is_number()) {
        const double d = j.get<double>();
        if (d == 0.0) return 0;
        if (d == std::floor(d) && d >= kMinShadowMapSize && d <= kMaxShadowMapSize) return int(d);
    }
    n.fail("expected \"auto\" or an integer in " + std::to_string(kMinShadowMapSize) + ".." +
           std::to_string(kMaxShadowMapSize) + ", got " + j.dump());
}

}  // namespace

RasterOverride parseRasterOverride(const JsonNode& n) {
    n.requireObject();
    RasterOverride o;
    if (auto f = n.find("shadowMapSize")) o.shadowMapSize = shadowMapSize(*f);
    if (auto f = n.find("depthBias")) o.depthBias = f->inRange(0.0f, kMaxShadowBias, false, false);
    if (auto f = n.find("normalBias")) o.normalBias = f->inRange(0.0f, kMaxShadowBias, false, false);
    if (auto f = n.find("pcf")) o.pcf = f->boolean();
    if (auto f = n.find("reflectionCubeSize"))
        o.reflectionCubeSize = f->integerIn(kMinReflectionCubeSize, kMaxReflectionCubeSize);
    if (auto f = n.find("movingPreview")) o.movingPreview = f->boolean();
    return o;
}

}  // namespace shadelab
