// Texture construction: sRGB decode of 8-bit texels, then the mip chain (texture.h).
#include "scene/texture.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace shadelab {
namespace {

// IEC 61966-2-1, as image/encode.cpp's srgbToLinear; a table, since every texel goes through it.
const std::array<float, 256>& srgbTable() {
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

// The source indices that fold into destination index d along an axis of `src` texels: 2d and 2d+1, plus
// 2d+2 for the last destination texel of an odd size.
int spanOf(int d, int src, int dst) { return (d == dst - 1 && src > 2 * dst) ? 3 : std::min(2, src - 2 * d); }

TextureLevel halve(const TextureLevel& a) {
    TextureLevel b;
    b.width = std::max(1, a.width / 2);
    b.height = std::max(1, a.height / 2);
    b.texels.resize(size_t(b.width) * size_t(b.height));
    for (int y = 0; y < b.height; ++y) {
        const int y0 = a.height == 1 ? 0 : 2 * y, ny = a.height == 1 ? 1 : spanOf(y, a.height, b.height);
        for (int x = 0; x < b.width; ++x) {
            const int x0 = a.width == 1 ? 0 : 2 * x, nx = a.width == 1 ? 1 : spanOf(x, a.width, b.width);
            glm::vec4 sum(0.0f);
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) sum += a.texels[size_t(y0 + j) * size_t(a.width) + size_t(x0 + i)];
            b.texels[size_t(y) * size_t(b.width) + size_t(x)] = sum / float(nx * ny);
        }
    }
    return b;
}

}  // namespace

size_t Texture::texelBytes() const {
    size_t n = 0;
    for (const TextureLevel& l : levels) n += l.texels.size() * sizeof(glm::vec4);
    return n;
}

uint64_t textureBytesFor(int width, int height) {
    uint64_t n = 0;
    uint64_t w = uint64_t(std::max(width, 1)), h = uint64_t(std::max(height, 1));
    for (;;) {
        n += w * h * sizeof(glm::vec4);
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
    base.texels.resize(size_t(width) * size_t(height));
    const std::array<float, 256>& table = srgbTable();
    for (size_t i = 0; i < base.texels.size(); ++i) {
        const uint8_t* p = rgba + 4 * i;
        if (srgb)
            base.texels[i] = glm::vec4(table[p[0]], table[p[1]], table[p[2]], p[3] / 255.0f);
        else
            base.texels[i] = glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
    }
    tex->levels.push_back(std::move(base));
    while (tex->levels.back().width > 1 || tex->levels.back().height > 1)
        tex->levels.push_back(halve(tex->levels.back()));
    return tex;
}

}  // namespace shadelab
