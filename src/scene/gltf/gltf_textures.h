// glTF images → shared Textures (texture.h), decoded on first use by a material: PNG or JPEG (stb_image),
// embedded (data URI, buffer view) or external (read by gltf_file.cpp through the model's folder guard and
// util/read_file.h's bound). Every failure — missing, truncated, undecodable, over a limit — is one warning
// line and an empty binding, so the material falls back to its factor. Internal to the glTF importer.
#pragma once

#include "scene/gltf/gltf_limits.h"
#include "scene/texture.h"

#include <functional>
#include <map>
#include <string>
#include <utility>

namespace tinygltf {
class Model;
class Value;
}  // namespace tinygltf

namespace shadelab::gltf {

class TextureLoader {
public:
    using Warn = std::function<void(const std::string&)>;
    // `imageProblems`: images known bad before decoding (gltf_file.h's LoadedModel), by index, with the reason.
    TextureLoader(const tinygltf::Model& model, const std::map<int, std::string>& imageProblems,
                  const GltfLimits& limits, Warn warn)
        : model_(model), imageProblems_(imageProblems), limits_(limits), warn_(std::move(warn)) {}

    // The binding for glTF texture `index` with `texCoord`, decoded from sRGB when `srgb`, with the
    // KHR_texture_transform object `transform` when not null. `place` names the referrer in warnings, e.g.
    // "materials[0].pbrMetallicRoughness.baseColorTexture".
    TextureBinding binding(int index, int texCoord, bool srgb, const std::string& place,
                           const tinygltf::Value* transform = nullptr);

    uint64_t texelBytes() const { return bytes_; }

private:
    std::shared_ptr<const Texture> image(int index, bool srgb, const std::string& place);

    const tinygltf::Model& model_;
    const std::map<int, std::string>& imageProblems_;
    const GltfLimits& limits_;
    Warn warn_;
    std::map<std::pair<int, bool>, std::shared_ptr<const Texture>> decoded_;  // null = failed, warned once
    uint64_t bytes_ = 0;
    uint64_t count_ = 0;
};

// Decodes PNG or JPEG bytes to 8-bit RGBA after checking the header's size against `maxSide`, `maxPixels`
// and the texel budget left (`bytesLeft`, as textureBytesFor counts). Throws std::runtime_error with the
// reason in words (the caller adds the place). Exposed for the hostile-input tests.
std::shared_ptr<const Texture> decodeTexture(const std::string& bytes, const std::string& name, bool srgb,
                                             uint64_t maxSide, uint64_t bytesLeft,
                                             uint64_t maxPixels = GltfLimits{}.maxTexturePixels);

}  // namespace shadelab::gltf
