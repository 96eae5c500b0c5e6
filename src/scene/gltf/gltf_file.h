// Reading a .gltf/.glb file or bytes into a tinygltf::Model, defensively: limits, external buffer paths,
// no image decoding. Internal to the glTF importer; callers use gltf_import.h.
#pragma once

#include "scene/gltf/gltf_import.h"

#include <tiny_gltf.h>

#include <map>
#include <string>
#include <vector>

namespace shadelab::gltf {

// A parsed model and what was found wrong with its images before any is decoded.
struct LoadedModel {
    tinygltf::Model model;
    std::map<int, std::string> imageProblems;  // image index -> reason (an undecodable data: URI)
};

// Checks the file, its declared sizes against options.limits, and reads it with buffer files confined to
// the model's folder (unless options.allowExternalPaths). Throws InputError naming the file.
LoadedModel loadModel(const std::string& path, const GltfImportOptions& options, std::vector<std::string>& warnings);

// Parses glTF text (`binary` false) or GLB bytes; with an empty baseDir every external file is refused.
LoadedModel parseModel(const std::string& bytes, bool binary, const std::string& name, const std::string& baseDir,
                       std::vector<std::string>& warnings);

}  // namespace shadelab::gltf
