// RasterSettings: the rasterizer's own knobs for shadows and reflections (issue 5), a plain struct with
// defaults that the CLI, the viewer and the tests edit alike. Not scene data: the scene's term switches
// (scene.terms.shadows / .reflections) decide whether these techniques run at all.
#pragma once

namespace shadelab::raster {

struct RasterSettings {
    int shadowMapSize = 2048;        // texels per side of every shadow-map layer
    float depthBias = 1.0f;          // shadow-map texels, subtracted from the receiver's light-space depth
    float normalBias = 1.5f;         // shadow-map texels, receiver moved along its normal (Holbert 2011)
    bool pcf = false;                // 3x3 percentage-closer filtering; off = one hard comparison, as the tracer
    int reflectionCubeSize = 128;    // texels per face of a reflective sphere's or mesh's environment cube
};

// Limits of the shadow and reflection passes (docs/lighting.md "Shadows and reflections in the rasterizer").
inline constexpr int kMaxShadowedLights = 8;      // lights 0..7 cast shadows; later lights are unshadowed
inline constexpr int kMaxShadowLayers = 6 * kMaxShadowedLights;
inline constexpr int kMaxShadowPlanes = 8;        // planes occlude analytically; later planes do not
inline constexpr int kMaxMirrorPlanes = 4;        // planes with kr > 0 that get a planar reflection pass

}  // namespace shadelab::raster
