// The command-line flags that override the scene's rasterizer settings (Scene::raster), shared by
// `shadelab render` and `shadelab view` so that both accept the same names, ranges and messages.
#pragma once

#include "scene/raster_override.h"

#include <string>
#include <vector>

namespace shadelab::cli {

class Args;

// --help lines for the flags, options at column 2 and their meaning at column 29, as both commands' help.
extern const char* const kRasterFlagsHelp;

// The flags that take a value (--shadow-map-size, ...), and those that do not (--pcf).
const std::vector<std::string>& rasterValuedFlags();
const std::vector<std::string>& rasterSwitchFlags();

// Records flag `name` in `o`, with `value` (unused for a switch). Returns false when `name` is not a raster
// flag; throws UsageError naming the flag when the value is bad.
bool parseRasterFlag(const std::string& name, const std::string& value, RasterOverride& o);

// Every raster flag `args` holds (it must accept them all); --no-pcf wins when both it and --pcf are given.
RasterOverride parseRasterFlags(const Args& args);

}  // namespace shadelab::cli
