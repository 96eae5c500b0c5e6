// C++ view of shaders/texture_sample.glsl: the same sampling text compiled as members of TextureLookup,
// whose texel hooks read a plain view of one texture's 8-bit mip chain and decode each texel through the
// tables of shading/texel_decode.h, as GL's texelFetch decodes GL_SRGB8_ALPHA8 / GL_RGBA8 (the tracer builds
// the view from scene/texture.h; the rasterizer runs the GLSL over texelFetch). No GL and no scene types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace shadelab::shading {

struct TexelLevelView {
    int width = 0, height = 0;
    const uint8_t* texels = nullptr;  // RGBA bytes, row-major, row 0 first
};

// Wrap-mode numbers of texture_sample.glsl.
inline constexpr int kTexRepeat = 0, kTexMirroredRepeat = 1, kTexClamp = 2;

struct TextureLookup {
    const TexelLevelView* levels = nullptr;  // one texture's chain; `map` is ignored (one texture per lookup)
    int levelCount = 0;
    const float* rgb = nullptr;    // 256 linear values of an RGB code: srgbDecodeTable() or unormDecodeTable()
    const float* alpha = nullptr;  // 256 linear values of an alpha code: unormDecodeTable()

    using vec2 = glm::vec2;
    using vec4 = glm::vec4;

    vec4 texTexel(int, int level, int x, int y) const {
        const TexelLevelView& l = levels[level];
        // texSample's folding already keeps (x, y) inside the level; the clamp, in integers, makes a read
        // outside it impossible whatever coordinate reached the sampler.
        x = glm::clamp(x, 0, l.width - 1);
        y = glm::clamp(y, 0, l.height - 1);
        const uint8_t* p = l.texels + 4 * (size_t(y) * size_t(l.width) + size_t(x));
        return vec4(rgb[p[0]], rgb[p[1]], rgb[p[2]], alpha[p[3]]);
    }
    int texWidth(int, int level) const { return levels[level].width; }
    int texHeight(int, int level) const { return levels[level].height; }

    // The GLSL built-ins the text uses, for its argument types.
#define SL_FN
    static float clamp(float x, float a, float b) { return glm::clamp(x, a, b); }
    static int clamp(int x, int a, int b) { return glm::clamp(x, a, b); }
    static float max(float a, float b) { return glm::max(a, b); }
    static float floor(float a) { return glm::floor(a); }
    static float ceil(float a) { return glm::ceil(a); }
    static float min(float a, float b) { return glm::min(a, b); }
    static int min(int a, int b) { return glm::min(a, b); }
    static float log2(float a) { return glm::log2(a); }
    static float dot(vec2 a, vec2 b) { return glm::dot(a, b); }
    static vec4 mix(vec4 a, vec4 b, float t) { return glm::mix(a, b, t); }
#include "shaders/texture_sample.glsl"
#undef SL_FN
};

}  // namespace shadelab::shading
