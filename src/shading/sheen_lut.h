// The sheen's directional albedo E(N·V, roughness) = ∫ f_sheen·N·L dω for a sheen colour of 1 (the Charlie
// lobe of shaders/gltf_layers.glsl, sheenLobe), integrated numerically once in C++ and read by every renderer
// (the rasterizer uploads these floats). KHR_materials_sheen scales the base under the sheen by 1 − max3(c)·E:
// a published fit of E is off by up to 0.06, so the table is computed from the lobe itself.
#pragma once

#include "shading/lighting.h"

#include <vector>

namespace shadelab::shading {

struct SheenLut {
    int size = 0;
    std::vector<float> e;  // size·size albedos, row j = roughness j/(size − 1), column i = N·V i/(size − 1)
};

inline constexpr int kSheenLutSize = 64;       // texels per side: N·V × roughness (the albedo is steep near grazing)
inline constexpr int kSheenLutSamples = 1024;  // Hammersley samples per texel

// Computes the table (about 40 ms on one core at the defaults).
SheenLut computeSheenLut(int size = kSheenLutSize, int samples = kSheenLutSamples);

// The table at the defaults, computed on first use (thread-safe) and kept.
const SheenLut& sheenLut();

// A fibre normal of the Charlie distribution with α `alpha`, in the frame where N = +z, drawn with density
// D_Charlie(h)·(N·H) from (u, v) in [0, 1)²: the CDF in θ is sin^(2 + 1/α) θ, so sin θ = u^(α/(2α + 1)).
glm::vec3 importanceSampleCharlie(float u, float v, float alpha);

// The GLSL lookup (shaders/sheen_albedo.glsl) over a table's texels.
struct SheenLookup {
    const SheenLut* lut = nullptr;

    float sheenTexel(int x, int y) const { return lut->e[size_t(y) * size_t(lut->size) + size_t(x)]; }

#define SL_FN
#include "shaders/sheen_albedo.glsl"
#undef SL_FN

    float at(float NoV, float roughness) const { return SheenLookup(*this).sheenAlbedo(lut->size, NoV, roughness); }
};

// E at (cos θ, roughness) in the table at the defaults.
inline float sheenAlbedoAt(float cosTheta, float roughness) { return SheenLookup{&sheenLut()}.at(cosTheta, roughness); }

}  // namespace shadelab::shading
