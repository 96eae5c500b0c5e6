// Shadow-map fitting: each shadowed light's layers fitted to the casters' bounds, the depth-test constants
// and the planes that can block it, i.e. the whole ShadowBlock, as a pure function of the scene.
// No GL here: ShadowMaps (shadow_maps.h) renders and uploads what this returns.
#pragma once

#include "raster/draw_range.h"
#include "raster/shadow_block.h"
#include "scene/bounds.h"
#include "scene/scene.h"

#include <vector>

namespace shadelab::raster {

struct ShadowFit {
    ShadowBlock block{};  // ready to upload; block.info.z is the map size in texels
    int layers = 0;       // layers used, from 0 (0: nothing casts, no depth pass)
};

// Bounds of everything that casts: spheres and the uploaded mesh parts (planes occlude analytically).
// Ranges that name no part of `scene` are skipped, as the depth passes skip them.
Bounds casterBounds(const Scene& scene, const std::vector<DrawRange>& ranges);

// The first kMaxShadowedLights lights' layers, in order: directional: one orthographic layer around
// `casters`; point outside their bounding sphere: one perspective frustum holding it; point inside: six
// 90° cube faces, +X −X +Y −Y +Z −Z (the order shaders/cube_face.glsl selects). The ε in block.bias.z is
// the camera's (secondaryRayEpsilon); ShadowMaps::setEpsilon moves it without a refit.
ShadowFit fitShadows(const Scene& scene, const Bounds& casters, const RasterSettings& settings);

// Planes (bits, the first kMaxShadowPlanes) that can block light l for some receiver: the tracer's shadow
// ray from O is blocked by plane k exactly when O and the light lie strictly on opposite sides of it.
int planeMask(const Scene& scene, const Bounds& casters, const Light& l);

}  // namespace shadelab::raster
