// Limits against hostile glTF files (docs/gltf-import.md, "Limits against hostile files"): sizes a model may declare
// before anything is allocated for it, and the geometry it may produce. Plain settings; the defaults suit any real
// teaching model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace shadelab {

struct GltfLimits {
    uint64_t maxFileBytes = uint64_t(2) << 30;       // the .gltf/.glb file itself, bytes
    uint64_t maxBufferBytes = uint64_t(1) << 30;     // one buffer's declared byteLength, bytes
    uint64_t maxDataUriBytes = uint64_t(256) << 20;  // one data: URI, characters
    uint64_t maxImageBytes = uint64_t(64) << 20;     // one image's encoded bytes (PNG/JPEG as stored), from a
                                                     // file, a data: URI or a buffer view alike
    uint64_t maxTextures = 256;                      // images decoded per model; later ones fall back
    uint64_t maxTextureSide = 8192;                  // one image's width or height, texels
    uint64_t maxTexturePixels = uint64_t(1) << 24;   // one image's width × height (4096², 16 Mpixels), from
                                                     // its header before decoding: a 1.5 KB JPEG may claim 8000²
    uint64_t maxTextureBytes = uint64_t(512) << 20;  // decoded texels per model (8-bit RGBA, with mips)
    uint64_t maxTriangles = 16'000'000;              // triangles over every primitive instance, whole scene
    std::string maxTrianglesWhy;                     // what lowered maxTriangles, for the message ("" = the default)
    uint64_t maxMeshBytes = uint64_t(4) << 30;       // vertex and index memory the import may allocate, bytes
};

// Checks what the glTF JSON (a .gltf's text, or a .glb's JSON chunk) declares against `limits`, before
// tinygltf reads any buffer. Throws InputError(file, place, reason). Text that is not valid JSON is left
// for the glTF parser to report. Returns the largest byteLength a buffer declares (0 when none), which
// bounds how much of any external buffer file is read.
uint64_t checkDeclaredSizes(const std::string& bytes, bool binary, const std::string& file, const GltfLimits& limits);

// The JSON chunk of a GLB (glTF 2.0 spec, "Binary glTF Layout"), or empty when the header is malformed.
std::string glbJson(const std::string& bytes);

}  // namespace shadelab
