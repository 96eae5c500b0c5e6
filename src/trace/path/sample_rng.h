// SampleRng: the path tracer's counter-based random numbers (design.md §8). Every number is a pure function
// of (pixel, sample, bounce, dimension), so an image does not depend on threads, tiles or the order in which
// passes run, and a progressive render to N samples equals a one-shot render with N. The hash is pcg4d
// (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3)): four 32-bit lanes mixed by two
// rounds of multiply-add and xorshift, so one call yields four independent numbers.
#pragma once

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
// depends on what other vertices did.
struct SampleRng {
    uint32_t pixel = 0;   // y·width + x
    uint32_t sample = 0;  // sample index within the pixel, 0..spp−1
    uint32_t seed = 0;    // a whole image's variation (0 by default); tests vary it for independent runs

    glm::vec4 draw(uint32_t bounce, uint32_t group) const {
        const glm::uvec4 h = pcg4d(glm::uvec4(pixel, sample, (bounce << 8) | group, seed));
        return {unitFloat(h.x), unitFloat(h.y), unitFloat(h.z), unitFloat(h.w)};
    }
};

}  // namespace shadelab::trace
