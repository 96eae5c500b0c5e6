// replaceUndecodableImageUris: the images tinygltf's data: URI decoder refuses, found as tinygltf finds them,
// and the document written back with a placeholder in their place.
#include "scene/gltf/gltf_image_uris.h"

#include "scene/gltf/gltf_limits.h"
#include "util/error_line.h"

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>

namespace shadelab::gltf {
namespace {

// The data: URI prefixes tinygltf decodes (tinygltf::IsDataURI); any other "data:" URI it takes for a file
// name, which fails softly (a missing image).
constexpr const char* kDataUriPrefixes[] = {"data:application/octet-stream;base64,",
                                            "data:image/jpeg;base64,",
                                            "data:image/png;base64,",
                                            "data:image/bmp;base64,",
                                            "data:image/gif;base64,",
                                            "data:text/plain;base64,",
                                            "data:application/gltf-buffer;base64,"};

// One byte of base64 ("AA=="): tinygltf decodes it; the texture loader refuses the image by its problem
// before looking at the byte.
constexpr const char* kPlaceholder = "data:application/octet-stream;base64,AA==";

bool isBase64Char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
}

// Why tinygltf cannot decode `uri`, or empty when it can (or it is no data: URI tinygltf knows). tinygltf's
// base64 decoder stops at the first '=' or character outside the alphabet, and fails when that leaves
// fewer than two characters: no byte.
std::string undecodable(const std::string& uri) {
    for (const char* prefix : kDataUriPrefixes) {
        const size_t n = std::strlen(prefix);
        if (uri.compare(0, n, prefix) != 0) continue;
        size_t valid = 0;
        while (n + valid < uri.size() && isBase64Char(uri[n + valid])) ++valid;
        if (valid >= 2) return {};
        if (uri.size() == n) return "its data: URI holds no data";
        const std::string start = uri.substr(n, 12);
        return escapeForMessage("its data: URI is not base64 (the data begins \"" + start +
                                (uri.size() > n + 12 ? "...\")" : "\")"));
    }
    return {};
}

void putU32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xFF);  // little-endian, as GLB is
}

// A GLB with its JSON chunk replaced by `json` (padded with spaces to 4 bytes, glTF 2.0 "Binary glTF Layout")
// and every later chunk kept as it was.
std::string withJsonChunk(const std::string& glb, std::string json) {
    uint32_t oldLength = 0;
    std::memcpy(&oldLength, glb.data() + 12, 4);
    while (json.size() % 4 != 0) json += ' ';
    const std::string rest = glb.substr(20 + size_t(oldLength));
    std::string out = glb.substr(0, 8);  // magic, version
    putU32(out, uint32_t(12 + 8 + json.size() + rest.size()));
    putU32(out, uint32_t(json.size()));
    putU32(out, 0x4E4F534Au);  // "JSON"
    return out + json + rest;
}

}  // namespace

bool isUndecodableImageUriError(const std::string& err) {
    return err.find("Failed to decode 'uri' for image[") != std::string::npos;
}

ImageUriRepair replaceUndecodableImageUris(const std::string& bytes, bool binary) {
    ImageUriRepair repair;
    const std::string text = binary ? glbJson(bytes) : bytes;
    nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
    if (!doc.is_object()) return repair;
    const auto images = doc.find("images");
    if (images == doc.end() || !images->is_array()) return repair;
    for (size_t i = 0; i < images->size(); ++i) {
        nlohmann::json& image = (*images)[i];
        if (!image.is_object()) continue;
        const auto uri = image.find("uri");
        if (uri == image.end() || !uri->is_string()) continue;
        std::string why = undecodable(uri->get_ref<const std::string&>());
        if (why.empty()) continue;
        repair.problems[int(i)] = std::move(why);
        *uri = kPlaceholder;
    }
    if (repair.problems.empty()) return repair;
    // The strings came from a parse, so they are valid UTF-8 and dump() cannot throw on them.
    std::string json = doc.dump();
    repair.bytes = binary ? withJsonChunk(bytes, std::move(json)) : std::move(json);
    return repair;
}

}  // namespace shadelab::gltf
