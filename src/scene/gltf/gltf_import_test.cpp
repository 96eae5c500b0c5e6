// Tests for glTF import (gltf_import.h) and scene loading (scene_load.h): real Khronos and glTF Asset
// Generator files from Debian's assimp-testmodels, broken files, and tiny glTFs written by the tests.
#include "scene/gltf/gltf_test_util.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace shadelab {
namespace {

using namespace gltftest;
namespace fs = std::filesystem;
TEST(GltfImport, BoxTexturedVariantsHaveTwelveTriangles) {
    REQUIRE_MODELS();
    for (const char* path : {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                             "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        SCOPED_TRACE(path);
        const GltfImport g = importGltf(model(path));
        EXPECT_EQ(triangleCount(g), 12u);
        ASSERT_EQ(g.parts.size(), 1u);
        EXPECT_EQ(g.parts[0].geometry->positions.size(), 24u);  // accessor count of POSITION
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
            for (const glm::vec3& n : p.geometry->normals) expectNear(n, {0, 0, 1});
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
    // The pbr model reads the glTF values themselves.
    expectNear(m.baseColor, {0.8f, 0, 0});
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_EQ(m.roughness, 1.0f);
}

// ---- Broken files: an InputError naming the file, or a clean import; never a crash -------------------------

// A truncated buffer: the POSITION accessor claims more vertices than its buffer view holds.
TEST(GltfImport, GeneratedNormalsOfAFlatQuadAreTheFaceNormal) {
    const GltfImport g = importGltf(writeGltf("quad.gltf", quad(), "[{\"mesh\":0}]"));
    ASSERT_EQ(g.parts.size(), 1u);
    EXPECT_EQ(g.parts[0].triangleCount(), 2u);
    for (const glm::vec3& n : g.parts[0].geometry->normals) expectNear(n, {0, 0, 1});
}

// Area weighting: a vertex shared by a big triangle facing +z and a small one facing +x leans to +z.
TEST(GltfImport, GeneratedNormalsAreAreaWeighted) {
    TinyMesh m;
    m.positions = {{0, 0, 0}, {0, 4, 0}, {-4, 0, 0}, {0, 0, -1}};
    m.indices = {0, 1, 2, 0, 3, 1};  // areas 8 (normal +z) and 2 (normal +x)
    const GltfImport g = importGltf(writeGltf("weighted.gltf", m, "[{\"mesh\":0}]"));
    ASSERT_EQ(g.parts.size(), 1u);
    const glm::vec3 expected = glm::normalize(glm::vec3(2 * 2, 0, 2 * 8));
    expectNear(g.parts[0].geometry->normals[0], expected);
    expectNear(g.parts[0].geometry->normals[2], {0, 0, 1});
}

TEST(GltfImport, GivenNormalsUseTheInverseTranspose) {
    // A 45-degree slope y = x under scale (2, 1, 1): the normal (-1, 1, 0)/sqrt2 becomes (-1, 2, 0)/sqrt5.
    TinyMesh m;
    m.positions = {{0, 0, 0}, {1, 1, 1}, {1, 1, 0}};
    m.normals.assign(3, glm::normalize(glm::vec3(-1, 1, 0)));
    m.indices = {0, 1, 2};
    const GltfImport g = importGltf(writeGltf("slope.gltf", m, "[{\"mesh\":0,\"scale\":[2,1,1]}]"));
    ASSERT_EQ(g.parts.size(), 1u);
    for (const glm::vec3& n : g.parts[0].geometry->normals) expectNear(n, glm::normalize(glm::vec3(-1, 2, 0)));
    // It is perpendicular to the transformed surface.
    const MeshGeometry& p = *g.parts[0].geometry;
    EXPECT_NEAR(glm::dot(p.normals[0], p.positions[1] - p.positions[0]), 0.0f, 1e-5f);
}

// ---- Node transforms ---------------------------------------------------------------------------------------

TEST(GltfImport, TranslationRotationScaleAndParents) {
    // Parent: translate (1, 2, 3). Child: rotate 90 degrees about +y, then scale 2.
    const float h = std::sqrt(0.5f);
    const std::string nodes =
        "[{\"children\":[1],\"translation\":[1,2,3]},"
        "{\"mesh\":0,\"rotation\":[0," +
        std::to_string(h) + ",0," + std::to_string(h) + "],\"scale\":[2,2,2]}]";
    const GltfImport g = importGltf(writeGltf("trs.gltf", quad(), nodes));
    ASSERT_EQ(g.parts.size(), 1u);
    const MeshGeometry& p = *g.parts[0].geometry;
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
    expectNear(g.parts[0].geometry->positions[1], {5, 1, 0});
    expectNear(g.parts[0].geometry->positions[2], {4, 1, 0});

    // The import transform applies on top: move everything up by 10.
    glm::mat4 up(1.0f);
    up[3] = glm::vec4(0, 10, 0, 1);
    const GltfImport lifted = importGltf(path, up);
    expectNear(lifted.parts[0].geometry->positions[2], {4, 11, 0});
}

TEST(GltfImport, NegativeScaleFlipsWinding) {
    TinyMesh m = quad();
    for (bool withNormals : {false, true}) {
        SCOPED_TRACE(withNormals ? "given normals" : "generated normals");
        m.normals.assign(withNormals ? 4 : 0, glm::vec3(0, 0, 1));
        const GltfImport g = importGltf(writeGltf("mirror.gltf", m, "[{\"mesh\":0,\"scale\":[-1,1,1]}]"));
        ASSERT_EQ(g.parts.size(), 1u);
        const MeshGeometry& p = *g.parts[0].geometry;
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

    // The material keeps the glTF values for the pbr model, clamped as above.
    m = phongFromMetallicRoughness({1.0f, 0.8f, 0.2f}, 1.0f, 0.25f);
    expectNear(m.baseColor, {1.0f, 0.8f, 0.2f});
    EXPECT_EQ(m.metallic, 1.0f);
    EXPECT_EQ(m.roughness, 0.25f);
    EXPECT_EQ(phongFromMetallicRoughness(glm::vec3(0.5f), 2.0f, -1.0f).metallic, 1.0f);
    // roughnessFromShininess inverts the Walter mapping where it is not clamped.
    EXPECT_NEAR(roughnessFromShininess(m.s), 0.25f, 1e-5f);
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
    expectNear(g.parts[0].material.baseColor, {0.2f, 0.4f, 0.6f});
    EXPECT_EQ(g.parts[0].material.roughness, 0.5f);
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
        "{\"rotation\":[" +
        std::to_string(-h) + ",0,0," + std::to_string(h) +
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

    ASSERT_EQ(g.cameras.size(), 1u);
    expectNear(g.cameras[0].position, {0, 1, 5});
    expectNear(g.cameras[0].target, {0, 1, 4});
    expectNear(g.cameras[0].up, {0, 1, 0});
    EXPECT_NEAR(g.cameras[0].fovY, glm::degrees(0.8f), 1e-4f);
}

// A spot light keeps its cone and range (KHR_lights_punctual "Spot", "Range Property"): node 1 at (0, 4, 1) rotated
// −90° about x shines down; node 2's "spot" object is empty, so the spec's defaults 0 and π/4 apply (tinygltf
// refuses a spot light with no "spot" object at all, which the spec allows); node 3 has a
// cone out of [0, π/2] and inner past outer, clamped with warnings, and a negative range, dropped with one.
TEST(GltfImport, SpotLightsKeepTheirConesAndRange) {
    const float h = std::sqrt(0.5f);
    const std::string down = "\"rotation\":[" + std::to_string(-h) + ",0,0," + std::to_string(h) + "]";
    const std::string nodes = "[{\"mesh\":0},{\"translation\":[0,4,1]," + down +
                              ",\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
                              "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}},"
                              "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":2}}}]";
    const std::string extra =
        ",\"extensionsUsed\":[\"KHR_lights_punctual\"],"
        "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":["
        "{\"type\":\"spot\",\"name\":\"stage\",\"range\":7.5,"
        "\"spot\":{\"innerConeAngle\":0.3,\"outerConeAngle\":0.6}},"
        "{\"type\":\"spot\",\"name\":\"plain\",\"spot\":{}},"
        "{\"type\":\"spot\",\"name\":\"bad\",\"range\":-2,"
        "\"spot\":{\"innerConeAngle\":1.4,\"outerConeAngle\":2.5}}]}}";
    const std::string path = writeGltf("spot_lights.gltf", quad(), nodes, "[0,1,2,3]", extra);
    const GltfImport g = importGltf(path);
    ASSERT_EQ(g.lights.size(), 3u);
    const Light& stage = g.lights[0];
    EXPECT_EQ(stage.type, LightType::Spot);
    expectNear(stage.position, {0, 4, 1});
    expectNear(stage.direction, {0, -1, 0});
    EXPECT_FLOAT_EQ(stage.innerConeAngle, 0.3f);
    EXPECT_FLOAT_EQ(stage.outerConeAngle, 0.6f);
    EXPECT_FLOAT_EQ(stage.range, 7.5f);
    EXPECT_EQ(g.lights[1].type, LightType::Spot);
    expectNear(g.lights[1].direction, {0, 0, -1});  // an unrotated node's −Z
    EXPECT_FLOAT_EQ(g.lights[1].innerConeAngle, 0.0f);
    EXPECT_FLOAT_EQ(g.lights[1].outerConeAngle, 0.785398163f);
    EXPECT_EQ(g.lights[1].range, 0.0f);  // no range
    const Light& bad = g.lights[2];
    EXPECT_FLOAT_EQ(bad.outerConeAngle, kMaxConeAngle);
    EXPECT_FLOAT_EQ(bad.innerConeAngle, 1.4f);
    EXPECT_EQ(bad.range, 0.0f);
    std::string all;
    for (const std::string& w : g.warnings) all += w + " | ";
    EXPECT_NE(all.find("lights[2].spot.outerConeAngle"), std::string::npos) << all;
    EXPECT_NE(all.find("lights[2]: range"), std::string::npos) << all;
    EXPECT_EQ(all.find("lights[0]"), std::string::npos) << "a valid spot light warned: " << all;
    EXPECT_EQ(all.find("point light"), std::string::npos) << all;

    // Negative control: the same file with the outer angle changed does not read back 0.6.
    std::string text;
    {
        std::ifstream in(path);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string outer = "\"outerConeAngle\":0.6";
    ASSERT_NE(text.find(outer), std::string::npos);
    text.replace(text.find(outer), outer.size(), "\"outerConeAngle\":0.7");
    const std::string changed = path.substr(0, path.size() - 5) + "_changed.gltf";
    std::ofstream(changed) << text;
    EXPECT_NE(importGltf(changed).lights[0].outerConeAngle, 0.6f);
}

// ---- Scene loading ---------------------------------------------------------------------------------------------

// Every corner of `b` lies in front of `c` and inside its frustum at the given aspect.
// 2CylinderEngine.glb (121,496 triangles) imports whole. Its speed is measured by bench/, not here.
TEST(GltfImport, TwoCylinderEngineImportsWhole) {
    REQUIRE_MODELS();
    const GltfImport g = importGltf(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    EXPECT_EQ(triangleCount(g), 121496u);
}

// Buffer URIs that leave the model's folder (../ or absolute) are refused unless allowed.
// Limits against hostile files (docs/gltf-import.md, "Limits against hostile files"): each gives a one-line InputError
// before anything big is allocated.

}  // namespace
}  // namespace shadelab
