// Textured surfaces, raster against reference (design.md §9 and §4): BoxTextured's front face head-on, its
// base-colour texture magnified, under Phong and pbr, within the §4 gates; negative controls (sRGB decoding
// skipped in the tracer, the texture dropped) must fail. And BoxTextured in each form renders non-trivially:
// the front face's linear colour divided by the untextured render's is the texture's mean, within 0.03.
#include "gl_fixture.h"
#include "image/encode.h"
#include "render_compare.h"
#include "scene/bounds.h"
#include "scene/gltf/gltf_import.h"
#include "scene/gltf/gltf_textures.h"
#include "util/read_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace shadelab::test {
namespace {

const std::string kModels = "/usr/share/assimp/models/glTF2/";

#define REQUIRE_BOX()                                                                \
    do {                                                                             \
        if (!std::filesystem::exists(kModels + "BoxTextured-glTF/BoxTextured.gltf")) \
            GTEST_SKIP() << "assimp-testmodels is missing (Debian package)";         \
    } while (0)

// The unit box centred at the origin, its +z face (the logo) head-on from 2 units, lit from the camera.
Scene boxScene(const std::string& relative, const std::string& model = "phong") {
    Scene scene = comparisonStage();
    const GltfImport g = importGltf(kModels + relative);
    Mesh mesh;
    mesh.name = "BoxTextured";
    mesh.parts = g.parts;
    scene.meshes.push_back(mesh);
    scene.camera.position = {0.0f, 0.0f, 2.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fovY = 40.0f;
    scene.lights.push_back(pointLight({0.3f, 0.4f, 2.5f}, glm::vec3(0.9f)));
    scene.model = model == "pbr" ? ShadingModel::Pbr : ShadingModel::Phong;
    return scene;
}

class TextureReference : public GlTest {};

TEST_F(TextureReference, BoxTexturedFrontFaceWithinTheGates) {
    REQUIRE_BOX();
    for (const char* model : {"phong", "pbr"}) {
        const Scene scene = boxScene("BoxTextured-glTF-Binary/BoxTextured.glb", model);
        const CompareResult c =
            compareWithReference(scene, scene, 320, 320, 0, CompareGates{}, std::string("texture_box_") + model);
        EXPECT_TRUE(c.pass) << model;
    }
}

// KHR_texture_transform (set here on the binding, as the importer does): rotated, scaled and offset, with
// BoxTextured's repeat wrap. Negative control: the tracer's rotation 0.05 rad off must fail.
TEST_F(TextureReference, TextureTransformWithinTheGatesAndRotationChangedFails) {
    REQUIRE_BOX();
    Scene scene = boxScene("BoxTextured-glTF-Binary/BoxTextured.glb");
    TextureBinding& b = scene.meshes[0].parts[0].material.baseColorTexture;
    b.rotation = 0.4f;
    b.scale = glm::vec2(0.8f, 0.7f);
    b.offset = glm::vec2(0.3f, -0.2f);
    EXPECT_TRUE(compareWithReference(scene, scene, 320, 320, 0, CompareGates{}, "texture_transform").pass);
    Scene rotated = scene;
    rotated.meshes[0].parts[0].material.baseColorTexture.rotation = 0.45f;
    EXPECT_FALSE(compareWithReference(scene, rotated, 320, 320, 0, CompareGates{}, "texture_transform_rotated").pass);
}

// Khronos' TextureTransformTest: nine textured parts with offsets, rotations, scales and clamp-to-edge.
// The tracer once read every part's triangles as if they were the first part's; both renderers must agree.
TEST_F(TextureReference, TextureTransformTestAssetAgrees) {
    if (!std::filesystem::exists(kModels + "textureTransform/TextureTransformTest.gltf")) GTEST_SKIP();
    Scene scene = comparisonStage();
    const GltfImport g = importGltf(kModels + "textureTransform/TextureTransformTest.gltf");
    Mesh mesh;
    mesh.name = "TextureTransformTest";
    mesh.parts = g.parts;
    ASSERT_GT(mesh.parts.size(), 1u);
    Bounds box;
    for (const MeshPart& p : mesh.parts) {
        box.extend(p.geometry->bounds.lo);
        box.extend(p.geometry->bounds.hi);
    }
    scene.meshes.push_back(mesh);
    const glm::vec3 centre = 0.5f * (box.lo + box.hi);
    scene.camera.target = centre;
    scene.camera.position = centre + glm::vec3(0.0f, 0.0f, 1.4f * glm::length(box.hi - box.lo));
    scene.lights.push_back(pointLight(scene.camera.position, glm::vec3(0.9f)));
    const CompareResult c = compareWithReference(scene, scene, 240, 240, 0, CompareGates{}, "texture_transform_asset");
    EXPECT_TRUE(c.pass);
}

TEST_F(TextureReference, SrgbDecodingSkippedFails) {
    REQUIRE_BOX();
    const Scene scene = boxScene("BoxTextured-glTF-Binary/BoxTextured.glb");
    Scene skipped = scene;
    const std::string png = readFile(kModels + "BoxTextured-glTF/CesiumLogoFlat.png", uint64_t(1) << 20);
    skipped.meshes[0].parts[0].material.baseColorTexture.texture =
        gltf::decodeTexture(png, "raw", false, 8192, uint64_t(1) << 30);
    const CompareResult c = compareWithReference(scene, skipped, 320, 320, 0, CompareGates{}, "texture_box_no_srgb");
    EXPECT_FALSE(c.pass) << "a tracer that skips sRGB decoding must fail the gates";
}

TEST_F(TextureReference, TextureDroppedFails) {
    REQUIRE_BOX();
    const Scene scene = boxScene("BoxTextured-glTF-Binary/BoxTextured.glb");
    Scene plain = scene;
    plain.meshes[0].parts[0].material.baseColorTexture = {};
    const CompareResult c = compareWithReference(scene, plain, 320, 320, 0, CompareGates{}, "texture_box_dropped");
    EXPECT_FALSE(c.pass);
}

// Mean of (textured / untextured) linear colour over the face's central 60 %: ambient and diffuse only, so
// the ratio at each pixel is the filtered texel, and its mean the texture's mean.
glm::vec3 faceRatio(const ImageF& textured, const ImageF& plain) {
    glm::dvec3 sum(0.0);
    int n = 0;
    for (int y = 100; y < 220; ++y)
        for (int x = 100; x < 220; ++x) {
            const float* a = textured.pixel(x, y);
            const float* b = plain.pixel(x, y);
            for (int k = 0; k < 3; ++k) sum[k] += b[k] > 0.0f ? a[k] / b[k] : 0.0;
            ++n;
        }
    return glm::vec3(sum / double(n));
}

TEST_F(TextureReference, BoxTexturedInEachFormRendersItsTexture) {
    REQUIRE_BOX();
    for (const char* form : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                             "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        Scene scene = boxScene(form);
        scene.terms.specular = false;
        scene.terms.shadows = false;
        Scene plain = scene;
        plain.meshes[0].parts[0].material.baseColorTexture = {};
        const auto& tex = *scene.meshes[0].parts[0].material.baseColorTexture.texture;
        // The central 120 × 120 pixels of a 320 px face cover its central 37.5 % of the texture per axis.
        glm::dvec3 mean(0.0);
        int n = 0;
        const TextureLevel& l0 = tex.levels[0];
        for (int y = int(l0.height * 0.3125); y < int(l0.height * 0.6875); ++y)
            for (int x = int(l0.width * 0.3125); x < int(l0.width * 0.6875); ++x, ++n)
                mean += glm::dvec3(glm::vec3(tex.texel(0, x, y)));
        const glm::vec3 want(mean / double(n));
        trace::TraceSettings ts;
        ts.width = ts.height = 320;
        ts.maxDepth = 0;
        const glm::vec3 traced = faceRatio(trace::traceImage(scene, ts).color, trace::traceImage(plain, ts).color);
        raster::RasterRenderer& r = sharedRasterRenderer();
        raster::OffscreenOptions o;
        o.width = o.height = 320;
        o.keepLinear = true;
        r.uploadMeshes(scene);
        const ImageF a = raster::renderOffscreen(r, scene, o).linear;
        const ImageF b = raster::renderOffscreen(r, plain, o).linear;
        const glm::vec3 rastered = faceRatio(a, b);
        std::printf("%s: texture mean %.4f %.4f %.4f, traced %.4f %.4f %.4f, raster %.4f %.4f %.4f\n", form, want.r,
                    want.g, want.b, traced.r, traced.g, traced.b, rastered.r, rastered.g, rastered.b);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(traced[k], want[k], 0.03f) << form << " channel " << k;
            EXPECT_NEAR(rastered[k], want[k], 0.03f) << form << " channel " << k;
        }
        // Not a flat colour: the logo is blue and green on grey.
        EXPECT_GT(want.b, want.r + 0.05f);
    }
}

}  // namespace
}  // namespace shadelab::test
