// RasterSettings: the rasterizer's own knobs for its shadows and reflections (docs/lighting.md, "Shadows and
// reflections in the rasterizer"), as plain scene data that the scene file ("raster"), the CLI flags, the viewer's
// panel and the tests edit alike. The tracer ignores them. The term switches (Scene::terms.shadows / .reflections)
// decide whether the techniques run.
#pragma once

namespace shadelab {

struct RasterSettings {
    int shadowMapSize = 0;         // texels per side of every shadow-map layer; 0: auto (raster::shadowMapSizeFor)
    float depthBias = 1.0f;        // shadow-map texels, subtracted from the receiver's light-space depth
    float normalBias = 1.5f;       // shadow-map texels, receiver moved along its normal (Holbert 2011)
    bool pcf = false;              // 3x3 percentage-closer filtering; off = one hard comparison, as the tracer
    int reflectionCubeSize = 128;  // texels per face of a reflective sphere's or mesh's environment cube
    bool movingPreview = true;     // viewer only: while the camera moves, draw at half width and height
};

// Accepted ranges (scene-file validation, CLI, viewer sliders).
inline constexpr int kMinShadowMapSize = 16;
inline constexpr int kMaxShadowMapSize = 8192;
inline constexpr float kMaxShadowBias = 64.0f;  // texels, for both biases (>= 0)
inline constexpr int kMinReflectionCubeSize = 8;
inline constexpr int kMaxReflectionCubeSize = 2048;

}  // namespace shadelab
