// checkDeclaredSizes: reads the glTF JSON with nlohmann before tinygltf does, so a file that declares a
// 100 GB buffer or a 2 GB data: URI is refused with one line instead of being allocated.
#include "scene/gltf/gltf_limits.h"

#include "util/input_error.h"

#include <algorithm>
#include <cstring>
#include <nlohmann/json.hpp>

namespace shadelab {
namespace {

std::string place(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

std::string over(const std::string& what, uint64_t size, uint64_t limit) {
    return what + " of " + std::to_string(size) + " bytes exceeds the limit of " + std::to_string(limit) + " bytes";
}

uint64_t declaredLength(const nlohmann::json& j) {
    const auto it = j.find("byteLength");
    return it != j.end() && it->is_number_unsigned() ? it->get<uint64_t>() : 0;
}

void checkDataUri(const nlohmann::json& item, const std::string& file, const std::string& where,
                  const GltfLimits& limits) {
    const auto uri = item.find("uri");
    if (uri == item.end() || !uri->is_string()) return;
    const std::string& s = uri->get_ref<const std::string&>();
    if (s.compare(0, 5, "data:") == 0 && s.size() > limits.maxDataUriBytes)
        throw InputError(file, where, over("data: URI", s.size(), limits.maxDataUriBytes));
}

}  // namespace

std::string glbJson(const std::string& bytes) {
    if (bytes.size() < 20) return {};
    uint32_t chunkLength = 0, chunkType = 0;
    std::memcpy(&chunkLength, bytes.data() + 12, 4);
    std::memcpy(&chunkType, bytes.data() + 16, 4);
    if (chunkType != 0x4E4F534Au || uint64_t(chunkLength) > bytes.size() - 20) return {};
    return bytes.substr(20, chunkLength);
}

uint64_t checkDeclaredSizes(const std::string& bytes, bool binary, const std::string& file, const GltfLimits& limits) {
    if (bytes.size() > limits.maxFileBytes) throw InputError(file, over("file", bytes.size(), limits.maxFileBytes));
    const nlohmann::json doc = nlohmann::json::parse(binary ? glbJson(bytes) : bytes, nullptr, false);
    if (!doc.is_object()) return 0;  // not JSON: tinygltf says why
    uint64_t largest = 0;

    const auto buffers = doc.find("buffers");
    if (buffers != doc.end() && buffers->is_array())
        for (size_t i = 0; i < buffers->size(); ++i) {
            const nlohmann::json& b = (*buffers)[i];
            if (!b.is_object()) continue;
            if (declaredLength(b) > limits.maxBufferBytes)
                throw InputError(file, place("buffers", i),
                                 over("byteLength", declaredLength(b), limits.maxBufferBytes));
            largest = std::max(largest, declaredLength(b));
            checkDataUri(b, file, place("buffers", i), limits);
        }

    const auto images = doc.find("images");
    const auto views = doc.find("bufferViews");
    if (images != doc.end() && images->is_array())
        for (size_t i = 0; i < images->size(); ++i) {
            const nlohmann::json& img = (*images)[i];
            if (!img.is_object()) continue;
            checkDataUri(img, file, place("images", i), limits);
            const auto bv = img.find("bufferView");
            if (bv == img.end() || !bv->is_number_unsigned() || views == doc.end() || !views->is_array()) continue;
            const size_t v = bv->get<size_t>();
            if (v < views->size() && (*views)[v].is_object() && declaredLength((*views)[v]) > limits.maxImageBytes)
                throw InputError(file, place("images", i),
                                 over("texture", declaredLength((*views)[v]), limits.maxImageBytes));
        }
    return largest;
}

}  // namespace shadelab
