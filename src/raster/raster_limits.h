// The rasterizer's fixed limits for shadows and reflections, and how it resolves RasterSettings (scene data,
// src/scene/raster_settings.h) for one image.
#pragma once

#include "scene/raster_settings.h"

#include <algorithm>
#include <cstddef>

namespace shadelab::raster {

// The shadow-map size a draw of a width x height image uses. Auto (0) matches the map to the image: the power
// of two nearest its longer side, within [1024, 2048]: 1024 below 1448 px, 2048 from 1448 px on. Finer
// maps than the image cost lookups their cache misses (on llvmpipe the 720p viewer frame) and gain nothing
// visible; coarser ones step the shadow edges. An explicit size is kept as given, within [16, kMaxShadowMapSize].
inline int shadowMapSizeFor(const RasterSettings& s, int width, int height) {
    if (s.shadowMapSize > 0) return std::clamp(s.shadowMapSize, kMinShadowMapSize, kMaxShadowMapSize);
    return std::max(width, height) >= 1448 ? 2048 : 1024;  // 1448 ≈ 1024·√2, halfway in log2
}

// Limits of the shadow and reflection passes (docs/lighting.md "Shadows and reflections in the rasterizer").
inline constexpr int kMaxShadowedLights = 8;  // lights 0..7 cast shadows; later lights are unshadowed
inline constexpr int kMaxShadowLayers = 6 * kMaxShadowedLights;
inline constexpr int kMaxShadowPlanes = 8;     // planes occlude analytically; later planes do not
inline constexpr int kMaxMirrorPlanes = 4;     // planes with kr > 0 that get a planar reflection pass
inline constexpr size_t kMaxPartialIds = 8;    // objects a partial redraw may redo (partial_merge.frag u_ids)
inline constexpr int kMaxShadowMapMiB = 2048;  // all layers together; a larger request is an error

// Reflective spheres and mesh parts beyond these get no environment cube (raster/environment_cubes.h).
inline constexpr int kMaxEnvironmentCubes = 8;

}  // namespace shadelab::raster
