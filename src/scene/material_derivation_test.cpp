// Given and derived material fields (Material::derived, deriveFields): a file's Phong fields derive the pbr ones
// and the other way round, an edit re-derives what follows from it unless that field was given, saving writes
// only the given fields (and Python's document lists the derived ones), and every value survives the round trip.
#include "scene/scene_json.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <string>

using namespace shadelab;

namespace {

Scene sphereWith(const std::string& material) {
    return parseSceneJson(
        R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": )" + material + "}]}",
        "m.json");
}

}  // namespace

TEST(MaterialDerivation, PhongFieldsDeriveThePbrOnesAndTheOtherWayRound) {
    const Material phong = sphereWith(R"({"md": [0.8, 0.2, 0.1], "s": 64})").spheres[0].material;
    EXPECT_EQ(phong.derived, kPbrFields);
    EXPECT_EQ(phong.baseColor, glm::vec3(0.8f, 0.2f, 0.1f));
    EXPECT_FLOAT_EQ(phong.roughness, roughnessFromShininess(64.0f));
    const Material pbr =
        sphereWith(R"({"baseColor": [1, 0.77, 0.34], "metallic": 1, "roughness": 0.3})").spheres[0].material;
    EXPECT_EQ(pbr.derived, kPhongFields);
    EXPECT_EQ(pbr.md, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(pbr.s, shininessFromRoughness(0.3f));
    const Material both =
        sphereWith(R"({"md": [0.5, 0.5, 0.5], "s": 8, "baseColor": [0.9, 0.1, 0.1], "roughness": 0.2})")
            .spheres[0]
            .material;
    EXPECT_EQ(both.derived, 0);  // some of both models' fields: each as given, nothing derived
    EXPECT_EQ(both.baseColor, glm::vec3(0.9f, 0.1f, 0.1f));
    EXPECT_FLOAT_EQ(both.roughness, 0.2f);
}

TEST(MaterialDerivation, AnEditReDerivesWhatFollowsUnlessItWasGiven) {
    Material m = sphereWith(R"({"md": [0.8, 0.2, 0.1], "s": 64})").spheres[0].material;
    Material edited = m;
    edited.s = 2048.0f;
    deriveFields(edited, editedFields(m, edited));
    EXPECT_FLOAT_EQ(edited.roughness, roughnessFromShininess(2048.0f));  // derived: follows s
    // Negative control: once roughness is given (set in the panel), a later s edit leaves it alone.
    Material given = edited;
    given.roughness = 0.6f;
    deriveFields(given, editedFields(edited, given));
    EXPECT_FALSE(given.derived & kFieldRoughness);
    Material later = given;
    later.s = 4.0f;
    deriveFields(later, editedFields(given, later));
    EXPECT_FLOAT_EQ(later.roughness, 0.6f);
    // And a pbr edit of a Phong-given material leaves the Phong fields as given.
    Material base = m;
    base.baseColor = glm::vec3(0.1f, 0.9f, 0.1f);
    deriveFields(base, editedFields(m, base));
    EXPECT_EQ(base.md, glm::vec3(0.8f, 0.2f, 0.1f));
}

TEST(MaterialDerivation, SavingWritesOnlyGivenFieldsAndPythonsDocumentListsTheDerived) {
    const Scene scene = sphereWith(R"({"md": [0.8, 0.2, 0.1], "s": 64})");
    const std::string saved = sceneToJson(scene);
    EXPECT_EQ(saved.find("\"roughness\""), std::string::npos) << saved;
    EXPECT_EQ(saved.find("\"baseColor\""), std::string::npos);
    EXPECT_NE(saved.find("\"s\""), std::string::npos);
    const Scene back = parseSceneJson(saved, "saved.json");
    EXPECT_EQ(back.spheres[0].material.baseColor, scene.spheres[0].material.baseColor);
    EXPECT_EQ(back.spheres[0].material.roughness, scene.spheres[0].material.roughness);
    EXPECT_EQ(back.spheres[0].material.derived, scene.spheres[0].material.derived);
    EXPECT_EQ(sceneToJson(back), saved);

    const std::string document = sceneToJson(scene, true);
    EXPECT_NE(document.find("\"roughness\""), std::string::npos);
    EXPECT_NE(document.find("\"derived\""), std::string::npos);
    const Scene fromDocument = parseSceneJson(document, "document.json");
    EXPECT_EQ(sceneToJson(fromDocument), saved);
    // A document whose s was edited (the list unchanged) derives roughness from the new s; the stale roughness
    // written beside it is not read.
    std::string edited = document;
    const size_t at = edited.find("\"s\": 64");
    ASSERT_NE(at, std::string::npos) << document;
    edited.replace(at, 7, "\"s\": 2048");
    const Material swept = parseSceneJson(edited, "edited.json").spheres[0].material;
    EXPECT_FLOAT_EQ(swept.roughness, roughnessFromShininess(2048.0f));
    EXPECT_EQ(swept.baseColor, glm::vec3(0.8f, 0.2f, 0.1f));
    // Once roughness is given (taken off the list, as Python does when it is set), the base colour still reads
    // as derived from md, and roughness keeps its value (negative control: not re-derived from s).
    std::string given = edited;
    const size_t list = given.find("\"roughness\"", given.find("\"derived\""));
    ASSERT_NE(list, std::string::npos);
    given.replace(list, 11, "\"metallic\"");  // the list names metallic twice now, and roughness no more
    const size_t value = given.find("\"roughness\": ");
    given.replace(value, given.find(',', value) - value, "\"roughness\": 0.6");
    const Material kept = parseSceneJson(given, "given.json").spheres[0].material;
    EXPECT_FLOAT_EQ(kept.roughness, 0.6f);
    EXPECT_EQ(kept.baseColor, glm::vec3(0.8f, 0.2f, 0.1f));
    EXPECT_FALSE(kept.derived & kFieldRoughness);
}

TEST(MaterialDerivation, AnUnknownDerivedFieldIsRefusedWithItsPlace) {
    try {
        sphereWith(R"({"md": [1, 1, 1], "derived": ["shininess"]})");
        FAIL() << "an unknown field name was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[0].material.derived[0]"), std::string::npos) << e.what();
    }
}

TEST(MaterialDerivation, AMaterialEditedUnderBothModelsSavesAndLoadsExactly) {
    Scene scene = sphereWith(R"({"md": [0.8, 0.2, 0.1], "s": 20})");
    Material& m = scene.spheres[0].material;
    const Material before = m;
    m.metallic = 0.7f;  // a pbr field given beside the Phong ones: baseColor and roughness stay derived
    deriveFields(m, editedFields(before, m));
    const Scene back = parseSceneJson(sceneToJson(scene), "both.json");
    const Material& r = back.spheres[0].material;
    EXPECT_EQ(r.baseColor, m.baseColor);
    EXPECT_EQ(r.roughness, m.roughness);
    EXPECT_EQ(r.metallic, 0.7f);
    EXPECT_EQ(r.md, m.md);
    EXPECT_EQ(r.s, m.s);
}

TEST(MaterialDerivation, AMeshOverrideOfBothModelsKeepsTheImportedRest) {
    Material imported;
    imported.baseColor = glm::vec3(0.2f, 0.4f, 0.6f);
    imported.s = 77.0f;
    imported.derived = kPhongFields | kPbrFields;  // as glTF import marks its materials
    MaterialOverride o;
    o.md = glm::vec3(1.0f, 0.0f, 0.0f);
    o.roughness = 0.2f;
    Material m = imported;
    o.applyTo(m);
    EXPECT_EQ(m.baseColor, imported.baseColor);  // not derived from md: both models' fields were given
    EXPECT_EQ(m.s, 77.0f);
    // Control: an override of one model's fields does derive the other's.
    MaterialOverride phongOnly;
    phongOnly.md = glm::vec3(1.0f, 0.0f, 0.0f);
    Material p = imported;
    phongOnly.applyTo(p);
    EXPECT_EQ(p.baseColor, glm::vec3(1.0f, 0.0f, 0.0f));
}
