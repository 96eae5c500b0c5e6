// Tests for glTF's material extensions on import (gltf_materials.cpp): which are read into the material (the clear
// coat with its maps, the specular layer and index, the sheen, the anisotropy, the transmission and volume), which
// are said once per file to be not shaded, and which of their textures are said not to be read yet.
#include "scene/gltf/gltf_test_util.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace shadelab {
namespace {

using namespace gltftest;

// A material extension that is not shaded is said once per file, not dropped in silence (here two materials
// with iridescence); one that is shaded, the clear coat, is not mentioned and is read (factor, roughness, and its
// maps on ClearCoatTest, the one layered Khronos asset Debian ships). Control: a model without either says
// nothing of the kind.
TEST(GltfImport, AMaterialExtensionNotShadedIsSaidOnceAndTheClearcoatIsRead) {
    const std::string sheen = R"({"extensions":{"KHR_materials_iridescence":{"iridescenceFactor":1}}})";
    const std::string path = writeGltf(
        "layers.gltf", quad(), R"([{"mesh":0}])", "[0]",
        R"(,"materials":[)" + sheen + "," + sheen +
            R"(,{"extensions":{"KHR_materials_clearcoat":{"clearcoatFactor":0.75,"clearcoatRoughnessFactor":0.2}}}])");
    const GltfImport g = importGltf(path);
    const auto lines = std::count_if(g.warnings.begin(), g.warnings.end(), [](const std::string& w) {
        return contains(w, "KHR_materials_iridescence is not shaded");
    });
    EXPECT_EQ(lines, 1);
    EXPECT_TRUE(
        anyWarningContains(g, "KHR_materials_iridescence is not shaded (2 materials use it): rendered without it"));
    EXPECT_FALSE(anyWarningContains(g, "KHR_materials_clearcoat"));
    REQUIRE_MODELS();
    const GltfImport coated = importGltf(model("glTF2/ClearCoat-glTF/ClearCoatTest.gltf"));
    EXPECT_FALSE(anyWarningContains(coated, "is not shaded"));
    int factors = 0, maps = 0, normalMaps = 0;
    for (const MeshPart& p : coated.parts) {
        const Material& m = p.material;
        if (m.clearcoat.factor == 1.0f && (m.clearcoat.roughness == 0.03f || m.clearcoat.roughness == 1.0f)) ++factors;
        maps += m.clearcoatTexture || m.clearcoatRoughnessTexture;
        normalMaps += bool(m.clearcoatNormalTexture);
        if (m.clearcoatNormalTexture) {
            EXPECT_FALSE(m.clearcoatNormalTexture.texture->srgb);
            EXPECT_EQ(p.geometry->tangents.size(), p.geometry->positions.size()) << "a coat normal map needs tangents";
        }
    }
    EXPECT_EQ(factors, 6);
    EXPECT_EQ(maps, 2);
    EXPECT_EQ(normalMaps, 2);
    const GltfImport plain = importGltf(model("glTF2/BoxTextured-glTF/BoxTextured.gltf"));
    EXPECT_FALSE(anyWarningContains(plain, "is not shaded"));
}

// A quad whose one primitive takes material 0 of `materials` (a glTF "materials" array, JSON), written as `name`.
std::string quadWithMaterial(const std::string& name, const std::string& materials) {
    const std::string path = writeGltf(name, quad(), R"([{"mesh":0}])", "[0]", R"(,"materials":)" + materials);
    std::ifstream in(path);
    nlohmann::json j = nlohmann::json::parse(in);
    in.close();
    j["meshes"][0]["primitives"][0]["material"] = 0;
    std::ofstream(path) << j.dump();
    return path;
}

// KHR_materials_specular and KHR_materials_ior are read into the material (pbr's F0 tint and weight, the index);
// their textures are said to be not shaded, once each; a material without them keeps the defaults (control).
TEST(GltfImport, SpecularAndIorAreRead) {
    const std::string path = quadWithMaterial(
        "specular.gltf", R"([{"extensions":{"KHR_materials_ior":{"ior":1.33},"KHR_materials_specular":)"
                         R"({"specularFactor":0.5,"specularColorFactor":[2,1,0.5],)"
                         R"("specularTexture":{"index":0}}}},{}])");
    const GltfImport g = importGltf(path);
    ASSERT_EQ(g.parts.size(), 1u);
    const Material& m = g.parts[0].material;
    EXPECT_EQ(m.ior, 1.33f);
    EXPECT_EQ(m.specular.factor, 0.5f);
    EXPECT_EQ(m.specular.color, glm::vec3(2.0f, 1.0f, 0.5f));
    EXPECT_FALSE(anyWarningContains(g, "KHR_materials_specular is not shaded"));
    EXPECT_TRUE(anyWarningContains(g, "KHR_materials_specular.specularTexture: not shaded yet; the factors alone are"));
    const GltfImport plain = importGltf(writeGltf("plain.gltf", quad(), R"([{"mesh":0}])"));
    EXPECT_EQ(plain.parts[0].material.specular, SpecularLayer{});
}

// KHR_materials_sheen is read into the material (pbr's sheen colour and roughness); its textures are said to be
// not shaded, once each; a material without it has no sheen (control).
TEST(GltfImport, SheenIsRead) {
    const std::string path =
        quadWithMaterial("sheen.gltf", R"([{"extensions":{"KHR_materials_sheen":{"sheenColorFactor":[1,0.5,0.25],)"
                                       R"("sheenRoughnessFactor":0.375,"sheenColorTexture":{"index":0}}}},{}])");
    const GltfImport g = importGltf(path);
    ASSERT_EQ(g.parts.size(), 1u);
    const Material& m = g.parts[0].material;
    EXPECT_EQ(m.sheen, (Sheen{{1.0f, 0.5f, 0.25f}, 0.375f}));
    EXPECT_FALSE(anyWarningContains(g, "KHR_materials_sheen is not shaded"));
    EXPECT_TRUE(anyWarningContains(g, "KHR_materials_sheen.sheenColorTexture: not shaded yet; the factors alone are"));
    const GltfImport plain = importGltf(writeGltf("plain.gltf", quad(), R"([{"mesh":0}])"));
    EXPECT_EQ(plain.parts[0].material.sheen, Sheen{});
    EXPECT_FALSE(plain.parts[0].material.sheen.on());
}

// KHR_materials_anisotropy is read into the material (its strength and turn); its texture is said to be not shaded.
TEST(GltfImport, AnisotropyIsRead) {
    const std::string path =
        quadWithMaterial("aniso.gltf", R"([{"extensions":{"KHR_materials_anisotropy":{"anisotropyStrength":0.625,)"
                                       R"("anisotropyRotation":1.5,"anisotropyTexture":{"index":0}}}}])");
    const GltfImport g = importGltf(path);
    ASSERT_EQ(g.parts.size(), 1u);
    EXPECT_EQ(g.parts[0].material.anisotropy, (Anisotropy{0.625f, 1.5f}));
    EXPECT_FALSE(anyWarningContains(g, "KHR_materials_anisotropy is not shaded"));
    EXPECT_TRUE(anyWarningContains(g, "KHR_materials_anisotropy.anisotropyTexture: not shaded yet"));
    // Its direction turns from the tangent: generated from TEXCOORD_0 for the grid's anisotropic spheres; the
    // clear coat grid's spheres, with no normal map and no anisotropy, get none (control).
    const auto tangentsOf = [](const char* name, int& anisotropic, int& withTangents) {
        const GltfImport imported = importGltf(std::string(SHADELAB_SOURCE_DIR) + "/assets/models/layers/" + name);
        for (const MeshPart& p : imported.parts) {
            const bool has = p.geometry->tangents.size() == p.geometry->positions.size();
            if (p.material.anisotropy.on()) {
                ++anisotropic;
                EXPECT_TRUE(has) << name << ": an anisotropic part without tangents";
            }
            withTangents += has;
        }
    };
    int anisotropic = 0, withTangents = 0;
    tangentsOf("anisotropy_grid.gltf", anisotropic, withTangents);
    EXPECT_EQ(anisotropic, 12);
    int none = 0, coatTangents = 0;
    tangentsOf("clearcoat_grid.gltf", none, coatTangents);
    EXPECT_EQ(coatTangents, 0);
}

// KHR_materials_transmission and KHR_materials_volume: the factor, the thickness, the attenuation distance and
// colour are read, and neither is said to be not shaded; their textures are said not to be read. Control: a
// volume with no distance absorbs nothing (infinite).
TEST(GltfImport, TransmissionAndVolumeAreRead) {
    const std::string path = quadWithMaterial(
        "transmission.gltf",
        R"([{"extensions":{"KHR_materials_transmission":{"transmissionFactor":0.75,"transmissionTexture":{"index":0}},)"
        R"("KHR_materials_volume":{"thicknessFactor":0.5,"attenuationDistance":2.5,)"
        R"("attenuationColor":[0.5,0.25,1],"thicknessTexture":{"index":0}}}},)"
        R"({"extensions":{"KHR_materials_volume":{"thicknessFactor":1}}}])");
    const GltfImport g = importGltf(path);
    ASSERT_GE(g.parts.size(), 1u);
    const Material& m = g.parts[0].material;
    EXPECT_EQ(m.transmission, Transmission{0.75f});
    EXPECT_EQ(m.volume, (Volume{0.5f, 2.5f, {0.5f, 0.25f, 1.0f}}));
    EXPECT_FALSE(anyWarningContains(g, "KHR_materials_transmission is not shaded"));
    EXPECT_FALSE(anyWarningContains(g, "KHR_materials_volume is not shaded"));
    EXPECT_TRUE(anyWarningContains(g, "KHR_materials_transmission.transmissionTexture: not shaded yet"));
    EXPECT_TRUE(anyWarningContains(g, "KHR_materials_volume.thicknessTexture: not shaded yet"));
    Volume defaults;
    defaults.thickness = 1.0f;
    EXPECT_TRUE(std::isinf(defaults.attenuationDistance));
    EXPECT_EQ(defaults.transmittance(5.0f), glm::vec3(1.0f));
}

}  // namespace
}  // namespace shadelab
