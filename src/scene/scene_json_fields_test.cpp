// What single fields of the scene JSON format mean (docs/scene-format.md): a plane from a point, named
// materials for every object type, the base colour that follows md, mesh transforms, grey numbers,
// comments, version and model, pbr and Phong fields read from each other, unknown fields warned about with a
// hint, and the display settings.
#include "scene/scene_json.h"
#include "scene/scene_json_test_util.h"

#include "util/input_error.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <nlohmann/json.hpp>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

namespace shadelab {
namespace {

using test::collectWarning;
using test::Diff;
using test::expectRoundTrip;
using test::gWarnings;
using test::joined;
using test::parse;

TEST(SceneJson, PlaneFromPointAgreesWithOffset) {
    Scene a = parse(R"({"objects": [{"type": "plane", "normal": [0, 2, 0], "point": [5, 3, 7]},
                                    {"type": "plane", "normal": [0, 1, 0], "offset": 3},
                                    {"type": "plane", "normal": [1, 1, 0], "point": [1, 1, 0]},
                                    {"type": "plane", "normal": [0.70710678, 0.70710678, 0], "offset": 1.41421356}]})");
    ASSERT_EQ(a.planes.size(), 4u);
    EXPECT_EQ(a.planes[0].normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(a.planes[0].offset, 3.0f);
    Diff d;
    d.v("normal", a.planes[0].normal, a.planes[1].normal), d.f("offset", a.planes[0].offset, a.planes[1].offset);
    EXPECT_EQ(joined(d.fields), "");
    EXPECT_NEAR(glm::length(a.planes[2].normal), 1.0f, 1e-6f);
    EXPECT_NEAR(a.planes[2].offset, a.planes[3].offset, 1e-6f);
    EXPECT_NEAR(a.planes[2].normal.x, a.planes[3].normal.x, 1e-6f);
}

TEST(SceneJson, NamedMaterialsResolveForEveryObjectType) {
    Scene s = parse(R"({"materials": {"gold": {"md": [0.8, 0.6, 0.2], "s": 64}, "my grey": {"md": 0.5}},
        "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "gold"},
                    {"type": "plane", "material": "my grey"},
                    {"type": "mesh", "source": "m.glb", "material": "gold"},
                    {"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": {"ms": 0, "kr": 0.25}}]})");
    ASSERT_EQ(s.spheres.size(), 2u);
    Material gold;
    gold.md = {0.8f, 0.6f, 0.2f}, gold.s = 64.0f;
    gold.baseColor = gold.md, gold.roughness = roughnessFromShininess(64.0f);  // Phong fields only: pbr follows
    Diff d;
    d.material("gold sphere", s.spheres[0].material, gold);
    Material grey;
    grey.md = grey.baseColor = glm::vec3(0.5f);
    d.material("grey plane", s.planes[0].material, grey);
    Material partial;
    partial.ms = glm::vec3(0.0f), partial.kr = glm::vec3(0.25f);
    d.material("inline partial", s.spheres[1].material, partial);
    MaterialOverride goldOverride;  // a mesh keeps the imported values of fields the material leaves out
    goldOverride.md = gold.md, goldOverride.s = 64.0f;
    d.materialOverride("gold mesh", s.meshes[0].material, goldOverride);
    EXPECT_EQ(joined(d.fields), "");
}

TEST(SceneJson, BaseColorFollowingAnMdAboveOneIsHeldToOneAndSavesLoadably) {
    // md may exceed 1 (an overbright teaching material); the base colour that follows it may not, or the saved
    // scene would not load again.
    const Scene s = parse(R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                          "material": {"md": [1.5, 0.5, 0]}}]})");
    EXPECT_EQ(s.spheres[0].material.md, glm::vec3(1.5f, 0.5f, 0.0f));
    EXPECT_EQ(s.spheres[0].material.baseColor, glm::vec3(1.0f, 0.5f, 0.0f));
    const Scene back = parse(sceneToJson(s));
    EXPECT_EQ(back.spheres[0].material.baseColor, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(back.spheres[0].material.md, glm::vec3(1.5f, 0.5f, 0.0f));
}

TEST(SceneJson, MeshTransformComposesTranslateRotateScale) {
    Scene s = parse(R"({"objects": [
        {"type": "mesh", "source": "a.glb", "transform": {"translate": [1, 2, 3], "rotate": [0, 90, 0], "scale": 2}},
        {"type": "mesh", "source": "b.glb", "transform": {"rotate": [90, 0, 90]}},
        {"type": "mesh", "source": "c.glb", "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 4,5,6,1]},
        {"type": "mesh", "source": "d.glb"}]})");
    ASSERT_EQ(s.meshes.size(), 4u);
    auto apply = [](const glm::mat4& m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); };
    glm::vec3 p = apply(s.meshes[0].transform, {1, 0, 0});  // scale 2, +90° about y: x → -z, then translate
    EXPECT_LT(glm::distance(p, glm::vec3(1, 2, 1)), 1e-5f);
    glm::vec3 q = apply(s.meshes[1].transform, {0, 1, 0});  // X first: y → z; then Z: z stays z
    EXPECT_LT(glm::distance(q, glm::vec3(0, 0, 1)), 1e-5f);
    glm::vec3 r = apply(s.meshes[1].transform, {1, 0, 0});  // X leaves x; then Z: x → y
    EXPECT_LT(glm::distance(r, glm::vec3(0, 1, 0)), 1e-5f);
    EXPECT_EQ(apply(s.meshes[2].transform, {0, 0, 0}), glm::vec3(4, 5, 6));
    EXPECT_EQ(s.meshes[3].transform, glm::mat4(1.0f));
    std::string text = sceneToJson(s);
    EXPECT_NE(text.find("\"matrix\": [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 4.0, 5.0, 6.0, 1.0]"),
              std::string::npos)
        << text;
    nlohmann::json saved = nlohmann::json::parse(text);
    EXPECT_TRUE(saved["objects"][2].contains("matrix"));
    EXPECT_FALSE(saved["objects"][3].contains("matrix")) << "identity is omitted";
    expectRoundTrip(s);
}

TEST(SceneJson, GreyNumbersCommentsVersionAndModel) {
    Scene s = parse(R"(// a comment
        {"shadelab": 1, /* another */ "ambient": 0.15, "model": "blinn-phong",
         "lights": [{"type": "directional", "direction": [0, -2, 0], "color": 2}]})");
    EXPECT_EQ(s.ambient, glm::vec3(0.15f));
    EXPECT_EQ(s.model, ShadingModel::BlinnPhong);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].direction, glm::vec3(0, -1, 0));
    EXPECT_EQ(s.lights[0].color, glm::vec3(2.0f));
    EXPECT_STREQ(toString(*parseShadingModel("phong")), "phong");
    EXPECT_STREQ(toString(*parseShadingModel("blinn-phong")), "blinn-phong");
    EXPECT_FALSE(parseShadingModel("gouraud").has_value());
}

// docs/scene-format.md, "Materials under each model": one model's fields alone give the other model's.
TEST(SceneJson, PbrModelAndMaterialsReadEachOthersFields) {
    Scene s = parse(R"({"model": "pbr", "objects": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": {"md": [0.5, 0.25, 0.125], "s": 62}},
        {"type": "sphere", "center": [0, 1, 0], "radius": 1,
         "material": {"baseColor": [1, 0.5, 0], "metallic": 1, "roughness": 0.5}},
        {"type": "sphere", "center": [0, 1, 0], "radius": 1,
         "material": {"md": 0.2, "baseColor": 0.9, "metallic": 0.5}},
        {"type": "sphere", "center": [0, 1, 0], "radius": 1}]})");
    EXPECT_EQ(s.model, ShadingModel::Pbr);
    EXPECT_FALSE(s.normalized);
    EXPECT_TRUE(parse(R"({"normalized": true})").normalized);
    EXPECT_FALSE(s.environment);
    EXPECT_FALSE(s.energyCompensation);
    EXPECT_TRUE(parse(R"({"energyCompensation": true})").energyCompensation);
    const Scene uniform = parse(R"({"environment": {}})");
    ASSERT_TRUE(uniform.environment);
    EXPECT_EQ(uniform.environment->hdr, "");
    EXPECT_EQ(uniform.environment->intensity, 1.0f);
    const Scene sky = parse(R"({"environment": {"hdr": "../environments/sky.hdr", "intensity": 2, "rotation": 90}})");
    EXPECT_EQ(sky.environment->hdr, "../environments/sky.hdr");
    EXPECT_EQ(sky.environment->intensity, 2.0f);
    EXPECT_EQ(sky.environment->rotation, 90.0f);
    EXPECT_FALSE(parse(R"({"environment": null})").environment);
    EXPECT_STREQ(toString(*parseShadingModel("pbr")), "pbr");
    ASSERT_EQ(s.spheres.size(), 4u);
    const Material& phongOnly = s.spheres[0].material;
    EXPECT_EQ(phongOnly.baseColor, glm::vec3(0.5f, 0.25f, 0.125f));
    EXPECT_EQ(phongOnly.metallic, 0.0f);
    EXPECT_FLOAT_EQ(phongOnly.roughness, std::pow(2.0f / 64.0f, 0.25f));
    EXPECT_FLOAT_EQ(shininessFromRoughness(phongOnly.roughness), 62.0f);
    const Material& pbrOnly = s.spheres[1].material;
    EXPECT_EQ(pbrOnly.md, glm::vec3(0.0f));  // a metal has no diffuse lobe
    EXPECT_EQ(pbrOnly.ma, glm::vec3(0.0f));
    EXPECT_EQ(pbrOnly.ms, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_FLOAT_EQ(pbrOnly.s, 2.0f / 0.0625f - 2.0f);
    const Material& both = s.spheres[2].material;  // each as given, nothing derived
    EXPECT_EQ(both.md, glm::vec3(0.2f));
    EXPECT_EQ(both.baseColor, glm::vec3(0.9f));
    EXPECT_EQ(both.ms, Material{}.ms);
    EXPECT_EQ(both.roughness, Material{}.roughness);
    const Material& neither = s.spheres[3].material;
    EXPECT_EQ(neither.baseColor, neither.md);
    EXPECT_NEAR(neither.roughness, roughnessFromShininess(neither.s), 1e-4f);
    expectRoundTrip(s);
}

// The principled BRDF's parameters: a material's "disney" object sets some, the rest keep Burley's defaults,
// and all of them survive saving and loading (written for a disney material, or any left off the defaults).
TEST(SceneJson, DisneyParametersReadWithDefaultsAndRoundTrip) {
    Scene s = parse(R"({"model": "disney", "objects": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1,
         "material": {"baseColor": [0.8, 0.2, 0.1], "disney": {"clearcoat": 1, "sheen": 0.25, "anisotropic": 0.5}}},
        {"type": "sphere", "center": [3, 1, 0], "radius": 1,
         "material": {"model": "pbr", "disney": {"subsurface": 0.7}}},
        {"type": "sphere", "center": [6, 1, 0], "radius": 1, "material": {"model": "disney"}}]})");
    EXPECT_EQ(s.model, ShadingModel::Disney);
    const DisneyParams& a = s.spheres[0].material.disney;
    EXPECT_EQ(a.clearcoat, 1.0f);
    EXPECT_EQ(a.sheen, 0.25f);
    EXPECT_EQ(a.anisotropic, 0.5f);
    EXPECT_EQ(a.specular, 0.5f);  // Burley's defaults where none is given
    EXPECT_EQ(a.sheenTint, 0.5f);
    EXPECT_EQ(a.clearcoatGloss, 1.0f);
    EXPECT_EQ(s.spheres[1].material.disney.subsurface, 0.7f);  // kept under another model, for a switch back
    EXPECT_EQ(s.spheres[2].material.model, ShadingModel::Disney);
    EXPECT_EQ(s.spheres[2].material.disney, DisneyParams{});
    expectRoundTrip(s);
    // Every parameter at once, each a value of its own, reads back exactly.
    Scene all = s;
    for (int i = 0; i < kDisneyFieldCount; ++i)
        all.spheres[0].material.disney.*kDisneyFields[i].member = 0.1f * float(i + 1);
    expectRoundTrip(all);
    EXPECT_EQ(gWarnings.size(), 0u) << joined(gWarnings);
}

// glTF's clear coat: read with its defaults (no coat), saved only where there is one, read back exactly, also as a
// mesh's override; a misspelt field warns with a hint (a value outside [0, 1]: scene_json_errors_test.cpp).
TEST(SceneJson, ClearcoatReadsSavesOnlyWhereThereIsOneAndRoundTrips) {
    Scene s = parse(R"({"model": "pbr", "objects": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1,
         "material": {"baseColor": [0.8, 0.2, 0.1], "clearcoat": {"factor": 0.75, "roughness": 0.125}}},
        {"type": "sphere", "center": [3, 1, 0], "radius": 1, "material": {"clearcoat": {"factor": 1}}},
        {"type": "sphere", "center": [6, 1, 0], "radius": 1},
        {"type": "mesh", "source": "torus.gltf", "material": {"clearcoat": {"roughness": 0.5}}}]})");
    EXPECT_EQ(s.spheres[0].material.clearcoat, (Clearcoat{0.75f, 0.125f}));
    EXPECT_EQ(s.spheres[1].material.clearcoat, (Clearcoat{1.0f, 0.0f}));  // glTF's default coat roughness
    EXPECT_EQ(s.spheres[2].material.clearcoat, Clearcoat{});
    EXPECT_EQ(s.meshes[0].material.clearcoat.value[1], 0.5f);
    EXPECT_FALSE(s.meshes[0].material.clearcoat.value[0]);
    expectRoundTrip(s);
    const std::string saved = sceneToJson(s);
    size_t coats = 0;
    for (size_t at = saved.find("\"clearcoat\""); at != std::string::npos; at = saved.find("\"clearcoat\"", at + 1))
        ++coats;
    EXPECT_EQ(coats, 3u) << saved;  // the two coats and the override; none where there is no coat
    parse(R"({"objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1,
                           "material": {"clearcoat": {"Factor": 1}}}]})");
    EXPECT_EQ(joined(gWarnings),
              "a.json: objects[0].material.clearcoat: unknown field 'Factor' (ignored); did you mean 'factor'?\n");
}

// glTF's specular layer: read (a factor, a colour above 1), saved where it is off its defaults, read back exactly,
// also as a mesh's override; its packing gives pbr's 0.04 exactly for the index 1.5 (so that a default material
// shades as pbr does), the index's own F0 otherwise, and clamps a tinted F0 at 1.
TEST(SceneJson, SpecularLayerReadsRoundTripsAndPacks) {
    Scene s = parse(R"({"model": "pbr", "objects": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1,
         "material": {"ior": 1.33, "specular": {"factor": 0.5, "color": [2, 1, 0.25]}}},
        {"type": "sphere", "center": [3, 1, 0], "radius": 1},
        {"type": "mesh", "source": "torus.gltf", "material": {"specular": {"factor": 0.25}}}]})");
    const SpecularLayer& a = s.spheres[0].material.specular;
    EXPECT_EQ(a.factor, 0.5f);
    EXPECT_EQ(a.color, glm::vec3(2.0f, 1.0f, 0.25f));
    EXPECT_EQ(s.spheres[1].material.specular, SpecularLayer{});
    EXPECT_FALSE(hasSpecularLayer(s.spheres[1].material.specular, s.spheres[1].material.ior));
    EXPECT_TRUE(hasSpecularLayer(SpecularLayer{}, 1.33f));
    EXPECT_EQ(s.meshes[0].material.specular.factor, 0.25f);
    EXPECT_FALSE(s.meshes[0].material.specular.color);
    expectRoundTrip(s);
    const std::string saved = sceneToJson(s);
    size_t layers = 0;
    const std::string key = "\"specular\": {";  // the layer's object, not the terms' "specular": true
    for (size_t at = saved.find(key); at != std::string::npos; at = saved.find(key, at + 1)) ++layers;
    EXPECT_EQ(layers, 2u) << "the layer and the override; a default layer is not written:\n" << saved;
    EXPECT_EQ(SpecularLayer{}.packed(1.5f), glm::vec4(glm::vec3(0.04f), 1.0f));  // bit for bit pbr's constant
    const glm::vec4 p = a.packed(1.33f);
    const float f0 = float(std::pow((1.33 - 1.0) / (1.33 + 1.0), 2.0));
    EXPECT_NEAR(p.x, 2.0f * f0, 1e-7f);
    EXPECT_NEAR(p.z, 0.25f * f0, 1e-7f);
    EXPECT_EQ(p.w, 0.5f);
    EXPECT_EQ((SpecularLayer{1.0f, glm::vec3(100.0f)}.packed(3.0f).x), 1.0f);  // clamped
}

// glTF's sheen: read with its defaults (none), saved only where there is one, read back exactly, also as a mesh's
// override; a misspelt field warns with a hint.
TEST(SceneJson, SheenReadsSavesOnlyWhereThereIsOneAndRoundTrips) {
    Scene s = parse(R"({"model": "pbr", "objects": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1,
         "material": {"baseColor": [0.1, 0.02, 0.2], "sheen": {"color": [1, 0.75, 0.5], "roughness": 0.3}}},
        {"type": "sphere", "center": [3, 1, 0], "radius": 1, "material": {"sheen": {"color": [0.5, 0.5, 0.5]}}},
        {"type": "sphere", "center": [6, 1, 0], "radius": 1},
        {"type": "mesh", "source": "torus.gltf", "material": {"sheen": {"roughness": 0.5}}}]})");
    EXPECT_EQ(s.spheres[0].material.sheen, (Sheen{{1.0f, 0.75f, 0.5f}, 0.3f}));
    EXPECT_EQ(s.spheres[1].material.sheen, (Sheen{glm::vec3(0.5f), 0.0f}));  // glTF's default sheen roughness
    EXPECT_EQ(s.spheres[2].material.sheen, Sheen{});
    EXPECT_FALSE(s.spheres[2].material.sheen.on());
    EXPECT_EQ(s.meshes[0].material.sheen.roughness, 0.5f);
    EXPECT_FALSE(s.meshes[0].material.sheen.color);
    expectRoundTrip(s);
    const std::string saved = sceneToJson(s);
    size_t sheens = 0;
    for (size_t at = saved.find("\"sheen\""); at != std::string::npos; at = saved.find("\"sheen\"", at + 1)) ++sheens;
    EXPECT_EQ(sheens, 3u) << saved;  // the two sheens and the override; none where there is none
    parse(R"({"objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1,
                           "material": {"sheen": {"colour": [1, 1, 1]}}}]})");
    EXPECT_EQ(joined(gWarnings),
              "a.json: objects[0].material.sheen: unknown field 'colour' (ignored); did you mean 'color'?\n");
}

// glTF's anisotropy: read (a strength, a negative turn), saved only where there is one, read back exactly, also as a
// mesh's override; its packing holds the turn's cosine and sine.
TEST(SceneJson, AnisotropyReadsRoundTripsAndPacks) {
    Scene s = parse(R"({"model": "pbr", "objects": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": {"anisotropy": {"strength": 0.75, "rotation": -1.25}}},
        {"type": "sphere", "center": [3, 1, 0], "radius": 1},
        {"type": "mesh", "source": "torus.gltf", "material": {"anisotropy": {"strength": 0.5}}}]})");
    EXPECT_EQ(s.spheres[0].material.anisotropy, (Anisotropy{0.75f, -1.25f}));
    EXPECT_EQ(s.spheres[1].material.anisotropy, Anisotropy{});
    EXPECT_FALSE(s.spheres[1].material.anisotropy.on());
    EXPECT_FALSE(usesLayeredPbr(s.spheres[1].material));
    EXPECT_TRUE(usesLayeredPbr(s.spheres[0].material));
    EXPECT_EQ(s.meshes[0].material.anisotropy.strength, 0.5f);
    EXPECT_FALSE(s.meshes[0].material.anisotropy.rotation);
    expectRoundTrip(s);
    const std::string saved = sceneToJson(s);
    size_t count = 0;
    for (size_t at = saved.find("\"anisotropy\""); at != std::string::npos; at = saved.find("\"anisotropy\"", at + 1))
        ++count;
    EXPECT_EQ(count, 2u) << saved;  // the anisotropy and the override; none where there is none
    const glm::vec3 p = s.spheres[0].material.anisotropy.packed();
    EXPECT_EQ(p.x, 0.75f);
    EXPECT_NEAR(p.y, std::cos(-1.25f), 1e-7f);
    EXPECT_NEAR(p.z, std::sin(-1.25f), 1e-7f);
}

// glTF's transmission and volume: read, saved only where there are any (an infinite attenuation distance left out),
// read back exactly, also as a mesh's override; under pbr they make the material layered, and a volume alone (no
// transmission) does not (control).
TEST(SceneJson, TransmissionAndVolumeReadAndRoundTrip) {
    Scene s = parse(R"({"model": "pbr", "objects": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": {"transmission": {"factor": 0.875},
         "volume": {"thickness": 2, "attenuationDistance": 0.5, "attenuationColor": [0.25, 0.5, 1]}}},
        {"type": "sphere", "center": [3, 1, 0], "radius": 1, "material": {"volume": {"thickness": 1}}},
        {"type": "mesh", "source": "torus.gltf", "material": {"transmission": {"factor": 0.5},
         "volume": {"attenuationDistance": null}}}]})");
    EXPECT_EQ(s.spheres[0].material.transmission, Transmission{0.875f});
    EXPECT_EQ(s.spheres[0].material.volume, (Volume{2.0f, 0.5f, {0.25f, 0.5f, 1.0f}}));
    EXPECT_TRUE(usesLayeredPbr(s.spheres[0].material));
    EXPECT_FALSE(usesLayeredPbr(s.spheres[1].material));
    EXPECT_TRUE(std::isinf(s.spheres[1].material.volume.attenuationDistance));
    EXPECT_EQ(s.meshes[0].material.transmission.factor, 0.5f);
    // A mesh's override says "absorbs nothing" as null, so that it replaces its glTF material's finite distance.
    ASSERT_TRUE(s.meshes[0].material.volume.attenuationDistance);
    EXPECT_TRUE(std::isinf(*s.meshes[0].material.volume.attenuationDistance));
    expectRoundTrip(s);
    const std::string saved = sceneToJson(s);
    EXPECT_EQ(saved.find("inf"), std::string::npos) << saved;
    size_t count = 0;
    for (size_t at = saved.find("\"transmission\""); at != std::string::npos;
         at = saved.find("\"transmission\"", at + 1))
        ++count;
    EXPECT_EQ(count, 2u) << saved;  // the sphere's and the override; none where there is none
    // The packing: the factor, the lobe's roughness scale from the index, η into the volume; its tint over 2.
    const glm::vec4 p = transmissionPacked(s.spheres[0].material);
    EXPECT_EQ(p, glm::vec4(0.875f, 1.0f, 1.0f / 1.5f, 0.0f));
    EXPECT_NEAR(transmissionTint(s.spheres[0].material).y, 0.5f * 0.5f * 0.5f * 0.5f, 1e-6f);
}

// The largest float is saved as its shortest text, 3.4028235e+38, a double just above FLT_MAX that rounds to it:
// it loads again (found by the scene fuzzer); a number past the rounding boundary is still refused (control).
TEST(SceneJson, TheLargestFloatSavedLoadsAgain) {
    const auto mesh = [](const char* scale) {
        return std::string(R"({"objects": [{"type": "mesh", "source": "m.glb", "transform": {"scale": )") + scale +
               "}}]}";
    };
    Scene s = parse(mesh("3.4028234e38"));
    EXPECT_EQ(s.meshes[0].transform[0][0], FLT_MAX);
    expectRoundTrip(s);
    EXPECT_EQ(parse(mesh("3.4028235e38")).meshes[0].transform[0][0], FLT_MAX);
    EXPECT_THROW(parse(mesh("3.4028236e38")), InputError);
}

TEST(SceneJson, UnknownFieldsWarnWithAHintAndStillLoad) {
    Scene s = parse(R"({"foo": 1, "camera": {"fovy": 30},
        "lights": [{"type": "point", "position": [0, 1, 0], "colour": [1, 0, 0]}], "raster": {"PCF": true},
        "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1,
                     "material": {"ks": 0.5, "zzz": 1, "disney": {"clearCoat": 1}}}]})");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].color, glm::vec3(1.0f));
    EXPECT_EQ(s.camera.fovY, 45.0f);
    std::vector<std::string> expected = {
        "a.json: unknown field 'foo' (ignored)",
        "a.json: camera: unknown field 'fovy' (ignored); did you mean 'fovY'?",
        "a.json: raster: unknown field 'PCF' (ignored); did you mean 'pcf'?",
        "a.json: lights[0]: unknown field 'colour' (ignored); did you mean 'color'?",
        "a.json: objects[0].material: unknown field 'ks' (ignored); did you mean 'ms'?",
        "a.json: objects[0].material: unknown field 'zzz' (ignored)",
        "a.json: objects[0].material.disney: unknown field 'clearCoat' (ignored); did you mean 'clearcoat'?"};
    EXPECT_EQ(joined(gWarnings), joined(expected));
    EXPECT_NO_THROW(parseSceneJson(R"({"foo": 1})", "a.json"));  // no warn callback: silently ignored
}

}  // namespace
}  // namespace shadelab
