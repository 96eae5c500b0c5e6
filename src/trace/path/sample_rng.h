// SampleRng: the path tracer's random numbers (design.md §8). Every number is a pure function of (pixel,
// sample, bounce, group, dimension), so an image does not depend on threads, tiles or the order in which
// passes run, and a progressive render to N samples equals a one-shot render with N. Two samplers give them:
// - Sobol (the default): one point of the Owen-scrambled four-dimensional Sobol sequence per group
//   (owen_sobol.h, Burley 2020), its scrambles and index shuffle seeded by (pixel, bounce, group, seed), so
//   a pixel's samples are stratified in every group while different groups and pixels stay uncorrelated;
// - Independent: a counter-based hash of (pixel, sample, bounce, group), pcg4d (Jarzynski & Olano 2020,
//   "Hash Functions for GPU Rendering", JCGT 9(3)): four 32-bit lanes mixed by two rounds of multiply-add
//   and xorshift, so one call yields four independent numbers. Noise falls as 1/sqrt(N) from the first
//   sample; tests keep it as the plain Monte Carlo reference.
#pragma once

#include "trace/path/owen_sobol.h"
#include "trace/path/path_settings.h"

#include <cstdint>
#include <glm/vec4.hpp>

namespace shadelab::trace {

// pcg4d of (a, b, c, d).
inline glm::uvec4 pcg4d(glm::uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v ^= v >> 16u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// A uniform float in [0, 1) from the top 24 bits (exactly representable, never 1).
inline float unitFloat(uint32_t bits) { return float(bits >> 8) * (1.0f / 16777216.0f); }

// The numbers of one camera sample. draw(bounce, group) returns the four numbers of one group; a path
// vertex uses a few fixed groups (PathIntegrator names them), so which number feeds which decision never
// depends on what other vertices did. Under Sobol the four numbers of a group are one 4D point and a
// pixel's samples 0, 1, 2, ... of one group are that group's sequence.
struct SampleRng {
    uint32_t pixel = 0;   // y·width + x
    uint32_t sample = 0;  // sample index within the pixel, 0..spp−1
    uint32_t seed = 0;    // a whole image's variation (0 by default); tests vary it for independent runs
    PathSampler sampler = PathSampler::Sobol;

    glm::vec4 draw(uint32_t bounce, uint32_t group) const {
        const uint32_t use = (bounce << 8) | group;
        glm::uvec4 h;
        if (sampler == PathSampler::Independent) {
            h = pcg4d(glm::uvec4(pixel, sample, use, seed));
        } else {
            // The four dimensions' scramble seeds and the index shuffle's, from (pixel, use, seed) alone:
            // the same for every sample of the group, so its samples are one scrambled sequence. The last
            // lane tells these hashes from the independent sampler's.
            const glm::uvec4 dimSeeds = pcg4d(glm::uvec4(pixel, use, seed, 0x50B01u));
            h = owenSobol4(sample, pcg4d(dimSeeds).x, dimSeeds);
        }
        return {unitFloat(h.x), unitFloat(h.y), unitFloat(h.z), unitFloat(h.w)};
    }
};

}  // namespace shadelab::trace
