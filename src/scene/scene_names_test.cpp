// The scene's name tables (shading_model.h, terms.h, light.h): every value has a canonical name that reads
// back, aliases read but are never written, and scene files accept exactly the table's words.
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace shadelab {
namespace {

template <typename E, size_t N>
void expectRoundTrip(const EnumName<E> (&table)[N]) {
    for (const EnumName<E>& e : table) {
        ASSERT_EQ(lookupName(table, e.name), e.value) << e.name;
        if (!e.alias) {
            EXPECT_STREQ(nameOf(table, e.value), e.name);
        }
    }
    EXPECT_FALSE(lookupName(table, "").has_value());
}

TEST(SceneNames, EveryTableRoundTrips) {
    expectRoundTrip(kShadingModelNames);
    expectRoundTrip(kTermNames);
    expectRoundTrip(kLightTypeNames);
    for (Term t : {Term::Ambient, Term::Diffuse, Term::Specular, Term::Shadows, Term::Reflections})
        EXPECT_EQ(parseTerm(toString(t)), t);
    EXPECT_STREQ(toString(LightType::Directional), "directional");
    EXPECT_FALSE(parseTerm("Specular").has_value()) << "names match exactly";
}

TEST(SceneNames, ChoicesListTheCanonicalNamesOnly) {
    EXPECT_EQ(nameChoices(kShadingModelNames), "phong, blinn-phong, pbr or disney");
    EXPECT_EQ(nameChoices(kTermNames), "ambient, diffuse, specular, shadows or reflections");
    EXPECT_EQ(nameChoices(kTermNames, "none"), "ambient, diffuse, specular, shadows, reflections or none");
    EXPECT_EQ(nameChoices(kLightTypeNames), "point, directional or spot");
}

TEST(SceneNames, BlinnIsAnAliasInSceneFilesAsOnTheCommandLine) {
    EXPECT_EQ(parseShadingModel("blinn"), ShadingModel::BlinnPhong);
    EXPECT_STREQ(toString(ShadingModel::BlinnPhong), "blinn-phong");
    const Scene s = parseSceneJson(R"({"model": "blinn"})", "a.json");
    EXPECT_EQ(s.model, ShadingModel::BlinnPhong);
    EXPECT_NE(sceneToJson(s).find(R"("model": "blinn-phong")"), std::string::npos) << "saved canonically";
}

TEST(SceneNames, JsonOneOfNamesThePathAndTheChoices) {
    const nlohmann::json doc = nlohmann::json::parse(R"({"term": "glow", "type": "point"})");
    const std::string file = "a.json";
    const JsonNode root(doc, "", file, nullptr);
    EXPECT_EQ(root.child("type").oneOf(kLightTypeNames, "light type"), LightType::Point);
    try {
        root.child("term").oneOf(kTermNames, "term");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "a.json: term: unknown term 'glow'; expected ambient, diffuse, specular, shadows "
                     "or reflections");
    }
}

}  // namespace
}  // namespace shadelab
