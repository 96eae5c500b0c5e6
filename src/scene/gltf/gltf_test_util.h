// Helpers shared by the glTF import tests: the assimp-testmodels folder, tiny glTF files written by the
// tests themselves (embedded data: buffers), and checks every imported part must pass.
#pragma once

#include "scene/gltf/gltf_import.h"
#include "scene/scene_load.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace shadelab::gltftest {

inline const std::filesystem::path kModels = "/usr/share/assimp/models";

#define REQUIRE_MODELS()                                                                          \
    do {                                                                                          \
        if (!std::filesystem::exists(kModels / "glTF2"))                                          \
            GTEST_SKIP() << kModels << " is missing; install Debian's assimp-testmodels package"; \
    } while (0)

inline std::string model(const std::string& relative) { return (kModels / relative).string(); }

inline std::string readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline size_t triangleCount(const GltfImport& g) {
    size_t n = 0;
    for (const MeshPart& p : g.parts) n += p.triangleCount();
    return n;
}

inline bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

inline bool anyWarningContains(const GltfImport& g, const std::string& needle) {
    return std::any_of(g.warnings.begin(), g.warnings.end(), [&](const std::string& w) { return contains(w, needle); });
}

inline void expectNear(const glm::vec3& a, const glm::vec3& b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol) << "x";
    EXPECT_NEAR(a.y, b.y, tol) << "y";
    EXPECT_NEAR(a.z, b.z, tol) << "z";
}

// Every part is well formed: one unit, finite normal per position, indices in range, whole triangles.
inline void expectWellFormed(const GltfImport& g) {
    for (const MeshPart& part : g.parts) {
        const MeshGeometry& p = *part.geometry;
        ASSERT_EQ(p.normals.size(), p.positions.size());
        ASSERT_EQ(p.indices.size() % 3, 0u);
        for (uint32_t i : p.indices) ASSERT_LT(i, p.positions.size());
        for (const glm::vec3& n : p.normals) {
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
            ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
        }
        for (const glm::vec3& v : p.positions)
            ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    }
}

// ---- Writing tiny glTF files -----------------------------------------------------------------------------

inline std::string base64(const std::string& bytes) {
    static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 2]));
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
    }
    return out;
}

template <class T>
inline void appendBytes(std::string& bytes, const std::vector<T>& values) {
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// One primitive's data for writeGltf. Empty normals or indices leave that attribute out.
struct TinyMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<uint32_t> indices;
    int mode = 4;
};

// A unit quad in the z = 0 plane, counter-clockwise seen from +z: two triangles sharing an edge.
inline TinyMesh quad() {
    TinyMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

// Writes a glTF whose one buffer is embedded as a data: URI and whose mesh 0 is `mesh`. `nodes` is the JSON
// array of nodes, `roots` the default scene's node list, `extra` further top-level members (",\"x\": ...").
inline std::string writeGltf(const std::string& name, const TinyMesh& mesh, const std::string& nodes,
                             const std::string& roots = "[0]", const std::string& extra = "") {
    std::string bytes, views, accessors, attributes;
    auto add = [&](const std::string& data, const std::string& accessor) {
        if (!views.empty()) {
            views += ",";
            accessors += ",";
        }
        views += "{\"buffer\":0,\"byteOffset\":" + std::to_string(bytes.size()) +
                 ",\"byteLength\":" + std::to_string(data.size()) + "}";
        accessors += accessor;
        bytes += data;
    };
    int next = 0;
    auto vec3s = [&](const std::vector<glm::vec3>& v, const char* semantic) {
        std::string data;
        appendBytes(data, v);
        add(data, "{\"bufferView\":" + std::to_string(next) +
                      ",\"componentType\":5126,\"count\":" + std::to_string(v.size()) + ",\"type\":\"VEC3\"}");
        attributes += std::string(attributes.empty() ? "" : ",") + "\"" + semantic + "\":" + std::to_string(next++);
    };
    vec3s(mesh.positions, "POSITION");
    if (!mesh.normals.empty()) vec3s(mesh.normals, "NORMAL");
    std::string indices;
    if (!mesh.indices.empty()) {
        std::string data;
        appendBytes(data, mesh.indices);
        add(data, "{\"bufferView\":" + std::to_string(next) + ",\"componentType\":5125,\"count\":" +
                      std::to_string(mesh.indices.size()) + ",\"type\":\"SCALAR\"}");
        indices = ",\"indices\":" + std::to_string(next++);
    }
    const std::string json = "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":" + roots +
                             "}],\"nodes\":" + nodes + ",\"meshes\":[{\"primitives\":[{\"attributes\":{" + attributes +
                             "}" + indices + ",\"mode\":" + std::to_string(mesh.mode) +
                             "}]}],\"buffers\":[{\"byteLength\":" + std::to_string(bytes.size()) +
                             ",\"uri\":\"data:application/octet-stream;base64," + base64(bytes) +
                             "\"}],\"bufferViews\":[" + views + "],\"accessors\":[" + accessors + "]" + extra + "}";
    const std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << json;
    return path;
}

// A triangle's geometric normal from its winding (counter-clockwise = front).
inline glm::vec3 faceNormal(const MeshGeometry& p, size_t t) {
    const glm::vec3& a = p.positions[p.indices[3 * t]];
    const glm::vec3& b = p.positions[p.indices[3 * t + 1]];
    const glm::vec3& c = p.positions[p.indices[3 * t + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}
inline glm::vec3 faceNormal(const MeshPart& p, size_t t) { return faceNormal(*p.geometry, t); }

// ---- Real files: triangle counts ----------------------------------------------------------------------------

}  // namespace shadelab::gltftest
