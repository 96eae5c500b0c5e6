// loadScene: path → ready Scene (.json parsed with meshes imported, or a .gltf/.glb framed and lit), plus
// the bounds, framing camera and default light rig it uses. Parsing and import live elsewhere.
#include "scene/scene_load.h"

#include "scene/environment_load.h"
#include "scene/gltf_import.h"
#include "scene/scene_json.h"
#include "util/input_error.h"
#include "util/read_file.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace shadelab {
namespace {

namespace fs = std::filesystem;
using WarnFn = void (*)(const std::string& line);

constexpr float kFrameAspect = 16.0f / 9.0f;  // widest image the framing must fit
constexpr float kFrameMargin = 1.1f;          // 10% room around the bounding sphere

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

void forwardWarnings(const std::vector<std::string>& lines, const std::string& file, WarnFn warn) {
    if (!warn) return;
    for (const std::string& line : lines) warn(file + ": " + line);
}

// Centre and radius of the sphere around `b`; an empty box gives the unit sphere at the origin.
void boundingSphere(const Bounds& b, glm::vec3& center, float& radius) {
    if (b.empty()) {
        center = glm::vec3(0.0f);
        radius = 1.0f;
        return;
    }
    center = 0.5f * (b.lo + b.hi);
    radius = 0.5f * glm::length(b.hi - b.lo);
    if (!(radius > 0.0f)) radius = 1.0f;  // a single point: give it a size to look at
}

void importMeshes(Scene& scene, const std::string& baseDir, WarnFn warn, const GltfImportOptions& gltf) {
    GltfImportOptions options = gltf;  // the triangle limit bounds the whole scene
    for (Mesh& mesh : scene.meshes) {
        const fs::path source(mesh.source);
        const std::string path =
            source.is_absolute() || baseDir.empty() ? mesh.source : (fs::path(baseDir) / source).string();
        GltfImport imported = importGltf(path, mesh.transform, options);
        for (const MeshPart& part : imported.parts) options.trianglesBefore += part.triangleCount();
        forwardWarnings(imported.warnings, path, warn);
        if (!mesh.material.empty())
            for (MeshPart& part : imported.parts) mesh.material.applyTo(part.material);
        mesh.parts = std::move(imported.parts);
    }
}

}  // namespace

Bounds sceneBounds(const Scene& scene) {
    Bounds b;
    for (const Sphere& s : scene.spheres) {
        b.extend(s.center - glm::vec3(s.radius));
        b.extend(s.center + glm::vec3(s.radius));
    }
    for (const Mesh& mesh : scene.meshes)
        for (const MeshPart& part : mesh.parts)
            if (part.geometry) b.extend(part.geometry->bounds);
    return b;
}

Camera frameBounds(const Bounds& b, float fovY) {
    if (b.empty()) return Camera{};
    glm::vec3 center;
    float radius;
    boundingSphere(b, center, radius);
    // A sphere of radius r seen from distance d fills a half-angle asin(r/d); fit it in the narrower of the
    // vertical half-FOV and the 16:9 horizontal one (which is never narrower for aspect >= 1).
    const float halfY = 0.5f * glm::radians(fovY);
    const float halfX = std::atan(std::tan(halfY) * kFrameAspect);
    const float distance = kFrameMargin * radius / std::sin(std::min(halfX, halfY));
    Camera c;
    c.fovY = fovY;
    c.target = center;
    c.position = center + distance * glm::normalize(glm::vec3(0.3f, 0.35f, 1.0f));  // front, right, above
    c.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return c;
}

std::vector<Light> defaultLightRig(const Bounds& b) {
    glm::vec3 center;
    float radius;
    boundingSphere(b, center, radius);
    // Classic two-point lighting: a warm key above-left-front, a dimmer cool fill on the right.
    Light key;
    key.name = "key";
    key.position = center + radius * glm::vec3(-2.5f, 3.0f, 3.5f);
    key.color = glm::vec3(0.8f, 0.76f, 0.68f);  // leaves headroom for white materials plus ambient and fill
    Light fill;
    fill.name = "fill";
    fill.position = center + radius * glm::vec3(3.5f, 1.0f, 1.5f);
    fill.color = glm::vec3(0.25f, 0.29f, 0.36f);
    return {key, fill};
}

void importSceneMeshes(Scene& scene, const std::string& baseDir, const GltfImportOptions& gltf) {
    importMeshes(scene, baseDir, nullptr, gltf);
}

Scene loadScene(const std::string& path, WarnFn warn, const GltfImportOptions& gltf) {
    // stat only: nothing is opened before readFile has refused FIFOs and devices.
    if (path.empty()) throw InputError("\"\"", "empty file name");
    std::error_code ec;
    if (path.find('\0') == std::string::npos && !fs::exists(path, ec)) throw InputError(path, "no such file");
    if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, not a scene file");
    const std::string ext = lowerExtension(path);
    if (ext == ".json") {
        Scene scene = parseSceneJson(readFile(path, kMaxSceneFileBytes), path, warn);
        importMeshes(scene, fs::path(path).parent_path().string(), warn, gltf);
        loadEnvironment(scene, fs::path(path).parent_path().string());
        return scene;
    }
    if (ext != ".gltf" && ext != ".glb") throw InputError(path, "unknown scene type; expected .json, .gltf or .glb");

    GltfImport imported = importGltf(path, glm::mat4(1.0f), gltf);
    forwardWarnings(imported.warnings, path, warn);
    Scene scene;
    scene.title = fs::path(path).filename().string();
    // A bare model gets the lecture's local terms. Its file holds no term choices, and shadows cast by a
    // heuristic light rig would be arbitrary; a scene file or --terms switches shadows and reflections on.
    scene.terms.shadows = false;
    scene.terms.reflections = false;
    Mesh mesh;
    mesh.name = fs::path(path).stem().string();
    mesh.source = fs::absolute(path, ec).lexically_normal().string();  // so a saved scene finds it anywhere
    if (ec) mesh.source = path;
    mesh.parts = std::move(imported.parts);
    scene.meshes.push_back(std::move(mesh));

    const Bounds bounds = sceneBounds(scene);
    scene.lights = imported.lights.empty() ? defaultLightRig(bounds) : std::move(imported.lights);
    if (scene.lights.size() > size_t(kMaxLights)) {
        if (warn)
            warn(path + ": " + std::to_string(scene.lights.size()) + " lights; keeping the first " +
                 std::to_string(kMaxLights));
        scene.lights.resize(size_t(kMaxLights));
    }
    scene.camera = imported.camera ? *imported.camera : frameBounds(bounds);
    return scene;
}

}  // namespace shadelab
