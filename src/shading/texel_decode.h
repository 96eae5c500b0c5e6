// 8-bit texel codes to the linear floats the tracer filters (design.md §9). Textures are stored as 8-bit RGBA
// (scene/texture.h): colour maps' RGB sRGB-encoded, everything else (data maps, every alpha) linear. The
// rasterizer uploads the codes as GL_SRGB8_ALPHA8 / GL_RGBA8 and texelFetch decodes them before
// texture_sample.glsl filters; the tracer decodes through these tables at fetch. llvmpipe's decoding is not
// bit-exact: within kGlTexelDecodeError of these tables (tests/texel_decode_test.cpp measures it), far under
// what the §4 gates can see. No GL and no scene types.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace shadelab::shading {

// The most a GL's decoding of an 8-bit code may differ from these tables: llvmpipe (Mesa 22.3) decodes sRGB
// with a polynomial, measured at most 1.2e-3 off (about 0.3/255 of the sRGB-encoded output), and UNORM8 by a
// multiplication, one ulp off.
inline constexpr float kGlTexelDecodeError = 2e-3f;

// The linear value of each sRGB code c (IEC 61966-2-1: c/255 ≤ 0.04045: c/255/12.92, else
// ((c/255 + 0.055)/1.055)^2.4), computed in double and rounded once to float.
inline const std::array<float, 256>& srgbDecodeTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

// Linear (UNORM8) codes: c / 255, rounded once to float.
inline const std::array<float, 256>& unormDecodeTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[size_t(i)] = float(double(i) / 255.0);
        return t;
    }();
    return table;
}

}  // namespace shadelab::shading
