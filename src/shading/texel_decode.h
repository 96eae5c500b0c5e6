// 8-bit texel codes to the linear values both renderers filter (design.md §9). Textures are stored as 8-bit
// RGBA (scene/texture.h): colour maps' RGB sRGB-encoded, everything else (data maps, every alpha) linear.
// A code's linear value is the exact one rounded once to the nearest half float (IEEE binary16, ties to
// even), so that the rasterizer can upload it losslessly as RGBA16F (raster/mesh_textures.cpp) and read it
// back with texelFetch bit for bit, while the tracer decodes the same codes through the float tables here.
// (llvmpipe's own GL_SRGB8_ALPHA8 decoding is off by up to 1.2e-3 and its GL_RGBA8 by an ulp, and decoding
// through tables in the shader costs more than the filtering: tests/texel_decode_test.cpp.) A half keeps
// 11 significant bits, so every code keeps a distinct value (the closest two, sRGB 254 and 255, are 0.009
// apart). No GL and no scene types.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace shadelab::shading {

// The value of half-float bits `h` (finite, non-negative), exactly.
inline double halfBitsValue(uint16_t h) {
    const int exponent = (h >> 10) & 31, mantissa = h & 1023;
    return exponent == 0 ? std::ldexp(double(mantissa), -24) : std::ldexp(double(1024 + mantissa), exponent - 25);
}

// The half float nearest to v in [0, 1], ties to even, by bisection over the ordered bit patterns (0 .. 0x3C00).
inline uint16_t halfBitsNearest(double v) {
    uint16_t lo = 0, hi = 0x3C00;  // halfBitsValue(hi) = 1
    while (hi - lo > 1) {
        const uint16_t mid = uint16_t((lo + hi) / 2);
        (halfBitsValue(mid) <= v ? lo : hi) = mid;
    }
    const double dlo = v - halfBitsValue(lo), dhi = halfBitsValue(hi) - v;
    return dlo < dhi ? lo : dhi < dlo ? hi : (lo % 2 == 0 ? lo : hi);
}

// One decoding: code → half bits (for the GL upload) and the same value as a float (for the tracer).
struct TexelDecodeTable {
    std::array<uint16_t, 256> half{};
    std::array<float, 256> value{};
};

// sRGB codes (IEC 61966-2-1: c/255 ≤ 0.04045: c/255/12.92, else ((c/255 + 0.055)/1.055)^2.4).
inline const TexelDecodeTable& srgbDecodeTable() {
    static const TexelDecodeTable table = [] {
        TexelDecodeTable t;
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t.half[size_t(i)] = halfBitsNearest(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
            t.value[size_t(i)] = float(halfBitsValue(t.half[size_t(i)]));
        }
        return t;
    }();
    return table;
}

// Linear (UNORM8) codes: c / 255.
inline const TexelDecodeTable& unormDecodeTable() {
    static const TexelDecodeTable table = [] {
        TexelDecodeTable t;
        for (int i = 0; i < 256; ++i) {
            t.half[size_t(i)] = halfBitsNearest(i / 255.0);
            t.value[size_t(i)] = float(halfBitsValue(t.half[size_t(i)]));
        }
        return t;
    }();
    return table;
}

}  // namespace shadelab::shading
