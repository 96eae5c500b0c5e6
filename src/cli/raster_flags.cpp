// Parsing of the rasterizer flags (raster_flags.h), with the ranges of scene/raster_settings.h.
#include "cli/raster_flags.h"

#include "cli/args.h"
#include "util/input_error.h"

namespace shadelab::cli {

const char* const kRasterFlagsHelp =
    "  --shadow-map-size N|auto   raster shadow maps of N x N texels, 16..8192, or auto: 1024, and 2048 from\n"
    "                             1448 px on the image's longer side (default: the scene's \"raster\")\n"
    "  --shadow-bias TEXELS       raster shadow depth bias in shadow-map texels, 0..64 (default: the scene's)\n"
    "  --normal-bias TEXELS       raster shadow normal-offset bias in texels, 0..64 (default: the scene's)\n"
    "  --pcf, --no-pcf            raster shadows filtered 3x3 (PCF), softer than the reference's hard edges,\n"
    "                             or hard (default: the scene's, normally hard)\n"
    "  --reflection-cube-size N   texels per face of the raster environment cube of reflective spheres and\n"
    "                             meshes, 8..2048 (default: the scene's)\n";

const std::vector<std::string>& rasterValuedFlags() {
    static const std::vector<std::string> flags = {"--shadow-map-size", "--shadow-bias", "--normal-bias",
                                                   "--reflection-cube-size"};
    return flags;
}

const std::vector<std::string>& rasterSwitchFlags() {
    static const std::vector<std::string> flags = {"--pcf", "--no-pcf"};
    return flags;
}

bool parseRasterFlag(const std::string& name, const std::string& value, RasterOverride& o) {
    if (name == "--shadow-map-size") {
        if (value == "auto" || value == "0") {
            o.shadowMapSize = 0;
        } else {
            try {
                o.shadowMapSize = parseInt(name, value, kMinShadowMapSize, kMaxShadowMapSize);
            } catch (const UsageError&) {
                throw UsageError(name + ": expected auto or a whole number from " + std::to_string(kMinShadowMapSize) +
                                 " to " + std::to_string(kMaxShadowMapSize) + ", got '" + value + "'");
            }
        }
    } else if (name == "--shadow-bias") {
        o.depthBias = parseNumber(name, value, 0.0f, kMaxShadowBias);
    } else if (name == "--normal-bias") {
        o.normalBias = parseNumber(name, value, 0.0f, kMaxShadowBias);
    } else if (name == "--pcf" || name == "--no-pcf") {
        o.pcf = name == "--pcf";
    } else if (name == "--reflection-cube-size") {
        o.reflectionCubeSize = parseInt(name, value, kMinReflectionCubeSize, kMaxReflectionCubeSize);
    } else {
        return false;
    }
    return true;
}

RasterOverride parseRasterFlags(const Args& args) {
    RasterOverride o;
    for (const std::string& name : rasterValuedFlags())
        if (auto v = args.value(name)) parseRasterFlag(name, *v, o);
    for (const std::string& name : rasterSwitchFlags())
        if (args.flag(name)) parseRasterFlag(name, "", o);
    return o;
}

}  // namespace shadelab::cli
