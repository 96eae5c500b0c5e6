// SceneHandle: scene documents parsed as scene files are, with mesh imports reused across edits.
#include "python/scene_handle.h"

#include "scene/environment_load.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"

#include <filesystem>

namespace shadelab::python {
namespace {

namespace fs = std::filesystem;

// The warning sink of the parse in progress on this thread (scene_json.h reports through a plain function).
thread_local std::vector<std::string>* tWarnings = nullptr;
void collectWarning(const std::string& line) {
    if (tWarnings) tWarnings->push_back(line);
}

struct WarningScope {
    explicit WarningScope(std::vector<std::string>& sink) : previous(tWarnings) { tWarnings = &sink; }
    ~WarningScope() { tWarnings = previous; }
    std::vector<std::string>* previous;
};

bool sameOverride(const MaterialOverride& a, const MaterialOverride& b) {
    return a.ma == b.ma && a.md == b.md && a.ms == b.ms && a.s == b.s && a.kr == b.kr && a.kt == b.kt &&
           a.ior == b.ior && a.baseColor == b.baseColor && a.metallic == b.metallic && a.roughness == b.roughness &&
           a.emission == b.emission && a.model == b.model && a.disney == b.disney && a.clearcoat == b.clearcoat &&
           a.specular == b.specular && a.sheen == b.sheen && a.anisotropy == b.anisotropy &&
           a.transmission == b.transmission && a.volume == b.volume;
}

// As scene_load.cpp resolves a mesh's source.
std::string resolveSource(const std::string& source, const std::string& baseDir) {
    const fs::path p(source);
    return p.is_absolute() || baseDir.empty() ? source : (fs::path(baseDir) / p).string();
}

std::string absoluteDir(const std::string& dir) {
    std::error_code ec;
    fs::path p = fs::absolute(dir.empty() ? fs::path(".") : fs::path(dir), ec);
    return ec ? dir : p.lexically_normal().string();
}

}  // namespace

SceneHandle SceneHandle::load(const std::string& path, bool allowExternalPaths, std::vector<std::string>& warnings,
                              uint64_t maxMemory) {
    WarningScope scope(warnings);
    SceneHandle h;
    h.gltf_.allowExternalPaths = allowExternalPaths;
    h.scene_ = loadScene(path, collectWarning, h.gltf_, MemoryLimit{maxMemory, "max_memory"});
    h.baseDir_ = absoluteDir(fs::path(path).parent_path().string());
    return h;
}

SceneHandle SceneHandle::fromDocument(const nlohmann::json& doc, const std::string& baseDir, bool allowExternalPaths,
                                      std::vector<std::string>& warnings, uint64_t maxMemory) {
    SceneHandle h;
    h.gltf_.allowExternalPaths = allowExternalPaths;
    h.baseDir_ = absoluteDir(baseDir);
    h.scene_ = h.build(doc, warnings, MemoryLimit{maxMemory, "max_memory"});
    return h;
}

bool SceneHandle::replace(const nlohmann::json& doc, std::vector<std::string>& warnings, bool rejectUnknownFields) {
    Scene next = build(doc, warnings);
    if (rejectUnknownFields)
        for (const std::string& line : warnings)
            if (line.find("unknown field '") != std::string::npos) return false;
    scene_ = std::move(next);
    return true;
}

Scene SceneHandle::build(const nlohmann::json& doc, std::vector<std::string>& warnings, const MemoryLimit& memory) {
    const std::string file;  // errors name the JSON path only: the document is no file
    Scene next;
    // The new scene keeps protecting what the handle read before (parts and maps it reuses came from those
    // files) and records what it reads now.
    InputFiles inputs = scene_.inputs;
    InputRecorder recorder(inputs);
    {
        WarningScope scope(warnings);
        next = parseSceneDocument(JsonNode(doc, "", file, collectWarning));
    }
    std::vector<Import> used;
    GltfImportOptions options = gltf_;  // the triangle limit bounds the whole scene, as in scene_load.cpp
    for (size_t i = 0; i < next.meshes.size(); ++i) {
        Mesh& mesh = next.meshes[i];
        const std::string path = resolveSource(mesh.source, baseDir_);
        // Unchanged at the same place: keep the parts (their materials are already overridden).
        if (i < scene_.meshes.size()) {
            const Mesh& old = scene_.meshes[i];
            if (old.source == mesh.source && old.transform == mesh.transform &&
                sameOverride(old.material, mesh.material) && !old.parts.empty()) {
                mesh.parts = old.parts;
                options.trianglesBefore += mesh.triangleCount();
                continue;
            }
        }
        const Import* found = nullptr;
        for (const std::vector<Import>* list : {&used, &imports_})
            for (const Import& imp : *list)
                if (!found && imp.path == path && imp.transform == mesh.transform) found = &imp;
        Import imp;
        if (found) {
            imp = *found;
        } else {
            GltfImport imported = importGltf(path, mesh.transform, options);
            for (const std::string& line : imported.warnings) warnings.push_back(path + ": " + line);
            imp = Import{path, mesh.transform, std::move(imported.parts)};
        }
        mesh.parts = imp.parts;
        if (!mesh.material.empty())
            for (MeshPart& part : mesh.parts) mesh.material.applyTo(part.material);
        options.trianglesBefore += mesh.triangleCount();
        used.push_back(std::move(imp));
    }
    imports_ = std::move(used);
    // The environment's .hdr is read and prefiltered as loadScene does; an unchanged file keeps its map.
    if (next.environment && !next.environment->hdr.empty()) {
        if (scene_.environment && scene_.environment->hdr == next.environment->hdr && scene_.environment->map)
            next.environment->map = scene_.environment->map;
        else
            loadEnvironment(next, baseDir_, {}, memory);
    }
    next.inputs = std::move(inputs);
    return next;
}

}  // namespace shadelab::python
