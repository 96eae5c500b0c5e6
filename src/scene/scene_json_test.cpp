// Tests for the scene JSON format (scene_json.h, docs/scene-format.md): exact round trips of every shipped
// scene and of randomized scenes (what single fields mean: scene_json_fields_test.cpp; validation errors:
// scene_json_errors_test.cpp). Text only: loadScene() owns files and glTF import.
#include "scene/scene_json.h"
#include "scene/scene_json_test_util.h"
#include "scene/scene_limits.h"

#include "util/input_error.h"
#include "util/read_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab {
namespace {

using test::collectWarning;
using test::Diff;
using test::diffScenes;
using test::expectRoundTrip;
using test::gWarnings;
using test::joined;
using test::parse;

// ---- Round trips -----------------------------------------------------------------------------------------

TEST(SceneJson, EveryShippedSceneRoundTripsExactlyWithoutWarnings) {
    std::filesystem::path dir = std::filesystem::path(SHADELAB_SOURCE_DIR) / "assets" / "scenes";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        gWarnings.clear();
        Scene s = parseSceneJson(readFile(entry.path().string()), entry.path().string(), collectWarning);
        EXPECT_TRUE(gWarnings.empty()) << joined(gWarnings);
        EXPECT_FALSE(s.title.empty());
        EXPECT_FALSE(s.notes.empty());
        // Something lights every lesson: lights, or an emitter (cornell.json's lamp, for the path tracer).
        bool emitter = false;
        for (const Sphere& sp : s.spheres) emitter = emitter || sp.material.emission != glm::vec3(0.0f);
        EXPECT_TRUE(!s.lights.empty() || emitter);
        expectRoundTrip(s);
        ++count;
    }
    EXPECT_GE(count, 3);
}

TEST(SceneJson, DefaultSceneIsTheLectureDemo) {
    std::string path = std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/default.json";
    Scene s = parseSceneJson(readFile(path), path);
    EXPECT_GE(s.spheres.size(), 4u);
    EXPECT_LE(s.spheres.size(), 6u);
    ASSERT_EQ(s.planes.size(), 1u);
    EXPECT_TRUE(s.planes[0].checker.has_value());
    for (const Sphere& sp : s.spheres) EXPECT_FLOAT_EQ(sp.center.y, sp.radius) << sp.name << " rests on y = 0";
}

struct RandomSceneMaker {
    std::mt19937 rng{20240611u};

    float any() {  // awkward values a third of the time, else a random magnitude over many octaves
        static const float awkward[] = {0.1f,        1e-7f, 12345.678f,     1.0f / 3.0f,
                                        0.0f,        -0.0f, 1e-45f,         FLT_MIN,
                                        16777217.0f, 0.3f,  kMaxCoordinate, 1.0f - FLT_EPSILON / 2,
                                        100.0f,      0.7f};
        std::uniform_int_distribution<int> pick(0, 2);
        if (pick(rng) == 0) return awkward[std::uniform_int_distribution<size_t>(0, std::size(awkward) - 1)(rng)];
        float m = std::uniform_real_distribution<float>(-1.0f, 1.0f)(rng);
        return std::ldexp(m, std::uniform_int_distribution<int>(-30, 30)(rng));
    }
    float nonNegative() { return std::abs(any()); }
    float positive() {
        float f = nonNegative();
        return f > 0.0f ? f : 0.25f;
    }
    float in(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    bool coin() { return std::uniform_int_distribution<int>(0, 1)(rng) == 1; }
    int upTo(int n) { return std::uniform_int_distribution<int>(0, n)(rng); }
    glm::vec3 vec() { return {any(), any(), any()}; }
    glm::vec3 rgb() { return {nonNegative(), nonNegative(), nonNegative()}; }
    glm::vec3 unit() { return glm::normalize(glm::vec3(in(-1, 1), in(-1, 1), in(-1, 1)) + glm::vec3(0.01f)); }
    std::string name() {
        static const char* names[] = {"", "key", "fill \"quoted\"", "back\\slash", "ünïcødé ☀", "tab\there", "x"};
        return names[upTo(static_cast<int>(std::size(names)) - 1)];
    }
    Material material() {
        Material m;
        m.ma = rgb(), m.md = rgb(), m.ms = rgb(), m.kr = rgb(), m.kt = rgb();
        m.s = coin() ? in(0.0f, kMaxShininess) : (coin() ? 0.0f : kMaxShininess);
        m.ior = positive();
        m.baseColor = {in(0.0f, 1.0f), in(0.0f, 1.0f), in(0.0f, 1.0f)};
        m.metallic = coin() ? in(0.0f, 1.0f) : 1.0f;
        m.roughness = coin() ? in(0.0f, 1.0f) : 0.0f;
        return m;
    }

    Scene make() {
        Scene s;
        s.title = name(), s.notes = "line one\nline two: 5 < 6 & \"7\"";
        s.camera.position = {in(-50, 50), in(-50, 50), in(-50, 50)};
        s.camera.target = s.camera.position + unit() * in(0.1f, 10.0f);
        s.camera.up = unit();
        s.camera.fovY = coin() ? in(1e-3f, 179.9f) : 0.1f;
        s.model = coin() ? ShadingModel::Phong : coin() ? ShadingModel::BlinnPhong : ShadingModel::Pbr;
        s.normalized = coin();
        s.terms = {coin(), coin(), coin(), coin(), coin()};
        s.ambient = rgb(), s.background = rgb(), s.maxDepth = upTo(64);
        if (coin())
            s.environment = Environment{coin() ? "" : name() + ".hdr", in(0.0f, 10.0f), in(-360.0f, 360.0f), {}};
        s.energyCompensation = coin();
        if (coin()) s.display = {in(-16.0f, 16.0f), coin() ? ViewTransform::Filmic : ViewTransform::Standard};
        if (coin()) {  // else the defaults
            s.raster.shadowMapSize = coin() ? 0 : (coin() ? kMaxShadowMapSize : kMinShadowMapSize + upTo(4000));
            s.raster.depthBias = coin() ? in(0.0f, kMaxShadowBias) : (coin() ? 0.0f : kMaxShadowBias);
            s.raster.normalBias = coin() ? in(0.0f, kMaxShadowBias) : 0.1f;
            s.raster.pcf = coin();
            s.raster.reflectionCubeSize =
                kMinReflectionCubeSize + upTo(kMaxReflectionCubeSize - kMinReflectionCubeSize);
            s.raster.movingPreview = coin();
        }
        for (int i = upTo(kMaxLights); i > 0; --i) {
            Light l;
            l.type = coin() ? LightType::Point : (coin() ? LightType::Directional : LightType::Spot);
            l.name = name(), l.position = vec(), l.direction = unit(), l.color = rgb();
            l.attenuation = {positive(), nonNegative(), nonNegative()};
            if (l.type == LightType::Spot) {
                l.outerConeAngle = in(0.0f, kMaxConeAngle);
                l.innerConeAngle = coin() ? in(0.0f, l.outerConeAngle) : l.outerConeAngle;
            }
            if (l.positional() && coin()) l.range = positive();
            s.lights.push_back(l);
        }
        for (int i = upTo(6); i > 0; --i) s.spheres.push_back({name(), vec(), positive(), material()});
        for (int i = upTo(3); i > 0; --i) {
            Plane p{name(), unit(), any(), material(), std::nullopt};
            if (coin()) p.checker = Checker{rgb(), positive()};
            s.planes.push_back(p);
        }
        for (int i = upTo(3); i > 0; --i) {
            Mesh m;
            m.name = name(), m.source = coin() ? "../models/duck.glb" : "sub dir/ünï.gltf";
            if (coin()) {
                m.transform = glm::translate(glm::mat4(1.0f), vec());
                m.transform = glm::rotate(m.transform, in(-7, 7), unit());
                m.transform = glm::scale(m.transform, glm::vec3(in(0.01f, 100), -in(0.01f, 100), in(0.01f, 100)));
            }
            if (coin()) m.material.ma = rgb();
            if (coin()) m.material.md = rgb();
            if (coin()) m.material.ms = rgb();
            if (coin()) m.material.s = in(0.0f, kMaxShininess);
            if (coin()) m.material.kr = rgb();
            if (coin()) m.material.kt = rgb();
            if (coin()) m.material.ior = positive();
            if (coin()) m.material.baseColor = glm::vec3(in(0.0f, 1.0f), in(0.0f, 1.0f), in(0.0f, 1.0f));
            if (coin()) m.material.metallic = in(0.0f, 1.0f);
            if (coin()) m.material.roughness = in(0.0f, 1.0f);
            s.meshes.push_back(m);
        }
        return s;
    }
};

TEST(SceneJson, RandomizedScenesRoundTripExactly) {
    RandomSceneMaker maker;
    for (int i = 0; i < 50; ++i) {
        SCOPED_TRACE("random scene " + std::to_string(i));
        expectRoundTrip(maker.make());
        if (HasFailure()) break;
    }
}

TEST(SceneJson, DefaultSceneRoundTripsAndEmptyObjectGivesDefaults) {
    expectRoundTrip(Scene{});
    EXPECT_EQ(joined(diffScenes(parse("{}"), Scene{})), "");
}

TEST(SceneJson, SavedFileIsReadableAndComplete) {
    Scene s;
    s.ambient = glm::vec3(0.1f);
    s.spheres.push_back({"ball", {0.0f, 1.0f, 0.0f}, 1.0f, Material{}});
    std::string text = sceneToJson(s);
    EXPECT_NE(text.find("\"ambient\": [0.1, 0.1, 0.1]"), std::string::npos) << text;
    EXPECT_EQ(text.find("0.10000000149"), std::string::npos) << text;
    for (const char* key : {"\"shadelab\": 1", "\"title\"", "\"notes\"", "\"camera\"", "\"fovY\"",
                            "\"model\": \"phong\"", "\"terms\"", "\"reflections\"", "\"background\"", "\"maxDepth\": 5",
                            "\"raster\"", "\"shadowMapSize\": \"auto\"", "\"lights\"", "\"ior\""})
        EXPECT_NE(text.find(key), std::string::npos) << key << "\n" << text;
}

TEST(SceneJson, RasterSettingsRoundTripAndAcceptAutoOrZero) {
    Scene s;
    s.raster = RasterSettings{2048, 0.25f, 3.0f, true, 256};
    std::string text = sceneToJson(s);
    EXPECT_EQ(nlohmann::json::parse(text)["raster"], nlohmann::json::parse(R"({"shadowMapSize": 2048,
        "depthBias": 0.25, "normalBias": 3.0, "pcf": true, "reflectionCubeSize": 256, "movingPreview": true})"))
        << text;
    expectRoundTrip(s);
    s.raster = RasterSettings{kMinShadowMapSize, 0.0f, kMaxShadowBias, false, kMaxReflectionCubeSize, false};
    expectRoundTrip(s);

    Scene a = parse(R"({"raster": {"shadowMapSize": "auto", "pcf": true}})");
    EXPECT_EQ(a.raster.shadowMapSize, 0);
    EXPECT_TRUE(a.raster.pcf);
    EXPECT_EQ(a.raster.depthBias, RasterSettings{}.depthBias) << "fields left out keep their defaults";
    EXPECT_EQ(a.raster.reflectionCubeSize, RasterSettings{}.reflectionCubeSize);
    EXPECT_TRUE(a.raster.movingPreview) << "the viewer's moving preview is on by default";
    EXPECT_FALSE(parse(R"({"raster": {"movingPreview": false}})").raster.movingPreview);
    EXPECT_EQ(parse(R"({"raster": {"shadowMapSize": 0}})").raster.shadowMapSize, 0);
    EXPECT_EQ(parse(R"({"raster": {"shadowMapSize": 512.0}})").raster.shadowMapSize, 512);
    EXPECT_EQ(parse(R"({"raster": {}})").raster.normalBias, RasterSettings{}.normalBias);
    EXPECT_TRUE(gWarnings.empty()) << joined(gWarnings);
    // Negative control: the comparison does see a changed setting.
    Scene b = s;
    b.raster.normalBias = std::nextafter(b.raster.normalBias, 0.0f);
    EXPECT_EQ(joined(diffScenes(s, b)).rfind("raster.normalBias", 0), 0u);
    Scene c = s;
    c.raster.movingPreview = !c.raster.movingPreview;
    EXPECT_EQ(joined(diffScenes(s, c)).rfind("raster.movingPreview", 0), 0u);
}

TEST(SceneJson, SaveWritesTheFile) {
    std::filesystem::create_directories(SHADELAB_TEST_OUTPUT_DIR);
    std::string path = std::string(SHADELAB_TEST_OUTPUT_DIR) + "/saved.json";
    Scene s = RandomSceneMaker().make();
    saveSceneJson(s, path);
    EXPECT_EQ(joined(diffScenes(parseSceneJson(readFile(path), path), s)), "");
}

// ---- Conveniences: plane point, named materials, grey numbers, transforms, comments -------------------------

}  // namespace
}  // namespace shadelab

// "display" is read, written back only when it is not Standard, and an unknown key in it warns.
TEST(SceneJson, DisplayIsReadAndSavedOnlyWhenNotStandard) {
    using namespace shadelab;
    const Scene plain = parseSceneJson("{}", "plain.json");
    EXPECT_TRUE(plain.display.isStandard());
    EXPECT_EQ(sceneToJson(plain).find("\"display\""), std::string::npos);
    const Scene filmic =
        parseSceneJson(R"({"display": {"exposure": -1.25, "viewTransform": "filmic"}})", "filmic.json");
    EXPECT_EQ(filmic.display, (DisplaySettings{-1.25, ViewTransform::Filmic}));
    const std::string saved = sceneToJson(filmic);
    EXPECT_NE(saved.find("\"display\""), std::string::npos) << saved;
    EXPECT_EQ(parseSceneJson(saved, "saved.json").display, filmic.display);
    EXPECT_EQ(parseSceneJson(R"({"display": {"exposure": 2}})", "e.json").display,
              (DisplaySettings{2.0, ViewTransform::Standard}));
}
