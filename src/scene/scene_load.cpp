// loadScene: path → ready Scene (.json parsed with meshes imported, or a .gltf/.glb framed and lit), plus
// the bounds, framing camera and default light rig it uses. Parsing and import live elsewhere.
#include "scene/scene_load.h"

#include "scene/environment_load.h"
#include "scene/gltf/gltf_import.h"
#include "scene/scene_json.h"
#include "scene/view.h"
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
constexpr float kFrameMargin = 1.1f;          // 10% room around the box's outline

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
    const glm::vec3 center = 0.5f * (b.lo + b.hi);
    // The camera looks at the box's centre from the front, right and above. Its distance is the least at
    // which every corner of the box lies inside the frustum with kFrameMargin of room, in the narrower of
    // the vertical half-FOV and the 16:9 horizontal one: for a corner at offset o, depth d − o·w must hold
    // margin·|o·r| / tan(halfX) and margin·|o·u| / tan(halfY). A tight fit of the box, not of its bounding
    // sphere, which left long models small in the frame.
    const glm::vec3 w = glm::normalize(glm::vec3(0.3f, 0.35f, 1.0f));  // from the centre toward the eye
    const glm::vec3 r = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), w));
    const glm::vec3 u = glm::cross(w, r);
    const float tanY = tanHalfFov(fovY), tanX = tanY * kFrameAspect;  // as the page's build computes it
    float distance = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
        const glm::vec3 o = corner - center;
        const float depth = glm::dot(o, w);
        distance = std::max({distance, depth + kFrameMargin * std::fabs(glm::dot(o, r)) / tanX,
                             depth + kFrameMargin * std::fabs(glm::dot(o, u)) / tanY});
    }
    // Never inside the box: at least its bounding radius away, so the near plane clips nothing.
    distance = std::max(distance, 0.5f * glm::length(b.hi - b.lo) * 1.05f);
    Camera c;
    c.fovY = fovY;
    c.target = center;
    c.position = center + distance * w;
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

namespace {

// loadScene without the recording of its inputs.
// What importing one triangle holds at its peak: positions, normals, two texture-coordinate sets and tangents
// for up to three vertices, its indices, the parts' copies while a node graph is expanded, and tinygltf's
// buffers. A 12.3-million-triangle node graph peaked at 1.2 GB, about 98 bytes a triangle.
constexpr uint64_t kLoadBytesPerTriangle = 100;

// `gltf` with its triangle limit lowered to what `memory` can hold while the models load, so that a model
// too large for the budget is refused from its accessor counts, before a vertex is read.
GltfImportOptions withinMemory(GltfImportOptions gltf, const MemoryLimit& memory) {
    if (memory.bytes == 0) return gltf;
    const uint64_t fits = memory.bytes / kLoadBytesPerTriangle;
    if (fits < gltf.limits.maxTriangles) {
        gltf.limits.maxTriangles = fits;
        gltf.limits.maxTrianglesWhy = ", the most " + std::to_string(memory.bytes >> 20) + " MiB" +
                                      (memory.name.empty() ? std::string() : " (" + memory.name + ")") +
                                      " can load at about " + std::to_string(kLoadBytesPerTriangle) +
                                      " bytes a triangle";
    }
    return gltf;
}

Scene loadSceneFiles(const std::string& path, WarnFn warn, const GltfImportOptions& unbounded,
                     const MemoryLimit& memory) {
    const GltfImportOptions gltf = withinMemory(unbounded, memory);
    // stat only: nothing is opened before readFile has refused FIFOs and devices.
    if (path.empty()) throw InputError("\"\"", "empty file name");
    std::error_code ec;
    if (path.find('\0') == std::string::npos && !fs::exists(path, ec)) throw InputError(path, "no such file");
    if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, not a scene file");
    const std::string ext = lowerExtension(path);
    if (ext == ".json") {
        Scene scene = parseSceneJson(readFile(path, kMaxSceneFileBytes), path, warn);
        importMeshes(scene, fs::path(path).parent_path().string(), warn, gltf);
        loadEnvironment(scene, fs::path(path).parent_path().string(), {}, memory);
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
    // Framed to fit, as F3D and the glTF Sample Viewer open a model: a file's camera often frames one part or
    // an aspect other than ours. Its cameras stay at hand (camera_choice.h).
    scene.modelCameras = std::move(imported.cameras);
    scene.camera = frameBounds(bounds);
    return scene;
}

}  // namespace

Scene loadScene(const std::string& path, WarnFn warn, const GltfImportOptions& gltf, const MemoryLimit& memory) {
    // Every file read from here on is one of the scene's inputs.
    InputFiles inputs;
    InputRecorder recorder(inputs);
    Scene scene = loadSceneFiles(path, warn, gltf, memory);
    scene.inputs = std::move(inputs);
    return scene;
}

}  // namespace shadelab
