// Tests for the scene JSON format (scene_json.h, docs/scene-format.md): exact round trips of every shipped
// scene and of randomized scenes, warnings, and the plane/material/transform conveniences (validation
// errors: scene_json_errors_test.cpp). Text only: loadScene() owns files and glTF import.
#include "scene/scene_json.h"
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

// ---- Field-by-field, bit-exact comparison: the list of differing fields, empty when equal ---------------

struct Diff {
    std::vector<std::string> fields;
    void f(const std::string& name, float a, float b) {
        if (std::memcmp(&a, &b, sizeof a) != 0) fields.push_back(name + " " + str(a) + " vs " + str(b));
    }
    void v(const std::string& name, const glm::vec3& a, const glm::vec3& b) {
        for (int i = 0; i < 3; ++i) f(name + "[" + std::to_string(i) + "]", a[i], b[i]);
    }
    template <class T>
    void eq(const std::string& name, const T& a, const T& b) {
        if (!(a == b)) fields.push_back(name);
    }
    template <class T, class Fn>
    void opt(const std::string& name, const std::optional<T>& a, const std::optional<T>& b, Fn cmp) {
        if (a.has_value() != b.has_value())
            fields.push_back(name + " presence");
        else if (a)
            cmp(name, *a, *b);
    }
    static std::string str(float x) {
        std::ostringstream s;
        s.precision(9);
        s << x;
        return s.str();
    }
    void material(const std::string& p, const Material& a, const Material& b) {
        v(p + ".ma", a.ma, b.ma), v(p + ".md", a.md, b.md), v(p + ".ms", a.ms, b.ms), f(p + ".s", a.s, b.s);
        v(p + ".kr", a.kr, b.kr), v(p + ".kt", a.kt, b.kt), f(p + ".ior", a.ior, b.ior);
        v(p + ".baseColor", a.baseColor, b.baseColor), f(p + ".metallic", a.metallic, b.metallic);
        f(p + ".roughness", a.roughness, b.roughness);
    }
    void materialOverride(const std::string& p, const MaterialOverride& a, const MaterialOverride& b) {
        auto vv = [this](const std::string& n, const glm::vec3& x, const glm::vec3& y) { v(n, x, y); };
        auto ff = [this](const std::string& n, float x, float y) { f(n, x, y); };
        opt(p + ".ma", a.ma, b.ma, vv), opt(p + ".md", a.md, b.md, vv), opt(p + ".ms", a.ms, b.ms, vv);
        opt(p + ".s", a.s, b.s, ff), opt(p + ".kr", a.kr, b.kr, vv), opt(p + ".kt", a.kt, b.kt, vv);
        opt(p + ".ior", a.ior, b.ior, ff), opt(p + ".baseColor", a.baseColor, b.baseColor, vv);
        opt(p + ".metallic", a.metallic, b.metallic, ff), opt(p + ".roughness", a.roughness, b.roughness, ff);
    }
};

std::vector<std::string> diffScenes(const Scene& a, const Scene& b) {
    Diff d;
    d.eq("title", a.title, b.title), d.eq("notes", a.notes, b.notes);
    d.v("camera.position", a.camera.position, b.camera.position);
    d.v("camera.target", a.camera.target, b.camera.target);
    d.v("camera.up", a.camera.up, b.camera.up), d.f("camera.fovY", a.camera.fovY, b.camera.fovY);
    d.eq("model", a.model, b.model);
    d.eq("normalized", a.normalized, b.normalized);
    d.eq("terms.ambient", a.terms.ambient, b.terms.ambient), d.eq("terms.diffuse", a.terms.diffuse, b.terms.diffuse);
    d.eq("terms.specular", a.terms.specular, b.terms.specular);
    d.eq("terms.shadows", a.terms.shadows, b.terms.shadows);
    d.eq("terms.reflections", a.terms.reflections, b.terms.reflections);
    d.v("ambient", a.ambient, b.ambient), d.v("background", a.background, b.background);
    d.eq("environment", a.environment.has_value(), b.environment.has_value());
    if (a.environment && b.environment) {
        d.eq("environment.hdr", a.environment->hdr, b.environment->hdr);
        d.f("environment.intensity", a.environment->intensity, b.environment->intensity);
        d.f("environment.rotation", a.environment->rotation, b.environment->rotation);
    }
    d.eq("energyCompensation", a.energyCompensation, b.energyCompensation);
    d.eq("maxDepth", a.maxDepth, b.maxDepth);
    d.eq("display.exposure", a.display.exposure, b.display.exposure);
    d.eq("display.viewTransform", int(a.display.transform), int(b.display.transform));
    d.eq("raster.shadowMapSize", a.raster.shadowMapSize, b.raster.shadowMapSize);
    d.f("raster.depthBias", a.raster.depthBias, b.raster.depthBias);
    d.f("raster.normalBias", a.raster.normalBias, b.raster.normalBias);
    d.eq("raster.pcf", a.raster.pcf, b.raster.pcf);
    d.eq("raster.reflectionCubeSize", a.raster.reflectionCubeSize, b.raster.reflectionCubeSize);
    d.eq("raster.movingPreview", a.raster.movingPreview, b.raster.movingPreview);
    d.eq("lights.size", a.lights.size(), b.lights.size());
    for (size_t i = 0; i < std::min(a.lights.size(), b.lights.size()); ++i) {
        const Light &x = a.lights[i], &y = b.lights[i];
        std::string p = "lights[" + std::to_string(i) + "]";
        d.eq(p + ".type", x.type, y.type), d.eq(p + ".name", x.name, y.name);
        d.v(p + ".position", x.position, y.position), d.v(p + ".direction", x.direction, y.direction);
        d.v(p + ".color", x.color, y.color), d.v(p + ".attenuation", x.attenuation, y.attenuation);
        d.f(p + ".innerConeAngle", x.innerConeAngle, y.innerConeAngle);
        d.f(p + ".outerConeAngle", x.outerConeAngle, y.outerConeAngle), d.f(p + ".range", x.range, y.range);
    }
    d.eq("spheres.size", a.spheres.size(), b.spheres.size());
    for (size_t i = 0; i < std::min(a.spheres.size(), b.spheres.size()); ++i) {
        const Sphere &x = a.spheres[i], &y = b.spheres[i];
        std::string p = "spheres[" + std::to_string(i) + "]";
        d.eq(p + ".name", x.name, y.name), d.v(p + ".center", x.center, y.center);
        d.f(p + ".radius", x.radius, y.radius), d.material(p + ".material", x.material, y.material);
    }
    d.eq("planes.size", a.planes.size(), b.planes.size());
    for (size_t i = 0; i < std::min(a.planes.size(), b.planes.size()); ++i) {
        const Plane &x = a.planes[i], &y = b.planes[i];
        std::string p = "planes[" + std::to_string(i) + "]";
        d.eq(p + ".name", x.name, y.name), d.v(p + ".normal", x.normal, y.normal);
        d.f(p + ".offset", x.offset, y.offset), d.material(p + ".material", x.material, y.material);
        d.opt(p + ".checker", x.checker, y.checker, [&d](const std::string& n, const Checker& c, const Checker& e) {
            d.v(n + ".md2", c.md2, e.md2), d.f(n + ".size", c.size, e.size);
        });
    }
    d.eq("meshes.size", a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < std::min(a.meshes.size(), b.meshes.size()); ++i) {
        const Mesh &x = a.meshes[i], &y = b.meshes[i];
        std::string p = "meshes[" + std::to_string(i) + "]";
        d.eq(p + ".name", x.name, y.name), d.eq(p + ".source", x.source, y.source);
        for (int k = 0; k < 16; ++k)
            d.f(p + ".transform[" + std::to_string(k) + "]", x.transform[k / 4][k % 4], y.transform[k / 4][k % 4]);
        d.materialOverride(p + ".material", x.material, y.material);
    }
    return d.fields;
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += x + "\n";
    return s;
}

std::vector<std::string> gWarnings;
void collectWarning(const std::string& line) { gWarnings.push_back(line); }

Scene parse(const std::string& text) {
    gWarnings.clear();
    return parseSceneJson(text, "a.json", collectWarning);
}

// Saves, reloads and checks that nothing changed, and that saving again gives the same text.
void expectRoundTrip(const Scene& scene) {
    std::string text = sceneToJson(scene);
    Scene back = parse(text);
    EXPECT_EQ(joined(diffScenes(scene, back)), "") << text;
    EXPECT_EQ(sceneToJson(back), text);
    EXPECT_TRUE(gWarnings.empty()) << joined(gWarnings);
}

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

TEST(SceneJson, UnknownFieldsWarnWithAHintAndStillLoad) {
    Scene s = parse(R"({"foo": 1, "camera": {"fovy": 30},
        "lights": [{"type": "point", "position": [0, 1, 0], "colour": [1, 0, 0]}], "raster": {"PCF": true},
        "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": {"ks": 0.5, "zzz": 1}}]})");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].color, glm::vec3(1.0f));
    EXPECT_EQ(s.camera.fovY, 45.0f);
    std::vector<std::string> expected = {
        "a.json: unknown field 'foo' (ignored)",
        "a.json: camera: unknown field 'fovy' (ignored); did you mean 'fovY'?",
        "a.json: raster: unknown field 'PCF' (ignored); did you mean 'pcf'?",
        "a.json: lights[0]: unknown field 'colour' (ignored); did you mean 'color'?",
        "a.json: objects[0].material: unknown field 'ks' (ignored); did you mean 'ms'?",
        "a.json: objects[0].material: unknown field 'zzz' (ignored)"};
    EXPECT_EQ(joined(gWarnings), joined(expected));
    EXPECT_NO_THROW(parseSceneJson(R"({"foo": 1})", "a.json"));  // no warn callback: silently ignored
}

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
