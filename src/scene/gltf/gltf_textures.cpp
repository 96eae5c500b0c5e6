// glTF textures, images and samplers → TextureBindings (gltf_textures.h).
#include "scene/gltf/gltf_textures.h"

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/gltf_values.h"
#include "util/error_line.h"

#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

namespace shadelab::gltf {
namespace {

bool isPng(const std::string& b) { return b.size() >= 8 && b.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0; }
bool isJpeg(const std::string& b) {
    return b.size() >= 3 && uint8_t(b[0]) == 0xFF && uint8_t(b[1]) == 0xD8 && uint8_t(b[2]) == 0xFF;
}

TextureWrap wrapFrom(int mode, const std::string& place, const TextureLoader::Warn& warn) {
    switch (mode) {
        case 33071: return TextureWrap::ClampToEdge;
        case 33648: return TextureWrap::MirroredRepeat;
        case 10497:
        case -1: return TextureWrap::Repeat;
        default:
            warn(place + ": unknown wrap mode " + std::to_string(mode) + "; using REPEAT");
            return TextureWrap::Repeat;
    }
}

// glTF min filters: 9728 NEAREST, 9729 LINEAR, 9984..9987 the mipmapped ones (NEAREST/LINEAR within a
// level × NEAREST/LINEAR between levels); unset is LINEAR_MIPMAP_LINEAR.
TextureSampler samplerFrom(const tinygltf::Sampler& s, const std::string& place, const TextureLoader::Warn& warn) {
    TextureSampler out;
    out.wrapS = wrapFrom(s.wrapS, place + ".wrapS", warn);
    out.wrapT = wrapFrom(s.wrapT, place + ".wrapT", warn);
    out.magLinear = s.magFilter != 9728;
    switch (s.minFilter) {
        case 9728: out.minLinear = false, out.mipmaps = false; break;
        case 9729: out.minLinear = true, out.mipmaps = false; break;
        case 9984: out.minLinear = false, out.mipLinear = false; break;
        case 9985: out.mipLinear = false; break;
        case 9986: out.minLinear = false; break;
        default: break;  // 9987 and unset: trilinear
    }
    return out;
}

// Refuses an image by its header's size: a side over `maxSide`, more than `maxPixels` texels, or more texel
// bytes than the budget left.
void checkSize(uint64_t w, uint64_t h, uint64_t maxSide, uint64_t maxPixels, uint64_t bytesLeft) {
    if (w == 0 || h == 0) throw std::runtime_error("image has no pixels");
    if (w > maxSide || h > maxSide)
        throw std::runtime_error("image is " + std::to_string(w) + "x" + std::to_string(h) + ", over the limit of " +
                                 std::to_string(maxSide) + " texels a side");
    if (w * h > maxPixels)  // both at most 2^32 - 1: no overflow
        throw std::runtime_error("image is " + std::to_string(w) + "x" + std::to_string(h) + " = " +
                                 std::to_string(w * h) + " pixels, over the limit of " + std::to_string(maxPixels) +
                                 " pixels");
    const uint64_t need = textureBytesFor(int(std::min<uint64_t>(w, INT32_MAX)), int(std::min<uint64_t>(h, INT32_MAX)));
    if (need > bytesLeft)
        throw std::runtime_error("image needs " + std::to_string(need) + " bytes of texels, over the " +
                                 std::to_string(bytesLeft) + " left of the model's texture budget");
}

struct StbFree {
    void operator()(unsigned char* p) const { stbi_image_free(p); }
};

}  // namespace

std::shared_ptr<const Texture> decodeTexture(const std::string& bytes, const std::string& name, bool srgb,
                                             uint64_t maxSide, uint64_t bytesLeft, uint64_t maxPixels) {
    if (bytes.empty()) throw std::runtime_error("image has no bytes");
    if (!isPng(bytes) && !isJpeg(bytes)) throw std::runtime_error("not a PNG or JPEG image");
    if (bytes.size() > size_t(INT32_MAX)) throw std::runtime_error("image too large to decode");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = int(bytes.size());
    int w = 0, h = 0, comp = 0;
    if (isPng(bytes)) {
        // The size from IHDR ourselves: stb_image refuses a huge PNG with only "unknown image type".
        if (bytes.size() < 24 || bytes.compare(12, 4, "IHDR") != 0) throw std::runtime_error("PNG without IHDR");
        auto u32 = [&](size_t at) {
            return uint32_t(uint8_t(bytes[at])) << 24 | uint32_t(uint8_t(bytes[at + 1])) << 16 |
                   uint32_t(uint8_t(bytes[at + 2])) << 8 | uint32_t(uint8_t(bytes[at + 3]));
        };
        checkSize(u32(16), u32(20), maxSide, maxPixels, bytesLeft);
    }
    if (!stbi_info_from_memory(data, length, &w, &h, &comp))
        throw std::runtime_error(std::string("cannot read the image header (") + stbi_failure_reason() + ")");
    // Every image, PNG or JPEG, from a file, a data: URI or a buffer view: its header's size against the
    // limits before a texel is decoded (stb_image would allocate for whatever the header claims).
    checkSize(uint64_t(std::max(w, 0)), uint64_t(std::max(h, 0)), maxSide, maxPixels, bytesLeft);
    int w2 = 0, h2 = 0;
    std::unique_ptr<unsigned char, StbFree> pixels(stbi_load_from_memory(data, length, &w2, &h2, &comp, 4));
    if (!pixels) throw std::runtime_error(std::string("cannot decode the image (") + stbi_failure_reason() + ")");
    if (w2 != w || h2 != h) throw std::runtime_error("image size changed while decoding");
    return makeTexture(name, pixels.get(), w, h, srgb);
}

TextureBinding TextureLoader::binding(int index, int texCoord, bool srgb, const std::string& place,
                                      const tinygltf::Value* transform) {
    TextureBinding b;
    if (index < 0) return b;
    if (transform) {
        // KHR_texture_transform: offset [0, 0], rotation 0, scale [1, 1], texCoord overriding the info's.
        const std::string where = place + ".extensions.KHR_texture_transform";
        auto pair = [&](const char* key, glm::vec2 fallback) {
            const std::vector<double> v = numbersOf(*transform, key);
            if (v.empty()) return fallback;
            const std::optional<float> x = v.size() == 2 ? finiteFloat(v[0]) : std::nullopt;
            const std::optional<float> y = v.size() == 2 ? finiteFloat(v[1]) : std::nullopt;
            if (!x || !y) {
                warn_(where + "." + key + " must be two finite numbers; ignored");
                return fallback;
            }
            return glm::vec2(*x, *y);
        };
        b.offset = pair("offset", glm::vec2(0.0f));
        b.scale = pair("scale", glm::vec2(1.0f));
        if (const std::optional<float> rotation = finiteFloat(numberOr(*transform, "rotation", 0.0)))
            b.rotation = *rotation;
        else
            warn_(where + ".rotation is not finite; ignored");
        const double coord = numberOr(*transform, "texCoord", double(texCoord));
        if (const std::optional<int> n = wholeNumber(coord, 0, 1 << 30))
            texCoord = *n;
        else
            texCoord = -1;  // refused below, with the other sets that are not imported
    }
    if (size_t(index) >= model_.textures.size()) {
        warn_(place + ": texture " + std::to_string(index) + " out of range (" +
              std::to_string(model_.textures.size()) + " textures); using the factor alone");
        return b;
    }
    if (texCoord != 0 && texCoord != 1) {
        warn_(place +
              (texCoord < 0 ? ": texCoord is not a whole number >= 0"
                            : ": TEXCOORD_" + std::to_string(texCoord) + " is not imported (only 0 and 1)") +
              "; using the factor alone");
        return b;
    }
    const tinygltf::Texture& t = model_.textures[size_t(index)];
    const std::string texPlace = "textures[" + std::to_string(index) + "]";
    if (t.source < 0 || size_t(t.source) >= model_.images.size()) {
        warn_(texPlace + ": image " + std::to_string(t.source) + " out of range (" +
              std::to_string(model_.images.size()) + " images); using the factor alone");
        return b;
    }
    b.texture = image(t.source, srgb, place);
    if (!b.texture) return b;
    if (t.sampler >= 0 && size_t(t.sampler) < model_.samplers.size())
        b.sampler =
            samplerFrom(model_.samplers[size_t(t.sampler)], "samplers[" + std::to_string(t.sampler) + "]", warn_);
    else if (t.sampler >= 0)
        warn_(texPlace + ": sampler " + std::to_string(t.sampler) + " out of range; using the default sampler");
    b.texCoord = texCoord;
    return b;
}

std::shared_ptr<const Texture> TextureLoader::image(int index, bool srgb, const std::string& place) {
    const auto key = std::make_pair(index, srgb);
    const auto found = decoded_.find(key);
    if (found != decoded_.end()) return found->second;
    std::shared_ptr<const Texture>& slot = decoded_[key];
    const tinygltf::Image& img = model_.images[size_t(index)];
    const std::string imgPlace = "images[" + std::to_string(index) + "]";
    const std::string name = !img.name.empty()                                    ? img.name
                             : !img.uri.empty() && img.uri.rfind("data:", 0) != 0 ? img.uri
                                                                                  : imgPlace;
    try {
        if (count_ >= limits_.maxTextures)
            throw std::runtime_error("over the limit of " + std::to_string(limits_.maxTextures) +
                                     " textures per model");
        const auto problem = imageProblems_.find(index);
        if (problem != imageProblems_.end()) throw std::runtime_error(problem->second);
        std::string bytes;
        if (img.bufferView >= 0) {
            bytes = bufferViewBytes(model_, img.bufferView, "", "");
        } else if (!img.image.empty()) {
            bytes.assign(img.image.begin(), img.image.end());
        } else if (!img.uri.empty()) {
            throw std::runtime_error(escapeForMessage("cannot read \"" + img.uri +
                                                      "\" (missing, outside the model's folder, or too large)"));
        }
        // One bound on the encoded bytes wherever they come from: an external file's is also bounded as it is
        // read (gltf_file.cpp), but a data: URI or a buffer view would otherwise skip it.
        if (bytes.size() > limits_.maxImageBytes)
            throw std::runtime_error("image of " + std::to_string(bytes.size()) + " bytes exceeds the limit of " +
                                     std::to_string(limits_.maxImageBytes) + " bytes");
        slot = decodeTexture(bytes, name, srgb, limits_.maxTextureSide, limits_.maxTextureBytes - bytes_,
                             limits_.maxTexturePixels);
        bytes_ += slot->texelBytes();
        ++count_;
    } catch (const std::exception& e) {
        warn_(imgPlace + " (used by " + place + "): " + e.what() + "; using the factor alone");
        slot = nullptr;
    }
    return slot;
}

}  // namespace shadelab::gltf
