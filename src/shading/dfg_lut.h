// The split-sum DFG table (Karis 2013): GGX with height-correlated Smith and Schlick Fresnel integrated over
// the hemisphere, computed once in C++ and shared by both renderers (the rasterizer uploads these floats).
#pragma once

#include "shading/environment_map.h"

namespace shadelab::shading {

inline constexpr int kDfgLutSize = 32;       // texels per side: N·V × roughness
inline constexpr int kDfgLutSamples = 1024;  // Hammersley samples per texel

// Computes the table (about 30 ms on one core at the defaults).
DfgLut computeDfgLut(int size = kDfgLutSize, int samples = kDfgLutSamples);

// The table at the defaults, computed on first use (thread-safe) and kept.
const DfgLut& dfgLut();

// Hammersley point i of n (Hammersley 1964; the radical inverse in base 2), in [0, 1)².
void hammersley(unsigned i, unsigned n, float& u, float& v);

// Walter et al. 2007, GGX importance sampling: a half-vector in the frame where N = +z, pdf D(h)·(N·H).
glm::vec3 importanceSampleGGX(float u, float v, float alpha);

}  // namespace shadelab::shading
