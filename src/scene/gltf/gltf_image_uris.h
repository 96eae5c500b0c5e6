// Images whose data: URI tinygltf cannot decode at all (no base64 at the start of its data). tinygltf fails
// the whole load on such an image, where shadelab treats any bad image as a warning and the material's factor
// (docs/gltf-import.md): this finds them and gives back the model with each one's URI replaced by a
// placeholder, so the load goes on and the texture loader reports the image with the reason. Internal to the
// glTF importer (gltf_file.cpp).
#pragma once

#include <map>
#include <string>

namespace shadelab::gltf {

struct ImageUriRepair {
    std::string bytes;                    // the model again (glTF text or GLB), with the placeholders
    std::map<int, std::string> problems;  // image index -> why its data: URI was replaced, in words
};

// The repaired model, or an empty `problems` (and `bytes`) when no image's data: URI is undecodable or the
// JSON does not parse (tinygltf then says why). `binary`: GLB bytes, else glTF text.
ImageUriRepair replaceUndecodableImageUris(const std::string& bytes, bool binary);

// Whether tinygltf's load error is the one an undecodable image data: URI gives ("Failed to decode 'uri' for
// image[i] ..."): only then is the repair worth a second parse.
bool isUndecodableImageUriError(const std::string& err);

}  // namespace shadelab::gltf
