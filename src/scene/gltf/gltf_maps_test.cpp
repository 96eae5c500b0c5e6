// glTF material maps as scene data (docs/gltf-import.md, "Material maps"): metallic-roughness, normal (scale) and
// occlusion (strength) bindings, TEXCOORD_1 and the transform's texCoord override, alpha modes, TANGENT read or
// generated in the MikkTSpace convention (mesh_tangents.h); and bad input: a missing or malformed TANGENT, TEXCOORD_2,
// an unknown alphaMode, each one line (an error naming the accessor, or a warning and the documented fallback).
#include "gltf_test_util.h"

#include "scene/mesh_tangents.h"

#include <nlohmann/json.hpp>

#include <glm/vec4.hpp>

namespace shadelab::gltftest {
namespace {

std::string asset(const std::string& name) {
    return std::string(SHADELAB_SOURCE_DIR) + "/assets/models/textures/" + name + ".gltf";
}

nlohmann::json assetJson(const std::string& name) { return nlohmann::json::parse(readTextFile(asset(name))); }

GltfImport importJson(const nlohmann::json& j) { return importGltfBytes(j.dump(), false, "edited.gltf"); }

float angleDegrees(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

TEST(GltfMaps, BindingsStrengthsAndAlphaAreImported) {
    const GltfImport mr = importGltf(asset("metal_rough"));
    ASSERT_EQ(mr.parts.size(), 1u);
    const Material& m = mr.parts[0].material;
    ASSERT_TRUE(m.metallicRoughnessTexture);
    EXPECT_FALSE(m.metallicRoughnessTexture.texture->srgb);  // data, not colour
    ASSERT_TRUE(m.occlusionTexture);
    EXPECT_FALSE(m.occlusionTexture.texture->srgb);
    EXPECT_FLOAT_EQ(m.occlusionTexture.strength, 0.8f);
    EXPECT_EQ(m.occlusionTexture.sampler.wrapS, TextureWrap::ClampToEdge);

    const GltfImport bump = importGltf(asset("normal_bump"));
    const Material& b = bump.parts[0].material;
    ASSERT_TRUE(b.normalTexture);
    EXPECT_FALSE(b.normalTexture.texture->srgb);
    EXPECT_FLOAT_EQ(b.normalTexture.strength, 1.5f);
    const MeshGeometry& g = *bump.parts[0].geometry;
    ASSERT_EQ(g.tangents.size(), g.positions.size());
    for (const glm::vec4& t : g.tangents) {
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
        EXPECT_EQ(t.w, 1.0f);
    }

    const GltfImport mask = importGltf(asset("alpha_mask"));
    ASSERT_EQ(mask.parts.size(), 2u);
    EXPECT_EQ(mask.parts[0].material.alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(mask.parts[1].material.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(mask.parts[1].material.alphaCutoff, 0.5f);
    const GltfImport blend = importGltf(asset("alpha_blend"));
    EXPECT_EQ(blend.parts[1].material.alphaMode, AlphaMode::Blend);
    EXPECT_FLOAT_EQ(blend.parts[1].material.alpha, 0.5f);

    const GltfImport uv = importGltf(asset("second_uv"));
    const MeshGeometry& q = *uv.parts[0].geometry;
    ASSERT_EQ(q.texcoords1.size(), 4u);
    EXPECT_EQ(q.texcoords1[0], glm::vec2(0.0f, 1.0f));
    EXPECT_EQ(uv.parts[0].material.baseColorTexture.texCoord, 1);
    EXPECT_EQ(uv.parts[0].material.occlusionTexture.texCoord, 1);  // KHR_texture_transform's override
    EXPECT_EQ(q.tangents.size(), 4u);                              // the file's TANGENT, read even without a normal map
}

// The patch's TANGENT is analytic (∂P/∂θ); generated tangents must point the same way within a degree where a
// vertex has triangles on both sides, and within 3° on the border (chords, not tangents), with the same w.
TEST(GltfMaps, GeneratedTangentsMatchTheFileTangents) {
    const GltfImport file = importGltf(asset("normal_bump"));
    const GltfImport generated = importGltf(asset("normal_bump_no_tangents"));
    EXPECT_TRUE(generated.warnings.empty());
    const MeshGeometry& a = *file.parts[0].geometry;
    const MeshGeometry& b = *generated.parts[0].geometry;
    ASSERT_EQ(b.tangents.size(), a.tangents.size());
    float worst = 0.0f;
    for (size_t i = 0; i < a.tangents.size(); ++i) {
        const size_t col = i % 17;
        const float angle = angleDegrees(glm::vec3(a.tangents[i]), glm::vec3(b.tangents[i]));
        EXPECT_LT(angle, col == 0 || col == 16 ? 3.0f : 1.0f) << "vertex " << i;
        EXPECT_EQ(a.tangents[i].w, b.tangents[i].w) << "vertex " << i;
        EXPECT_NEAR(glm::dot(glm::vec3(b.tangents[i]), b.normals[i]), 0.0f, 1e-5f);  // orthogonalised
        worst = std::max(worst, angle);
    }
    std::printf("generated vs file tangents: worst %.3f degrees\n", worst);
}

TEST(GltfMaps, TangentHandednessFollowsTheUvWinding) {
    // A +z quad, u along +x, glTF's v down (−y): T = +x, bitangent (the image's up) +y = N × T, so w = +1.
    const std::vector<glm::vec3> p{{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}}, n(4, glm::vec3(0, 0, 1));
    const std::vector<uint32_t> idx{0, 3, 2, 0, 2, 1};
    std::vector<glm::vec4> t = generateTangents(p, n, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, idx);
    for (const glm::vec4& v : t) EXPECT_EQ(v, glm::vec4(1, 0, 0, 1));
    // u mirrored: T = −x, and the frame is left-handed against N: w = −1.
    t = generateTangents(p, n, {{1, 0}, {0, 0}, {0, 1}, {1, 1}}, idx);
    for (const glm::vec4& v : t) EXPECT_EQ(v, glm::vec4(-1, 0, 0, -1));
    // No (u, v) area: a unit vector perpendicular to N, w = +1.
    t = generateTangents(p, n, std::vector<glm::vec2>(4, glm::vec2(0.5f)), idx);
    for (const glm::vec4& v : t) {
        EXPECT_NEAR(glm::length(glm::vec3(v)), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::vec3(v), n[0]), 0.0f, 1e-6f);
        EXPECT_EQ(v.w, 1.0f);
    }
}

TEST(GltfMaps, MirroringNodeFlipsTheHandedness) {
    nlohmann::json j = assetJson("normal_bump");
    j["nodes"][0]["scale"] = {-1.0, 1.0, 1.0};
    const GltfImport g = importJson(j);
    for (const glm::vec4& t : g.parts[0].geometry->tangents) EXPECT_EQ(t.w, -1.0f);
    // And generating on the mirrored geometry agrees with the file's mirrored TANGENT.
    nlohmann::json k = assetJson("normal_bump_no_tangents");
    k["nodes"][0]["scale"] = {-1.0, 1.0, 1.0};
    const GltfImport h = importJson(k);
    for (const glm::vec4& t : h.parts[0].geometry->tangents) EXPECT_EQ(t.w, -1.0f);
}

int tangentAccessor(const nlohmann::json& j) { return j["meshes"][0]["primitives"][0]["attributes"]["TANGENT"]; }

TEST(GltfMaps, BadTangentsAreOneLine) {
    {  // count differs from POSITION: an error naming the accessor
        nlohmann::json j = assetJson("normal_bump");
        j["accessors"][tangentAccessor(j)]["count"] = 288;
        try {
            importJson(j);
            ADD_FAILURE() << "expected an InputError";
        } catch (const InputError& e) {
            EXPECT_TRUE(contains(e.what(), "TANGENT count 288 differs from POSITION count 289")) << e.what();
            EXPECT_TRUE(contains(e.what(), "accessors[")) << e.what();
        }
    }
    {  // VEC3 where VEC4 is needed
        nlohmann::json j = assetJson("normal_bump");
        j["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
            j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"];
        try {
            importJson(j);
            ADD_FAILURE() << "expected an InputError";
        } catch (const InputError& e) {
            EXPECT_TRUE(contains(e.what(), "expected VEC4")) << e.what();
        }
    }
    {  // all zero (an accessor without a buffer view): one warning, generated tangents instead
        nlohmann::json j = assetJson("normal_bump");
        j["accessors"][tangentAccessor(j)].erase("bufferView");
        const GltfImport g = importJson(j);
        EXPECT_TRUE(anyWarningContains(g, "generated ones used instead"));
        const MeshGeometry& m = *g.parts[0].geometry;
        ASSERT_EQ(m.tangents.size(), m.positions.size());
        for (const glm::vec4& t : m.tangents) EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
    }
}

TEST(GltfMaps, UnsupportedCoordinateSetsAndAlphaModesWarn) {
    nlohmann::json j = assetJson("second_uv");
    j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 2;
    j["materials"][0]["alphaMode"] = "CUTOUT";
    const GltfImport g = importJson(j);
    EXPECT_TRUE(anyWarningContains(g, "TEXCOORD_2 is not imported")) << g.warnings.size();
    EXPECT_TRUE(anyWarningContains(g, "alphaMode: unknown \"CUTOUT\""));
    EXPECT_FALSE(g.parts[0].material.baseColorTexture);  // the factor alone
    EXPECT_EQ(g.parts[0].material.alphaMode, AlphaMode::Opaque);
    // A map whose set the primitive lacks reads (0, 0) in both renderers: documented, not an error.
    nlohmann::json k = assetJson("uv_checker");
    k["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1;
    const GltfImport h = importJson(k);
    EXPECT_TRUE(h.parts[0].geometry->texcoords1.empty());
    EXPECT_TRUE(h.parts[0].material.baseColorTexture);
}

TEST(GltfMaps, NormalMapOutOfRangeFallsBackToTheVertexNormal) {
    nlohmann::json j = assetJson("normal_bump_no_tangents");
    j["materials"][0]["normalTexture"]["index"] = 7;
    const GltfImport g = importJson(j);
    EXPECT_TRUE(anyWarningContains(g, "normalTexture: texture 7 out of range"));
    EXPECT_FALSE(g.parts[0].material.normalTexture);
    EXPECT_TRUE(g.parts[0].geometry->tangents.empty());  // nothing needs them
}

}  // namespace
}  // namespace shadelab::gltftest
