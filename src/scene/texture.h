// Texture: one decoded glTF image as shared, immutable scene data (design.md §9), with its sampler and the
// binding a material holds. Texels are stored as 8-bit RGBA, as the image gives them: colour images (base
// colour, emissive) keep their sRGB-encoded RGB, data images (metallic-roughness, normal, occlusion) and
// every alpha are linear. Both renderers decode a texel to the same linear floats before filtering (GL:
// GL_SRGB8_ALPHA8 / GL_RGBA8 with texelFetch; the tracer: shading/texel_decode.h's tables). The mip chain is
// built here once, averaged in linear light and re-encoded to 8 bits, so the rasterizer uploads exactly the
// levels the tracer samples (shaders/texture_sample.glsl ≡ src/shading/texture_sample.h).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

namespace shadelab {

// glTF sampler wrap modes (the GL enum values glTF stores).
enum class TextureWrap : int { Repeat = 10497, MirroredRepeat = 33648, ClampToEdge = 33071 };

struct TextureSampler {
    TextureWrap wrapS = TextureWrap::Repeat;  // glTF's defaults
    TextureWrap wrapT = TextureWrap::Repeat;
    bool magLinear = true;  // magnification: bilinear (true) or nearest
    bool minLinear = true;  // minification within a level: bilinear (true) or nearest
    bool mipmaps = true;    // minification reads the mip chain; false = level 0 only
    bool mipLinear = true;  // between levels: blend the two nearest (true) or take the nearest one
};

inline constexpr size_t kTexelBytes = 4;  // stored bytes per texel: RGBA, 8 bits each

struct TextureLevel {
    int width = 0, height = 0;
    std::vector<uint8_t> texels;  // RGBA bytes, row-major, row 0 = the image's top row (glTF's v = 0)
};

struct Texture {
    std::string name;                  // the image's name or URI, for messages and the viewer
    bool srgb = false;                 // RGB are sRGB-encoded (colour maps); else linear. Alpha is always linear.
    std::vector<TextureLevel> levels;  // levels[0] is the image; each next level halves (floor, min 1)

    int width() const { return levels.empty() ? 0 : levels[0].width; }
    int height() const { return levels.empty() ? 0 : levels[0].height; }
    size_t texelBytes() const;  // every level, as stored
    // The linear value texel (x, y) of `level` decodes to, as both renderers read it.
    glm::vec4 texel(size_t level, int x, int y) const;
};

// The 8-bit code of linear value `linear` (clamped to [0, 1]): sRGB-encoded when `srgb`, else linear; rounded
// half up in the encoded space, as image/encode.h's encodeChannel does.
uint8_t encodeTexelChannel(float linear, bool srgb);

// What a material holds for one of its maps; an empty binding (no texture) means "the factor alone".
struct TextureBinding {
    std::shared_ptr<const Texture> texture;
    TextureSampler sampler;
    int texCoord = 0;       // TEXCOORD_n: 0 or 1 (the info's texCoord, or KHR_texture_transform's override)
    float strength = 1.0f;  // normalTexture.scale or occlusionTexture.strength; 1 for the other maps
    // KHR_texture_transform: uv' = T(offset) · R(rotation) · S(scale) · uv, rotation in radians.
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;
    glm::vec2 scale{1.0f};

    explicit operator bool() const { return texture != nullptr; }
    // The linear part R · S as texture_sample.glsl's texTransform takes it: (m.x, m.y) the first row,
    // (m.z, m.w) the second. cos and sin are taken here, once, so both renderers use the same numbers.
    glm::vec4 uvMatrix() const {
        const float c = std::cos(rotation), s = std::sin(rotation);
        return {c * scale.x, s * scale.y, -s * scale.x, c * scale.y};
    }
};

// Builds a texture from 8-bit RGBA pixels (4 bytes per texel, row-major, top row first; sRGB-encoded RGB
// when `srgb`), kept as level 0, then the mip chain: each level a 2×2 box filter of the previous level's
// unrounded linear values (an odd size's last row or column is folded into its neighbour's average, so
// every level's mean equals the image's mean up to rounding), stored re-encoded to 8 bits.
std::shared_ptr<const Texture> makeTexture(std::string name, const uint8_t* rgba, int width, int height, bool srgb);

// The texel memory a width × height image takes once decoded, with its mip chain, 8-bit RGBA (the limits
// count this).
uint64_t textureBytesFor(int width, int height);

}  // namespace shadelab
