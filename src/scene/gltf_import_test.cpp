// Tests for glTF import (gltf_import.h) and scene loading (scene_load.h): real Khronos and glTF Asset
// Generator files from Debian's assimp-testmodels, broken files, and tiny glTFs written by the tests.
#include "scene/gltf_import.h"
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

namespace shadelab {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

#define REQUIRE_MODELS()                                                                                   \
    do {                                                                                                   \
        if (!fs::exists(kModels / "glTF2"))                                                                \
            GTEST_SKIP() << kModels << " is missing; install Debian's assimp-testmodels package";          \
    } while (0)

std::string model(const std::string& relative) { return (kModels / relative).string(); }

std::string readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

size_t triangleCount(const GltfImport& g) {
    size_t n = 0;
    for (const MeshPart& p : g.parts) n += p.triangleCount();
    return n;
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

bool anyWarningContains(const GltfImport& g, const std::string& needle) {
    return std::any_of(g.warnings.begin(), g.warnings.end(), [&](const std::string& w) { return contains(w, needle); });
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol) << "x";
    EXPECT_NEAR(a.y, b.y, tol) << "y";
    EXPECT_NEAR(a.z, b.z, tol) << "z";
}

// Every part is well formed: one unit, finite normal per position, indices in range, whole triangles.
void expectWellFormed(const GltfImport& g) {
    for (const MeshPart& p : g.parts) {
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

std::string base64(const std::string& bytes) {
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
void appendBytes(std::string& bytes, const std::vector<T>& values) {
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
TinyMesh quad() {
    TinyMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

// Writes a glTF whose one buffer is embedded as a data: URI and whose mesh 0 is `mesh`. `nodes` is the JSON
// array of nodes, `roots` the default scene's node list, `extra` further top-level members (",\"x\": ...").
std::string writeGltf(const std::string& name, const TinyMesh& mesh, const std::string& nodes,
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
        add(data, "{\"bufferView\":" + std::to_string(next) + ",\"componentType\":5126,\"count\":" +
                      std::to_string(v.size()) + ",\"type\":\"VEC3\"}");
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
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":" + roots + "}],\"nodes\":" + nodes +
        ",\"meshes\":[{\"primitives\":[{\"attributes\":{" + attributes + "}" + indices +
        ",\"mode\":" + std::to_string(mesh.mode) + "}]}],\"buffers\":[{\"byteLength\":" +
        std::to_string(bytes.size()) + ",\"uri\":\"data:application/octet-stream;base64," + base64(bytes) +
        "\"}],\"bufferViews\":[" + views + "],\"accessors\":[" + accessors + "]" + extra + "}";
    const fs::path dir = fs::path(SHADELAB_TEST_OUTPUT_DIR);
    fs::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << json;
    return path;
}

// A triangle's geometric normal from its winding (counter-clockwise = front).
glm::vec3 faceNormal(const MeshPart& p, size_t t) {
    const glm::vec3& a = p.positions[p.indices[3 * t]];
    const glm::vec3& b = p.positions[p.indices[3 * t + 1]];
    const glm::vec3& c = p.positions[p.indices[3 * t + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

// ---- Real files: triangle counts ----------------------------------------------------------------------------

TEST(GltfImport, BoxTexturedVariantsHaveTwelveTriangles) {
    REQUIRE_MODELS();
    for (const char* path : {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                             "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        SCOPED_TRACE(path);
        const GltfImport g = importGltf(model(path));
        EXPECT_EQ(triangleCount(g), 12u);
        ASSERT_EQ(g.parts.size(), 1u);
        EXPECT_EQ(g.parts[0].positions.size(), 24u);  // accessor count of POSITION
        expectWellFormed(g);
    }
}

TEST(GltfImport, TwoCylinderEngine) {
    REQUIRE_MODELS();
    const GltfImport g = importGltf(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    // Sum over the mesh instances of the default scene of indices.count / 3 (derived from the GLB's JSON).
    EXPECT_EQ(triangleCount(g), 121496u);
    expectWellFormed(g);
}

// glTF Asset Generator Mesh_PrimitiveMode (see its README): one primitive over 4 vertices, or 6 for the
// non-indexed triangle list. Strips and fans of n vertices give n - 2 triangles; lists give count / 3.
TEST(GltfImport, AssetGeneratorPrimitiveModes) {
    REQUIRE_MODELS();
    struct Case {
        int index;
        size_t triangles;
    };
    const Case cases[] = {
        {0, 0}, {1, 0}, {2, 0},  {3, 0},  {4, 2},  {5, 2},  {6, 2},  {7, 0},   // points and lines: skipped
        {8, 0}, {9, 0}, {10, 0}, {11, 2}, {12, 2}, {13, 2}, {14, 2}, {15, 2},  // 14: UNSIGNED_BYTE, 15: SHORT
    };
    for (const Case& c : cases) {
        char name[128];
        std::snprintf(name, sizeof name, "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_%02d.gltf",
                      c.index);
        SCOPED_TRACE(name);
        const GltfImport g = importGltf(model(name));
        EXPECT_EQ(triangleCount(g), c.triangles);
        if (c.triangles == 0) {
            EXPECT_TRUE(anyWarningContains(g, "skipped"));
        }
        expectWellFormed(g);
        // The README's figure: a unit square in z = 0 facing +z; no normals given, so they are generated.
        for (const MeshPart& p : g.parts) {
            for (const glm::vec3& n : p.normals) expectNear(n, {0, 0, 1});
            for (size_t t = 0; t < p.triangleCount(); ++t) expectNear(faceNormal(p, t), {0, 0, 1});
        }
    }
}

// IncorrectVertexArrays/Cube.gltf: 36-vertex cubes, 35-vertex truncated ones and lines. Lists keep
// floor(count / 3) triangles: 12 + 11 (non-indexed) + 12 + 11 (indexed); the four line meshes are skipped.
TEST(GltfImport, TruncatedArraysKeepWholeTriangles) {
    REQUIRE_MODELS();
    const GltfImport g = importGltf(model("glTF2/IncorrectVertexArrays/Cube.gltf"));
    EXPECT_EQ(triangleCount(g), 46u);
    EXPECT_EQ(g.parts.size(), 4u);
    EXPECT_TRUE(anyWarningContains(g, "trailing indices"));
    expectWellFormed(g);
}

TEST(GltfImport, BadNormalsAreReplaced) {
    REQUIRE_MODELS();
    const GltfImport g = importGltf(model("glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb"));
    EXPECT_EQ(triangleCount(g), 12u);
    EXPECT_TRUE(anyWarningContains(g, "normals replaced"));
    expectWellFormed(g);
}

TEST(GltfImport, MaterialsFollowTheMapping) {
    REQUIRE_MODELS();
    // BoxBadNormals' one material: baseColorFactor (0.8, 0, 0), metallic 0, roughness 1.
    const GltfImport g = importGltf(model("glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb"));
    ASSERT_EQ(g.parts.size(), 1u);
    const Material& m = g.parts[0].material;
    expectNear(m.md, {0.8f, 0, 0});
    expectNear(m.ms, glm::vec3(0.04f));
    EXPECT_FLOAT_EQ(m.s, 1.0f);
}

// ---- Broken files: an InputError naming the file, or a clean import; never a crash -------------------------

TEST(GltfImport, BrokenFilesThrowInputErrorOrImport) {
    REQUIRE_MODELS();
    struct Case {
        const char* path;
        const char* expected;  // substring of the InputError, or null when the file imports
    };
    const Case cases[] = {
        {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "out of range"},
        {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "out of range"},
        {"glTF2/MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
        {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "node hierarchy has a cycle"},
        {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "accessors[2]: non-finite value"},
        {"glTF2/SchemaFailures/sceneWrongType.gltf", "BoxTextured0.bin"},
        {"glTF2/TestNoRootNode/NoScene.gltf", nullptr},
        {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", nullptr},
        {"glTF2/draco/2CylinderEngine.gltf", "bufferView"},
        {"glTF2/wrongTypes/badArray.gltf", nullptr},
        {"glTF2/wrongTypes/badExtension.gltf", nullptr},
        {"glTF2/wrongTypes/badNumber.gltf", nullptr},
        {"glTF2/wrongTypes/badObject.gltf", nullptr},
        {"glTF2/wrongTypes/badString.gltf", nullptr},
        {"glTF2/wrongTypes/badUint.gltf", nullptr},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.path);
        const std::string path = model(c.path);
        if (!fs::exists(path)) continue;
        try {
            const GltfImport g = importGltf(path);
            EXPECT_EQ(c.expected, nullptr) << "imported; expected an error containing " << c.expected;
            expectWellFormed(g);
        } catch (const InputError& e) {
            EXPECT_TRUE(contains(e.what(), path)) << e.what();
            if (c.expected) {
                EXPECT_TRUE(contains(e.what(), c.expected)) << e.what();
            } else {
                ADD_FAILURE() << "unexpected error: " << e.what();
            }
        }
    }
}

TEST(GltfImport, IndexOutOfRangeNamesTheAccessor) {
    REQUIRE_MODELS();
    const std::string path = model("glTF2/IndexOutOfRange/IndexOutOfRange.gltf");
    try {
        importGltf(path);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": accessors[0]: index ", 0), 0u) << e.what();
    }
}

TEST(GltfImport, MissingFileAndWrongExtension) {
    EXPECT_THROW(importGltf("/no/such/model.glb"), InputError);
    const fs::path dir(SHADELAB_TEST_OUTPUT_DIR);
    fs::create_directories(dir);
    std::ofstream(dir / "model.obj") << "v 0 0 0\n";
    EXPECT_THROW(importGltf((dir / "model.obj").string()), InputError);
    std::ofstream(dir / "garbage.glb") << "not a glb";
    EXPECT_THROW(importGltf((dir / "garbage.glb").string()), InputError);
}

// A truncated buffer: the POSITION accessor claims more vertices than its buffer view holds.
TEST(GltfImport, AccessorPastItsBufferViewIsAnError) {
    const std::string path = writeGltf("overrun.gltf", quad(), "[{\"mesh\":0}]");
    std::ifstream in(path);
    std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "\"count\":4,\"type\":\"VEC3\"";
    json.replace(json.find(from), from.size(), "\"count\":5,\"type\":\"VEC3\"");
    std::ofstream(path) << json;
    try {
        importGltf(path);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "accessors[0]: 5 elements of 12 bytes")) << e.what();
    }
}

// ---- Normals ---------------------------------------------------------------------------------------------

TEST(GltfImport, GeneratedNormalsOfAFlatQuadAreTheFaceNormal) {
    const GltfImport g = importGltf(writeGltf("quad.gltf", quad(), "[{\"mesh\":0}]"));
    ASSERT_EQ(g.parts.size(), 1u);
    EXPECT_EQ(g.parts[0].triangleCount(), 2u);
    for (const glm::vec3& n : g.parts[0].normals) expectNear(n, {0, 0, 1});
}

// Area weighting: a vertex shared by a big triangle facing +z and a small one facing +x leans to +z.
TEST(GltfImport, GeneratedNormalsAreAreaWeighted) {
    TinyMesh m;
    m.positions = {{0, 0, 0}, {0, 4, 0}, {-4, 0, 0}, {0, 0, -1}};
    m.indices = {0, 1, 2, 0, 3, 1};  // areas 8 (normal +z) and 2 (normal +x)
    const GltfImport g = importGltf(writeGltf("weighted.gltf", m, "[{\"mesh\":0}]"));
    ASSERT_EQ(g.parts.size(), 1u);
    const glm::vec3 expected = glm::normalize(glm::vec3(2 * 2, 0, 2 * 8));
    expectNear(g.parts[0].normals[0], expected);
    expectNear(g.parts[0].normals[2], {0, 0, 1});
}

TEST(GltfImport, GivenNormalsUseTheInverseTranspose) {
    // A 45-degree slope y = x under scale (2, 1, 1): the normal (-1, 1, 0)/sqrt2 becomes (-1, 2, 0)/sqrt5.
    TinyMesh m;
    m.positions = {{0, 0, 0}, {1, 1, 1}, {1, 1, 0}};
    m.normals.assign(3, glm::normalize(glm::vec3(-1, 1, 0)));
    m.indices = {0, 1, 2};
    const GltfImport g = importGltf(writeGltf("slope.gltf", m, "[{\"mesh\":0,\"scale\":[2,1,1]}]"));
    ASSERT_EQ(g.parts.size(), 1u);
    for (const glm::vec3& n : g.parts[0].normals) expectNear(n, glm::normalize(glm::vec3(-1, 2, 0)));
    // It is perpendicular to the transformed surface.
    const MeshPart& p = g.parts[0];
    EXPECT_NEAR(glm::dot(p.normals[0], p.positions[1] - p.positions[0]), 0.0f, 1e-5f);
}

// ---- Node transforms ---------------------------------------------------------------------------------------

TEST(GltfImport, TranslationRotationScaleAndParents) {
    // Parent: translate (1, 2, 3). Child: rotate 90 degrees about +y, then scale 2.
    const float h = std::sqrt(0.5f);
    const std::string nodes = "[{\"children\":[1],\"translation\":[1,2,3]},"
                              "{\"mesh\":0,\"rotation\":[0," + std::to_string(h) + ",0," + std::to_string(h) +
                              "],\"scale\":[2,2,2]}]";
    const GltfImport g = importGltf(writeGltf("trs.gltf", quad(), nodes));
    ASSERT_EQ(g.parts.size(), 1u);
    const MeshPart& p = g.parts[0];
    // Ry(90) sends +x to -z and +z to +x; (1,0,0) → scale (2,0,0) → rotate (0,0,-2) → translate (1,2,1).
    expectNear(p.positions[0], {1, 2, 3});
    expectNear(p.positions[1], {1, 2, 1});
    expectNear(p.positions[2], {1, 4, 1});
    for (const glm::vec3& n : p.normals) expectNear(n, {1, 0, 0});
}

TEST(GltfImport, MatrixNodeAndImportTransform) {
    // Column-major: rotate 90 degrees about +z ((x, y) → (-y, x)), translate (5, 0, 0).
    const std::string nodes = "[{\"mesh\":0,\"matrix\":[0,1,0,0, -1,0,0,0, 0,0,1,0, 5,0,0,1]}]";
    const std::string path = writeGltf("matrix.gltf", quad(), nodes);
    const GltfImport g = importGltf(path);
    ASSERT_EQ(g.parts.size(), 1u);
    expectNear(g.parts[0].positions[1], {5, 1, 0});
    expectNear(g.parts[0].positions[2], {4, 1, 0});

    // The import transform applies on top: move everything up by 10.
    glm::mat4 up(1.0f);
    up[3] = glm::vec4(0, 10, 0, 1);
    const GltfImport lifted = importGltf(path, up);
    expectNear(lifted.parts[0].positions[2], {4, 11, 0});
}

TEST(GltfImport, NegativeScaleFlipsWinding) {
    TinyMesh m = quad();
    for (bool withNormals : {false, true}) {
        SCOPED_TRACE(withNormals ? "given normals" : "generated normals");
        m.normals.assign(withNormals ? 4 : 0, glm::vec3(0, 0, 1));
        const GltfImport g = importGltf(writeGltf("mirror.gltf", m, "[{\"mesh\":0,\"scale\":[-1,1,1]}]"));
        ASSERT_EQ(g.parts.size(), 1u);
        const MeshPart& p = g.parts[0];
        expectNear(p.positions[1], {-1, 0, 0});
        // Mirroring in x keeps the normal +z; the winding is swapped so the front face still agrees with it.
        for (size_t t = 0; t < p.triangleCount(); ++t) expectNear(faceNormal(p, t), {0, 0, 1});
        for (const glm::vec3& n : p.normals) expectNear(n, {0, 0, 1});
    }
}

TEST(GltfImport, StripAndFanWinding) {
    for (int mode : {5, 6}) {
        SCOPED_TRACE(mode == 5 ? "strip" : "fan");
        TinyMesh m;
        m.mode = mode;
        // Strip 0,1,3,2 and fan 0,1,2,3 both cover the unit quad counter-clockwise.
        m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        m.indices = mode == 5 ? std::vector<uint32_t>{0, 1, 3, 2} : std::vector<uint32_t>{0, 1, 2, 3};
        const GltfImport g = importGltf(writeGltf("strip.gltf", m, "[{\"mesh\":0}]"));
        ASSERT_EQ(g.parts.size(), 1u);
        ASSERT_EQ(g.parts[0].triangleCount(), 2u);
        for (size_t t = 0; t < 2; ++t) expectNear(faceNormal(g.parts[0], t), {0, 0, 1});
    }
}

TEST(GltfImport, CycleIsAnError) {
    const std::string nodes = "[{\"mesh\":0,\"children\":[1]},{\"children\":[2]},{\"children\":[1]}]";
    try {
        importGltf(writeGltf("cycle.gltf", quad(), nodes));
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "nodes[1]: node hierarchy has a cycle")) << e.what();
    }
}

// ---- Materials ---------------------------------------------------------------------------------------------

TEST(PhongFromMetallicRoughness, HandComputedValues) {
    // Dielectric, roughness 0.5: alpha = 0.25, s = 2 / 0.0625 - 2 = 30.
    Material m = phongFromMetallicRoughness({0.8f, 0.2f, 0.1f}, 0.0f, 0.5f);
    expectNear(m.md, {0.8f, 0.2f, 0.1f});
    expectNear(m.ma, {0.8f, 0.2f, 0.1f});
    expectNear(m.ms, glm::vec3(0.04f));
    EXPECT_NEAR(m.s, 30.0f, 1e-3f);
    expectNear(m.kr, glm::vec3(0.0f));
    expectNear(m.kt, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(m.ior, 1.5f);

    // Metal, roughness 0.25: no diffuse, tinted specular; alpha = 1/16, s = 2 * 256 - 2 = 510.
    m = phongFromMetallicRoughness({1.0f, 0.8f, 0.2f}, 1.0f, 0.25f);
    expectNear(m.md, glm::vec3(0.0f));
    expectNear(m.ms, {1.0f, 0.8f, 0.2f});
    EXPECT_NEAR(m.s, 510.0f, 1e-2f);

    // Half metal, grey 0.5, roughness 1: md = 0.25, ms = (0.04 + 0.5) / 2 = 0.27, s = 0 clamped to 1.
    m = phongFromMetallicRoughness(glm::vec3(0.5f), 0.5f, 1.0f);
    expectNear(m.md, glm::vec3(0.25f));
    expectNear(m.ms, glm::vec3(0.27f));
    EXPECT_FLOAT_EQ(m.s, 1.0f);

    // Mirror-smooth: the exponent clamps to the contract's maximum instead of dividing by zero.
    EXPECT_FLOAT_EQ(phongFromMetallicRoughness(glm::vec3(1.0f), 0.0f, 0.0f).s, kMaxShininess);
}

TEST(GltfImport, DefaultMaterialAndIorExtension) {
    // No material: shadelab's default Material (grey plastic), so an untextured model shows every term.
    GltfImport g = importGltf(writeGltf("nomaterial.gltf", quad(), "[{\"mesh\":0}]"));
    ASSERT_EQ(g.parts.size(), 1u);
    expectNear(g.parts[0].material.md, Material{}.md);
    expectNear(g.parts[0].material.ms, Material{}.ms);
    EXPECT_FLOAT_EQ(g.parts[0].material.s, Material{}.s);

    std::string path = writeGltf("ior.gltf", quad(), "[{\"mesh\":0}]", "[0]",
                                 ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.2,0.4,0.6,1],"
                                 "\"metallicFactor\":0,\"roughnessFactor\":0.5},"
                                 "\"extensions\":{\"KHR_materials_ior\":{\"ior\":1.33}}}]");
    std::ifstream in(path);
    std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    json.replace(json.find("\"mode\":4"), 8, "\"mode\":4,\"material\":0");
    std::ofstream(path) << json;
    g = importGltf(path);
    ASSERT_EQ(g.parts.size(), 1u);
    expectNear(g.parts[0].material.md, {0.2f, 0.4f, 0.6f});
    EXPECT_NEAR(g.parts[0].material.s, 30.0f, 1e-3f);
    EXPECT_FLOAT_EQ(g.parts[0].material.ior, 1.33f);
}

// ---- Lights and cameras ---------------------------------------------------------------------------------------

TEST(GltfImport, PunctualLightsAndCamera) {
    const float h = std::sqrt(0.5f);
    // Node 1: point light at (1, 2, 3). Node 2: directional light rotated -90 degrees about x, so its -z
    // points down. Node 3: camera at (0, 1, 5) looking down -z.
    const std::string nodes =
        "[{\"mesh\":0},"
        "{\"translation\":[1,2,3],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
        "{\"rotation\":[" + std::to_string(-h) + ",0,0," + std::to_string(h) +
        "],\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}},"
        "{\"translation\":[0,1,5],\"camera\":0}]";
    const std::string extra =
        ",\"extensionsUsed\":[\"KHR_lights_punctual\"],"
        "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":["
        "{\"type\":\"point\",\"name\":\"bulb\",\"color\":[1,0.5,0.25],\"intensity\":100},"
        "{\"type\":\"directional\",\"name\":\"sun\",\"intensity\":50}]}},"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}]";
    const GltfImport g = importGltf(writeGltf("lights.gltf", quad(), nodes, "[0,1,2,3]", extra));

    ASSERT_EQ(g.lights.size(), 2u);
    EXPECT_EQ(g.lights[0].name, "bulb");
    EXPECT_EQ(g.lights[0].type, LightType::Point);
    expectNear(g.lights[0].position, {1, 2, 3});
    expectNear(g.lights[0].color, {1, 0.5f, 0.25f});  // the brightest light keeps its colour
    EXPECT_EQ(g.lights[1].type, LightType::Directional);
    expectNear(g.lights[1].direction, {0, -1, 0});
    expectNear(g.lights[1].color, glm::vec3(0.5f));  // half the brightest intensity

    ASSERT_TRUE(g.camera.has_value());
    expectNear(g.camera->position, {0, 1, 5});
    expectNear(g.camera->target, {0, 1, 4});
    expectNear(g.camera->up, {0, 1, 0});
    EXPECT_NEAR(g.camera->fovY, glm::degrees(0.8f), 1e-4f);
}

// ---- Scene loading ---------------------------------------------------------------------------------------------

// Every corner of `b` lies in front of `c` and inside its frustum at the given aspect.
void expectFramed(const Camera& c, const Bounds& b, float aspect) {
    const glm::vec3 f = glm::normalize(c.target - c.position);
    const glm::vec3 r = glm::normalize(glm::cross(f, c.up));
    const glm::vec3 u = glm::cross(r, f);
    const float tanY = std::tan(glm::radians(c.fovY) / 2);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
        const glm::vec3 d = corner - c.position;
        const float z = glm::dot(d, f);
        ASSERT_GT(z, 0.0f);
        EXPECT_LE(std::abs(glm::dot(d, u)) / z, tanY) << "corner " << i;
        EXPECT_LE(std::abs(glm::dot(d, r)) / z, tanY * aspect) << "corner " << i;
    }
}

TEST(SceneLoad, GlbIsFramedAndLit) {
    REQUIRE_MODELS();
    // BoxTextured.glb has no camera and no lights, so both come from its bounds.
    const std::string path = model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
    const Scene s = loadScene(path);
    EXPECT_EQ(s.title, "BoxTextured.glb");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].name, "BoxTextured");
    EXPECT_EQ(s.meshes[0].source, path);
    EXPECT_EQ(s.meshes[0].triangleCount(), 12u);
    EXPECT_TRUE(s.planes.empty());
    EXPECT_TRUE(s.spheres.empty());
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);

    const Bounds b = sceneBounds(s);
    ASSERT_FALSE(b.empty());
    expectFramed(s.camera, b, 16.0f / 9.0f);
    expectFramed(s.camera, b, 1.0f);
    // Seen from the front (+z) and above; key light above the model.
    EXPECT_GT(s.camera.position.z, b.hi.z);
    EXPECT_GT(s.camera.position.y, b.hi.y);
    EXPECT_GT(s.lights[0].position.y, b.hi.y);
}

TEST(SceneLoad, GlbKeepsItsOwnCameraAndLights) {
    REQUIRE_MODELS();
    // 2CylinderEngine.glb has a perspective camera (yfov 0.3143463730812073) and no lights.
    Scene s = loadScene(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    EXPECT_EQ(s.meshes[0].triangleCount(), 121496u);
    EXPECT_NEAR(s.camera.fovY, glm::degrees(0.3143463730812073f), 1e-4f);
    EXPECT_EQ(s.lights.size(), 2u);

    const std::string nodes = "[{\"mesh\":0},{\"translation\":[0,3,0],"
                              "\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}]";
    const std::string extra = ",\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\"}]}}";
    s = loadScene(writeGltf("lit.gltf", quad(), nodes, "[0,1]", extra));
    ASSERT_EQ(s.lights.size(), 1u);
    expectNear(s.lights[0].position, {0, 3, 0});
    expectNear(s.lights[0].color, glm::vec3(1.0f));
}

TEST(SceneLoad, ErrorsNameTheFile) {
    const fs::path dir(SHADELAB_TEST_OUTPUT_DIR);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.txt") << "hello";
    try {
        loadScene((dir / "scene.txt").string());
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "unknown scene type")) << e.what();
    }
    try {
        loadScene("/no/such/scene.json");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "/no/such/scene.json: no such file");
    }
}

TEST(SceneLoad, ImportSceneMeshesAppliesTransformAndOverride) {
    writeGltf("scene_quad.gltf", quad(), "[{\"mesh\":0}]");
    Scene s;
    Mesh m;
    m.source = "scene_quad.gltf";
    m.transform[3] = glm::vec4(0, 0, 7, 1);
    m.material.md = glm::vec3(0.1f, 0.2f, 0.3f);
    s.meshes.push_back(m);
    importSceneMeshes(s, SHADELAB_TEST_OUTPUT_DIR);
    ASSERT_EQ(s.meshes[0].parts.size(), 1u);
    expectNear(s.meshes[0].parts[0].positions[2], {1, 1, 7});
    expectNear(s.meshes[0].parts[0].material.md, {0.1f, 0.2f, 0.3f});
    expectNear(s.meshes[0].parts[0].material.ms, Material{}.ms);  // not overridden: the default material's

    s.meshes[0].source = "missing.glb";
    EXPECT_THROW(importSceneMeshes(s, SHADELAB_TEST_OUTPUT_DIR), InputError);
}

TEST(SceneLoad, BoundsFramingAndRig) {
    Bounds empty;
    EXPECT_TRUE(empty.empty());
    const Camera fallback = frameBounds(empty);
    expectNear(fallback.position, Camera{}.position);

    Scene s;
    s.spheres.push_back({"a", {0, 0, 0}, 1.0f, {}});
    s.spheres.push_back({"b", {10, 0, 0}, 2.0f, {}});
    s.planes.push_back({});  // unbounded; ignored
    const Bounds b = sceneBounds(s);
    expectNear(b.lo, {-1, -2, -2});
    expectNear(b.hi, {12, 2, 2});
    for (float fov : {20.0f, 45.0f, 90.0f}) {
        SCOPED_TRACE(fov);
        const Camera c = frameBounds(b, fov);
        EXPECT_FLOAT_EQ(c.fovY, fov);
        expectNear(c.target, {5.5f, 0, 0});
        expectFramed(c, b, 16.0f / 9.0f);
    }
    const std::vector<Light> rig = defaultLightRig(b);
    ASSERT_EQ(rig.size(), 2u);
    EXPECT_GT(rig[0].color.r, rig[0].color.b);  // warm key
    EXPECT_LT(rig[1].color.r, rig[1].color.b);  // cool fill
    EXPECT_GT(glm::length(rig[0].color), glm::length(rig[1].color));
}

// 2CylinderEngine.glb (121,496 triangles) imports whole. Its speed is measured by bench/, not here.
TEST(GltfImport, TwoCylinderEngineImportsWhole) {
    REQUIRE_MODELS();
    const GltfImport g = importGltf(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    EXPECT_EQ(triangleCount(g), 121496u);
}

// Buffer URIs that leave the model's folder (../ or absolute) are refused unless allowed (issue 6).
TEST(GltfImport, ExternalPathsRefusedUnlessAllowed) {
    REQUIRE_MODELS();
    const std::filesystem::path root = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "external";
    std::filesystem::create_directories(root / "model");
    std::filesystem::create_directories(root / "elsewhere");
    const std::string bin = (root / "elsewhere" / "box.bin").string();
    std::filesystem::copy_file(model("glTF2/BoxTextured-glTF/BoxTextured0.bin"), bin,
                               std::filesystem::copy_options::overwrite_existing);
    std::ifstream in(model("glTF2/BoxTextured-glTF/BoxTextured.gltf"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_NE(text.find("\"BoxTextured0.bin\""), std::string::npos);
    for (const std::string& uri : {std::string("../elsewhere/box.bin"), bin}) {
        std::string t = text;
        t.replace(t.find("\"BoxTextured0.bin\""), 18, "\"" + uri + "\"");
        const std::string path = (root / "model" / "box.gltf").string();
        std::ofstream(path) << t;
        try {
            importGltf(path);
            ADD_FAILURE() << uri << " was read without --allow-external-paths";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("outside the model's folder"), std::string::npos) << e.what();
        }
        GltfImportOptions allow;
        allow.allowExternalPaths = true;
        EXPECT_EQ(triangleCount(importGltf(path, glm::mat4(1.0f), allow)), 12u) << uri;
    }
    // The same buffer beside the model is inside its folder and loads by default.
    std::filesystem::copy_file(bin, root / "model" / "BoxTextured0.bin", std::filesystem::copy_options::overwrite_existing);
    std::ofstream((root / "model" / "inside.gltf").string()) << text;
    EXPECT_EQ(triangleCount(importGltf((root / "model" / "inside.gltf").string())), 12u);
}

// Limits against hostile files (issue 6): each gives a one-line InputError before anything big is allocated.
TEST(GltfImport, LimitsRefuseHostileFiles) {
    auto expectRefused = [](const std::string& text, const GltfLimits& limits, const std::string& needle) {
        try {
            importGltfBytes(text, false, "hostile.gltf", limits);
            ADD_FAILURE() << "accepted; expected an error containing '" << needle << "'";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("hostile.gltf"), std::string::npos) << e.what();
        }
    };
    const std::string asset = R"("asset":{"version":"2.0"})";
    // A buffer that claims 100 GB: refused from its declaration alone.
    expectRefused("{" + asset + R"(,"buffers":[{"byteLength":100000000000,"uri":"x.bin"}]})", GltfLimits{},
                  "buffers[0]: byteLength of 100000000000 bytes exceeds the limit");
    GltfLimits small;
    small.maxDataUriBytes = 64;
    expectRefused("{" + asset + R"(,"buffers":[{"byteLength":48,"uri":"data:application/octet-stream;base64,)" +
                      std::string(64, 'A') + R"("}]})",
                  small, "buffers[0]: data: URI of");
    GltfLimits tinyImages;
    tinyImages.maxImageBytes = 10;
    expectRefused("{" + asset + R"(,"bufferViews":[{"buffer":0,"byteLength":1000}],"images":[{"bufferView":0,"mimeType":"image/png"}]})",
                  tinyImages, "images[0]: texture of 1000 bytes");
    // Triangles: the quad below has 2; a limit of 1 refuses it, the default accepts it (negative control).
    const std::string quadText = readTextFile(writeGltf("limits_quad.gltf", quad(), "[{\"mesh\":0}]"));
    GltfLimits oneTriangle;
    oneTriangle.maxTriangles = 1;
    expectRefused(quadText, oneTriangle, "exceeds the limit of 1 triangles");
    GltfLimits fewBytes;
    fewBytes.maxMeshBytes = 16;
    expectRefused(quadText, fewBytes, "bytes of geometry");
    EXPECT_EQ(triangleCount(importGltfBytes(quadText, false, "quad.gltf")), 2u);
}

}  // namespace
}  // namespace shadelab
