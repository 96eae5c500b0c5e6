// RasterSettings: the rasterizer's own knobs for shadows and reflections (issue 5), a plain struct with
// defaults that the CLI, the viewer and the tests edit alike. Not scene data: the scene's term switches
// (scene.terms.shadows / .reflections) decide whether these techniques run at all.
#pragma once

#include <algorithm>

namespace shadelab::raster {

struct RasterSettings {
    int shadowMapSize = 0;           // texels per side of every shadow-map layer; 0: auto (shadowMapSizeFor)
    float depthBias = 1.0f;          // shadow-map texels, subtracted from the receiver's light-space depth
    float normalBias = 1.5f;         // shadow-map texels, receiver moved along its normal (Holbert 2011)
    bool pcf = false;                // 3x3 percentage-closer filtering; off = one hard comparison, as the tracer
    int reflectionCubeSize = 128;    // texels per face of a reflective sphere's or mesh's environment cube
};

// The shadow-map size a draw of a width x height image uses. Auto (0) matches the map to the image: the power
// of two nearest its longer side, within [1024, 2048] (1024 up to 1448 px, 2048 above). Finer maps than the
// image cost lookups their cache misses (on llvmpipe the 720p viewer frame) and gain nothing visible;
// coarser ones step the shadow edges. An explicit size is kept as given, within [16, kMaxShadowMapSize].
inline constexpr int kMinShadowMapSize = 16;
inline constexpr int kMaxShadowMapSize = 8192;
inline int shadowMapSizeFor(const RasterSettings& s, int width, int height) {
    if (s.shadowMapSize > 0) return std::clamp(s.shadowMapSize, kMinShadowMapSize, kMaxShadowMapSize);
    return std::max(width, height) >= 1448 ? 2048 : 1024;  // 1448 ≈ 1024·√2: nearer to 2048 than to 1024 in log2
}

// Limits of the shadow and reflection passes (docs/lighting.md "Shadows and reflections in the rasterizer").
inline constexpr int kMaxShadowedLights = 8;      // lights 0..7 cast shadows; later lights are unshadowed
inline constexpr int kMaxShadowLayers = 6 * kMaxShadowedLights;
inline constexpr int kMaxShadowPlanes = 8;        // planes occlude analytically; later planes do not
inline constexpr int kMaxMirrorPlanes = 4;        // planes with kr > 0 that get a planar reflection pass

}  // namespace shadelab::raster
