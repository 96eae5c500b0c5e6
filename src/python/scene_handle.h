// SceneHandle: the Scene behind a Python shadelab.Scene, with the folder its mesh sources are relative to. Every
// edit replaces the whole description by a new document parsed exactly as a scene file is (scene_json.h: same
// schema, name tables and messages), while meshes whose source, transform and material are unchanged keep their
// imported geometry. Pure C++: the bindings (bind_scene.cpp) convert Python values to documents (py_json.h).
#pragma once

#include "scene/environment_load.h"
#include "scene/gltf/gltf_import.h"
#include "scene/scene.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace shadelab::python {

class SceneHandle {
public:
    // loadScene(): a .json scene file, or a .gltf / .glb model framed and lit. Warnings are appended to `warnings`.
    // maxMemory (bytes; 0: none) holds the environment map's load to it (scene/environment_load.h), as
    // render(max_memory=...) names it.
    static SceneHandle load(const std::string& path, bool allowExternalPaths, std::vector<std::string>& warnings,
                            uint64_t maxMemory = 0);
    // A document in the scene file's schema; mesh sources are relative to `baseDir`. Errors name the JSON path
    // (InputError with no file: "lights[2].color: expected 3 numbers, got 2"). maxMemory as for load().
    static SceneHandle fromDocument(const nlohmann::json& doc, const std::string& baseDir, bool allowExternalPaths,
                                    std::vector<std::string>& warnings, uint64_t maxMemory = 0);

    // Replaces the scene by `doc`. On an InputError the scene is left as it was; so it is, returning false, when
    // `rejectUnknownFields` and the reader warned about an unknown field (an attribute edit with a misspelt name).
    bool replace(const nlohmann::json& doc, std::vector<std::string>& warnings, bool rejectUnknownFields = false);

    const Scene& scene() const { return scene_; }
    const std::string& baseDir() const { return baseDir_; }
    bool allowExternalPaths() const { return gltf_.allowExternalPaths; }

private:
    // A glTF file as importGltf returned it, before the scene's material override: kept so that an edit of a
    // mesh's override or a new copy of the same mesh re-reads nothing.
    struct Import {
        std::string path;
        glm::mat4 transform{1.0f};
        std::vector<MeshPart> parts;
    };
    // Parses `doc` and fills its meshes' parts from the current scene, the imports or the files, and its
    // environment map, held to `memory`.
    Scene build(const nlohmann::json& doc, std::vector<std::string>& warnings, const MemoryLimit& memory = {});

    Scene scene_;
    std::string baseDir_;  // absolute
    GltfImportOptions gltf_;
    std::vector<Import> imports_;  // of the meshes the current scene names
};

}  // namespace shadelab::python
