// C++ mirror of the std140 `Shadows` uniform block in shaders/shadow.glsl, layout pinned by static_asserts
// (as frame_block.h). Filled by ShadowMaps; read by every colour pass when scene.terms.shadows is on.
#pragma once

#include "raster/raster_limits.h"

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace shadelab::raster {

enum ShadowKind : int { kShadowNone = 0, kShadowOrtho = 1, kShadowPerspective = 2, kShadowCube = 3 };

struct ShadowBlock {
    glm::mat4 layerViewProj[kMaxShadowLayers];  // world → clip space of each shadow-map layer
    glm::ivec4 light[kMaxShadowedLights];       // x: ShadowKind, y: first layer, z: planes that can block it (bits)
    glm::vec4 range[kMaxShadowedLights];  // x: texel footprint (ortho: world; else per unit distance), y: near, z: far
    glm::vec4 depth[kMaxShadowedLights];  // the depth test without divisions, perspectiveDepthTest / orthoDepthTest
    glm::vec4 planes[kMaxShadowPlanes];   // xyz: unit normal, w: offset
    glm::ivec4 info;                      // x: plane count, y: pcf, z: map size (texels), w: 0
    glm::vec4 bias;                       // x: depth bias (texels), y: normal bias (texels), z: scene epsilon
};

static_assert(offsetof(ShadowBlock, light) == 64 * kMaxShadowLayers);
static_assert(offsetof(ShadowBlock, range) == 64 * kMaxShadowLayers + 16 * kMaxShadowedLights);
static_assert(offsetof(ShadowBlock, depth) == 64 * kMaxShadowLayers + 32 * kMaxShadowedLights);
static_assert(offsetof(ShadowBlock, planes) == 64 * kMaxShadowLayers + 48 * kMaxShadowedLights);
static_assert(offsetof(ShadowBlock, info) == 64 * kMaxShadowLayers + 48 * kMaxShadowedLights + 16 * kMaxShadowPlanes);
static_assert(sizeof(ShadowBlock) == 64 * kMaxShadowLayers + 48 * kMaxShadowedLights + 16 * kMaxShadowPlanes + 32);

// ShadowBlock::depth for a light whose map stores window depth of a perspective projection (near n, far f):
// a receiver at distance r along the layer's axis is lit by a stored depth d when window(r) <= d, i.e.
// A - B/r <= d, tested as (A - d)·r <= B. For an orthographic map: z = the depth bias in window units.
// Defined in shadow_fit.cpp.
glm::vec4 perspectiveDepthTest(float zNear, float zFar);
glm::vec4 orthoDepthTest(float zNear, float zFar, float texelWorld, float depthBiasTexels);

}  // namespace shadelab::raster
