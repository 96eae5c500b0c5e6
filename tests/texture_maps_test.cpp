// glTF material maps (design.md §9 and §4): each asset tools/make_texture_gltf.py writes, raster
// against the reference tracer under the §4 gates for Phong and pbr; and negative controls that must fail
// (the normal map's green channel flipped, sRGB decoding skipped, the transform's rotation changed, the
// second UV set ignored, the alpha mode ignored, the metallic-roughness and occlusion maps dropped).
#include "gl_fixture.h"
#include "render_compare.h"
#include "scene/bounds.h"
#include "scene/gltf/gltf_import.h"
#include "scene/texture.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

namespace shadelab::test {
namespace {

const char* const kAssets[] = {"uv_checker",        "wrap_modes", "normal_bump", "normal_bump_no_tangents",
                               "texture_transform", "alpha_mask", "alpha_blend", "second_uv",
                               "metal_rough",       "emissive"};

// The asset head-on from 3.2 units (its quads span [-1, 1]), lit from the upper left, with the stage's ambient.
Scene assetScene(const std::string& name, ShadingModel model = ShadingModel::Phong) {
    Scene scene = comparisonStage();
    const GltfImport g = importGltf(sourcePath("assets/models/textures/" + name + ".gltf"));
    EXPECT_TRUE(g.warnings.empty()) << name << ": " << (g.warnings.empty() ? "" : g.warnings[0]);
    Mesh mesh;
    mesh.name = name;
    mesh.parts = g.parts;
    scene.meshes.push_back(mesh);
    scene.camera.position = {0.0f, 0.0f, 3.2f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fovY = 40.0f;
    scene.lights.push_back(pointLight({-1.5f, 1.5f, 3.0f}, glm::vec3(0.9f)));
    scene.model = model;
    return scene;
}

Material& part(Scene& s, size_t k) { return s.meshes[0].parts[k].material; }
const Material& part(const Scene& s, size_t k) { return s.meshes[0].parts[k].material; }

// A copy of `t` whose texels (decoded, then encoded back to 8 bits) went through `f` (every level, so
// filtering sees the change everywhere).
template <class F>
TextureBinding mapped(const TextureBinding& t, F f) {
    auto copy = std::make_shared<Texture>(*t.texture);
    for (size_t level = 0; level < copy->levels.size(); ++level) {
        TextureLevel& l = copy->levels[level];
        for (int y = 0; y < l.height; ++y)
            for (int x = 0; x < l.width; ++x) {
                const glm::vec4 v = f(t.texture->texel(level, x, y));
                uint8_t* p = &l.texels[(size_t(y) * size_t(l.width) + size_t(x)) * kTexelBytes];
                for (int k = 0; k < 4; ++k) p[k] = encodeTexelChannel(v[k], copy->srgb && k < 3);
            }
    }
    TextureBinding b = t;
    b.texture = copy;
    return b;
}

CompareResult gate(const Scene& raster, const Scene& traced, const std::string& name) {
    return compareWithReference(raster, traced, 240, 240, 0, CompareGates{}, name);
}

class TextureMaps : public GlTest {};

// One test per asset, so that ctest runs them in parallel, each in its own process.
class TextureMapsAsset : public GlTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(TextureMapsAsset, WithinTheGatesUnderPhongAndPbr) {
    const std::string name = GetParam();
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
        const Scene scene = assetScene(name, model);
        const std::string tag = "maps_" + name + (model == ShadingModel::Pbr ? "_pbr" : "_phong");
        EXPECT_TRUE(gate(scene, scene, tag).pass) << tag;
    }
}

INSTANTIATE_TEST_SUITE_P(Assets, TextureMapsAsset, ::testing::ValuesIn(kAssets),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string(p.param); });

TEST_F(TextureMaps, NormalMapGreenFlippedFails) {
    for (const char* name : {"normal_bump", "normal_bump_no_tangents"}) {
        const Scene scene = assetScene(name);
        Scene flipped = scene;
        part(flipped, 0).normalTexture =
            mapped(part(scene, 0).normalTexture, [](glm::vec4 v) { return glm::vec4(v.r, 1.0f - v.g, v.b, v.a); });
        EXPECT_FALSE(gate(scene, flipped, std::string("maps_green_flipped_") + name).pass) << name;
    }
}

TEST_F(TextureMaps, GeneratedTangentsAgreeWithTheFileTangents) {
    // The file's analytic tangents rasterized, the generated ones traced: the same picture within the gates.
    const Scene file = assetScene("normal_bump"), generated = assetScene("normal_bump_no_tangents");
    EXPECT_TRUE(gate(file, generated, "maps_generated_tangents").pass);
    // Handedness matters: the generated tangents with w negated (a mirrored frame) must fail.
    Scene mirrored = generated;
    MeshGeometry g = *mirrored.meshes[0].parts[0].geometry;
    for (glm::vec4& t : g.tangents) t.w = -t.w;
    mirrored.meshes[0].parts[0].geometry = shareGeometry(std::move(g));
    EXPECT_FALSE(gate(file, mirrored, "maps_tangents_mirrored").pass);
}

TEST_F(TextureMaps, SrgbDecodingSkippedFails) {
    const Scene scene = assetScene("uv_checker");
    Scene raw = scene;
    // Texels left as stored: re-encode the decoded values, as a tracer that skipped decoding would read them.
    part(raw, 0).baseColorTexture = mapped(part(scene, 0).baseColorTexture, [](glm::vec4 v) {
        auto enc = [](float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; };
        return glm::vec4(enc(v.r), enc(v.g), enc(v.b), v.a);
    });
    EXPECT_FALSE(gate(scene, raw, "maps_srgb_skipped").pass);
}

TEST_F(TextureMaps, TransformRotationChangedFails) {
    const Scene scene = assetScene("texture_transform");
    ASSERT_NEAR(part(scene, 0).baseColorTexture.rotation, 0.4f, 1e-6f);
    Scene rotated = scene;
    part(rotated, 0).baseColorTexture.rotation += 0.05f;
    EXPECT_FALSE(gate(scene, rotated, "maps_transform_rotated").pass);
}

TEST_F(TextureMaps, SecondUvSetIgnoredFails) {
    const Scene scene = assetScene("second_uv");
    ASSERT_EQ(part(scene, 0).baseColorTexture.texCoord, 1);
    ASSERT_EQ(part(scene, 0).occlusionTexture.texCoord, 1);  // the transform's override
    Scene first = scene;
    part(first, 0).baseColorTexture.texCoord = 0;
    EXPECT_FALSE(gate(scene, first, "maps_second_uv_ignored").pass);
}

TEST_F(TextureMaps, AlphaModeIgnoredFails) {
    for (const char* name : {"alpha_mask", "alpha_blend"}) {
        const Scene scene = assetScene(name);
        Scene opaque = scene;
        part(opaque, 1).alphaMode = AlphaMode::Opaque;
        EXPECT_FALSE(gate(scene, opaque, std::string("maps_alpha_ignored_") + name).pass) << name;
    }
}

TEST_F(TextureMaps, MetallicRoughnessAndOcclusionDroppedFail) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
        const Scene scene = assetScene("metal_rough", model);
        const std::string tag = model == ShadingModel::Pbr ? "_pbr" : "_phong";
        Scene noMr = scene;
        part(noMr, 0).metallicRoughnessTexture = {};
        EXPECT_FALSE(gate(scene, noMr, "maps_mr_dropped" + tag).pass);
        Scene noAo = scene;
        part(noAo, 0).occlusionTexture = {};
        EXPECT_FALSE(gate(scene, noAo, "maps_occlusion_dropped" + tag).pass);
    }
}

TEST_F(TextureMaps, EmissiveTextureDroppedOrNotDecodedFails) {
    const Scene scene = assetScene("emissive");
    ASSERT_TRUE(part(scene, 0).emissiveTexture);
    EXPECT_TRUE(part(scene, 0).emissiveTexture.texture->srgb);
    Scene dropped = scene;
    part(dropped, 0).emissiveTexture = {};
    EXPECT_FALSE(gate(scene, dropped, "maps_emissive_dropped").pass);
    Scene raw = scene;
    part(raw, 0).emissiveTexture = mapped(part(scene, 0).emissiveTexture, [](glm::vec4 v) {
        auto enc = [](float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; };
        return glm::vec4(enc(v.r), enc(v.g), enc(v.b), v.a);
    });
    EXPECT_FALSE(gate(scene, raw, "maps_emissive_srgb_skipped").pass);
}

// assimp-testmodels' BoxTexcoords (base colour on TEXCOORD_0, the same image as metallic-roughness on
// TEXCOORD_1) and ClearCoat (normal maps, jpg and png), head-on: within the gates, and not flat. Head-on
// because on BoxTexcoords' grazing side faces llvmpipe's per-quad derivatives pick other mip levels than the
// tracer's exact differentials (textures-status.md, "Known limits"): 0.27 % of pixels over, max 136/255.
// ClearCoat is held to the shadow-edge gates (1 %, no hard maximum, mean <= 1/255): untextured, it already
// fails the strict ones (0.66 % over, max 147) on its capsules' silhouettes against their own tiles, which
// share one coverage id; textured, 0.09 % over, max 114, on the same pixels.
TEST_F(TextureMaps, AssimpModelsWithinTheGates) {
    const std::string models = "/usr/share/assimp/models/glTF2/";
    for (const char* file : {"BoxTexcoords-glTF/boxTexcoords.gltf", "ClearCoat-glTF/ClearCoatTest.gltf"}) {
        if (!std::filesystem::exists(models + file)) GTEST_SKIP() << "assimp-testmodels is missing (Debian package)";
        Scene scene = comparisonStage();
        const GltfImport g = importGltf(models + file);
        Mesh mesh;
        mesh.name = file;
        mesh.parts = g.parts;
        Bounds box;
        size_t normalMaps = 0, secondSet = 0;
        for (const MeshPart& p : mesh.parts) {
            box.extend(p.geometry->bounds.lo);
            box.extend(p.geometry->bounds.hi);
            normalMaps += p.material.normalTexture ? 1 : 0;
            secondSet += p.material.metallicRoughnessTexture.texCoord == 1 ? 1 : 0;
        }
        if (std::string(file).find("Texcoords") != std::string::npos)
            EXPECT_GT(secondSet, 0u);
        else
            EXPECT_GT(normalMaps, 0u);
        scene.meshes.push_back(mesh);
        const glm::vec3 centre = 0.5f * (box.lo + box.hi);
        scene.camera.target = centre;
        scene.camera.position = centre + glm::vec3(0.0f, 0.0f, 1.6f) * glm::length(box.hi - box.lo);
        scene.lights.push_back(pointLight(scene.camera.position + glm::vec3(-1.0f, 1.0f, 0.0f), glm::vec3(0.9f)));
        for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
            scene.model = model;
            const std::string tag = std::string("maps_assimp_") + (secondSet ? "boxtexcoords" : "clearcoat") +
                                    (model == ShadingModel::Pbr ? "_pbr" : "_phong");
            const Rendered r = rasterizeWithCoverage(scene, 240, 240);
            const CompareResult c = gateWithEvidence(r, traceWithCoverage(scene, 240, 240, comparisonDepth(scene, 0)),
                                                     secondSet ? CompareGates{} : kShadowEdgeGates, tag);
            EXPECT_TRUE(c.pass) << tag;
            // Not flat: the covered pixels' colours spread by more than 20/255 in some channel.
            int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
            for (int y = 0; y < 240; ++y)
                for (int x = 0; x < 240; ++x) {
                    if (r.coverage[size_t(y) * 240 + size_t(x)] == 0) continue;
                    for (int k = 0; k < 3; ++k) {
                        const int v = r.pixels.pixel(x, y)[k];
                        lo[k] = std::min(lo[k], v);
                        hi[k] = std::max(hi[k], v);
                    }
                }
            EXPECT_GT(std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}), 20) << tag;
        }
    }
}

}  // namespace
}  // namespace shadelab::test
