// glTF import of broken and hostile files: one-line errors naming the file and the place, cycles,
// out-of-range indices, buffers outside the model folder, and the size limits.
#include "scene/gltf/gltf_test_util.h"

#include <filesystem>
#include <fstream>

namespace shadelab {
namespace {

using namespace gltftest;
namespace fs = std::filesystem;
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
    std::filesystem::copy_file(bin, root / "model" / "BoxTextured0.bin",
                               std::filesystem::copy_options::overwrite_existing);
    std::ofstream((root / "model" / "inside.gltf").string()) << text;
    EXPECT_EQ(triangleCount(importGltf((root / "model" / "inside.gltf").string())), 12u);
}

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
    expectRefused(
        "{" + asset +
            R"(,"bufferViews":[{"buffer":0,"byteLength":1000}],"images":[{"bufferView":0,"mimeType":"image/png"}]})",
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
