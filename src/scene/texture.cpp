// Texture construction: 8-bit level 0 as given, then the mip chain averaged in linear light and re-encoded
// to 8 bits (texture.h).
#include "scene/texture.h"

#include "shading/texel_decode.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>

namespace shadelab {
namespace {

// image/encode.cpp's sRGB curve and rounding (encodeChannel): the reference the fast encoder below matches.
uint8_t encodeReference(float linear, bool srgb) {
    const double x = std::clamp(double(linear), 0.0, 1.0);
    const double v = !srgb ? x : x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    return uint8_t(std::min(255.0, std::max(0.0, std::floor(v * 255.0 + 0.5))));
}

// The sRGB encoder, exact against encodeReference and fast: a 4096-entry table of the code at each bucket's
// lower end, then one step up if the value reaches the next code's threshold (never more: the curve's
// steepest slope, 12.92 · 255 codes per unit, is under 4096, so no bucket spans two thresholds; checked at
// construction). threshold[c] is the least float whose code exceeds c.
struct SrgbEncoder {
    std::array<uint8_t, 4097> start{};
    std::array<float, 256> threshold{};
    SrgbEncoder() {
        for (int c = 0; c < 255; ++c) {
            // Bisection over the ordered bit patterns of floats in [0, 1].
            uint32_t lo = 0, hi = 0x3f800000u;  // encodeReference(0) = 0 ≤ c < 255 = encodeReference(1)
            while (hi - lo > 1) {
                const uint32_t mid = lo + (hi - lo) / 2;
                float f;
                std::memcpy(&f, &mid, sizeof f);
                (encodeReference(f, true) > c ? hi : lo) = mid;
            }
            std::memcpy(&threshold[size_t(c)], &hi, sizeof(float));
        }
        threshold[255] = std::numeric_limits<float>::infinity();
        for (int b = 0; b <= 4096; ++b) start[size_t(b)] = encodeReference(float(b) / 4096.0f, true);
        for (int b = 0; b < 4096; ++b)
            if (start[size_t(b) + 1] - start[size_t(b)] > 1) std::abort();  // one step would not be enough
    }
    uint8_t operator()(float v) const {
        if (!(v > 0.0f)) return 0;  // NaN too
        if (v >= 1.0f) return 255;
        const int c = start[size_t(v * 4096.0f)];
        return uint8_t(c + (v >= threshold[size_t(c)] ? 1 : 0));
    }
};

const SrgbEncoder& srgbEncoder() {
    static const SrgbEncoder e;
    return e;
}

uint8_t encodeLinear(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return uint8_t(std::floor(double(v) * 255.0 + 0.5));
}

// The source indices that fold into destination index d along an axis of `src` texels: 2d and 2d+1, plus
// 2d+2 for the last destination texel of an odd size.
int spanOf(int d, int src, int dst) { return (d == dst - 1 && src > 2 * dst) ? 3 : std::min(2, src - 2 * d); }

// One 2×2 box-filter step: `dst` (float RGBA, dw × dh) from the source's linear texels, read by
// `at(x, y, sum)`, which adds texel (x, y) to sum.
template <class Read>
void halve(int sw, int sh, const Read& at, float* dst, int& dw, int& dh) {
    dw = std::max(1, sw / 2);
    dh = std::max(1, sh / 2);
    for (int y = 0; y < dh; ++y) {
        const int y0 = sh == 1 ? 0 : 2 * y, ny = sh == 1 ? 1 : spanOf(y, sh, dh);
        for (int x = 0; x < dw; ++x) {
            const int x0 = sw == 1 ? 0 : 2 * x, nx = sw == 1 ? 1 : spanOf(x, sw, dw);
            float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) at(x0 + i, y0 + j, sum);
            float* out = dst + (size_t(y) * size_t(dw) + size_t(x)) * 4;
            const float n = float(nx * ny);
            for (int k = 0; k < 4; ++k) out[k] = sum[k] / n;
        }
    }
}

TextureLevel encodeLevel(const float* linear, int w, int h, bool srgb) {
    TextureLevel l;
    l.width = w;
    l.height = h;
    l.texels.resize(size_t(w) * size_t(h) * kTexelBytes);
    const SrgbEncoder& enc = srgbEncoder();
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
        const float* v = linear + 4 * i;
        uint8_t* p = &l.texels[4 * i];
        for (int k = 0; k < 3; ++k) p[k] = srgb ? enc(v[k]) : encodeLinear(v[k]);
        p[3] = encodeLinear(v[3]);
    }
    return l;
}

}  // namespace

uint8_t encodeTexelChannel(float linear, bool srgb) { return srgb ? srgbEncoder()(linear) : encodeLinear(linear); }

size_t Texture::texelBytes() const {
    size_t n = 0;
    for (const TextureLevel& l : levels) n += l.texels.size();
    return n;
}

glm::vec4 Texture::texel(size_t level, int x, int y) const {
    const TextureLevel& l = levels[level];
    const uint8_t* p = &l.texels[(size_t(y) * size_t(l.width) + size_t(x)) * kTexelBytes];
    const std::array<float, 256>& rgb = (srgb ? shading::srgbDecodeTable() : shading::unormDecodeTable());
    const std::array<float, 256>& a = shading::unormDecodeTable();
    return {rgb[p[0]], rgb[p[1]], rgb[p[2]], a[p[3]]};
}

uint64_t textureBytesFor(int width, int height) {
    uint64_t n = 0;
    uint64_t w = uint64_t(std::max(width, 1)), h = uint64_t(std::max(height, 1));
    for (;;) {
        n += w * h * kTexelBytes;
        if (w == 1 && h == 1) return n;
        w = std::max<uint64_t>(1, w / 2);
        h = std::max<uint64_t>(1, h / 2);
    }
}

std::shared_ptr<const Texture> makeTexture(std::string name, const uint8_t* rgba, int width, int height, bool srgb) {
    auto tex = std::make_shared<Texture>();
    tex->name = std::move(name);
    tex->srgb = srgb;
    TextureLevel base;
    base.width = width;
    base.height = height;
    base.texels.assign(rgba, rgba + size_t(width) * size_t(height) * kTexelBytes);
    tex->levels.push_back(std::move(base));
    if (width <= 1 && height <= 1) return tex;

    // Level 1 straight from the 8-bit codes, each next level from the previous one's unrounded floats, in two
    // buffers used in turn (each level is at most a quarter of the one before, after level 1's). Not
    // zero-filled: every float is written before it is read.
    const float* rgb = (srgb ? shading::srgbDecodeTable() : shading::unormDecodeTable()).data();
    const float* alpha = shading::unormDecodeTable().data();
    const size_t level1 = size_t(std::max(1, width / 2)) * size_t(std::max(1, height / 2)) * 4;
    std::unique_ptr<float[]> a(new float[level1]), b(new float[level1 / 2 + 4]);
    float* cur = a.get();
    float* next = b.get();
    int w = 0, h = 0;
    halve(
        width, height,
        [&](int x, int y, float* sum) {
            const uint8_t* p = rgba + (size_t(y) * size_t(width) + size_t(x)) * kTexelBytes;
            sum[0] += rgb[p[0]];
            sum[1] += rgb[p[1]];
            sum[2] += rgb[p[2]];
            sum[3] += alpha[p[3]];
        },
        cur, w, h);
    tex->levels.push_back(encodeLevel(cur, w, h, srgb));
    while (w > 1 || h > 1) {
        const int sw = w;
        int nw = 0, nh = 0;
        halve(
            w, h,
            [&](int x, int y, float* sum) {
                const float* v = cur + (size_t(y) * size_t(sw) + size_t(x)) * 4;
                for (int k = 0; k < 4; ++k) sum[k] += v[k];
            },
            next, nw, nh);
        std::swap(cur, next);
        w = nw;
        h = nh;
        tex->levels.push_back(encodeLevel(cur, w, h, srgb));
    }
    return tex;
}

}  // namespace shadelab
