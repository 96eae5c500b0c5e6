// loadScene: glTF/GLB files as scenes (framing, default rig, their own camera and lights), errors, and
// importSceneMeshes with transforms and material overrides.
#include "scene/camera_choice.h"
#include "scene/gltf/gltf_test_util.h"
#include "scene/scene_json.h"

#include <filesystem>
#include <fstream>

namespace shadelab {
namespace {

using namespace gltftest;
namespace fs = std::filesystem;
void expectFramed(const Camera& c, const Bounds& b, float aspect) {
    const glm::vec3 f = glm::normalize(c.target - c.position);
    const glm::vec3 r = glm::normalize(glm::cross(f, c.up));
    const glm::vec3 u = glm::cross(r, f);
    const float tanY = std::tan(glm::radians(c.fovY) / 2);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
        const glm::vec3 d = corner - c.position;
        const float z = glm::dot(d, f);
        ASSERT_GT(z, 0.0f);
        EXPECT_LE(std::abs(glm::dot(d, u)) / z, tanY) << "corner " << i;
        EXPECT_LE(std::abs(glm::dot(d, r)) / z, tanY * aspect) << "corner " << i;
    }
}

TEST(SceneLoad, GlbIsFramedAndLit) {
    REQUIRE_MODELS();
    // BoxTextured.glb has no camera and no lights, so both come from its bounds.
    const std::string path = model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
    const Scene s = loadScene(path);
    EXPECT_EQ(s.title, "BoxTextured.glb");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].name, "BoxTextured");
    EXPECT_EQ(s.meshes[0].source, path);
    EXPECT_EQ(s.meshes[0].triangleCount(), 12u);
    EXPECT_TRUE(s.planes.empty());
    EXPECT_TRUE(s.spheres.empty());
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);

    const Bounds b = sceneBounds(s);
    ASSERT_FALSE(b.empty());
    expectFramed(s.camera, b, 16.0f / 9.0f);
    expectFramed(s.camera, b, 1.0f);
    // Seen from the front (+z) and above; key light above the model.
    EXPECT_GT(s.camera.position.z, b.hi.z);
    EXPECT_GT(s.camera.position.y, b.hi.y);
    EXPECT_GT(s.lights[0].position.y, b.hi.y);
}

TEST(SceneLoad, GlbKeepsItsOwnCameraAndLights) {
    REQUIRE_MODELS();
    // 2CylinderEngine.glb has a perspective camera (yfov 0.3143463730812073) and no lights.
    Scene s = loadScene(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    EXPECT_EQ(s.meshes[0].triangleCount(), 121496u);
    // Opened framed to fit (45°); the file's camera is kept for --camera file|0 (camera_choice.h).
    ASSERT_EQ(s.modelCameras.size(), 1u);
    EXPECT_NEAR(s.modelCameras[0].fovY, glm::degrees(0.3143463730812073f), 1e-4f);
    EXPECT_FLOAT_EQ(s.camera.fovY, 45.0f);
    expectFramed(s.camera, sceneBounds(s), 16.0f / 9.0f);
    const std::string file = "2CylinderEngine.glb";
    EXPECT_FLOAT_EQ(chooseCamera(s, *parseCameraChoice("file"), file).fovY, s.modelCameras[0].fovY);
    EXPECT_FLOAT_EQ(chooseCamera(s, *parseCameraChoice("0"), file).fovY, s.modelCameras[0].fovY);
    expectNear(chooseCamera(s, *parseCameraChoice("fit"), file).position, s.camera.position);
    try {
        chooseCamera(s, *parseCameraChoice("1"), file);
        FAIL() << "camera 1 does not exist";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "2CylinderEngine.glb: camera 1: the model has 1 camera (0)");
    }
    EXPECT_EQ(s.lights.size(), 2u);

    const std::string nodes =
        "[{\"mesh\":0},{\"translation\":[0,3,0],"
        "\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}]";
    const std::string extra = ",\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\"}]}}";
    s = loadScene(writeGltf("lit.gltf", quad(), nodes, "[0,1]", extra));
    ASSERT_EQ(s.lights.size(), 1u);
    expectNear(s.lights[0].position, {0, 3, 0});
    expectNear(s.lights[0].color, glm::vec3(1.0f));
}

TEST(SceneLoad, CameraChoiceWords) {
    EXPECT_EQ(parseCameraChoice("fit")->kind, CameraChoice::Kind::Fit);
    EXPECT_EQ(parseCameraChoice("file")->kind, CameraChoice::Kind::File);
    EXPECT_EQ(parseCameraChoice("12")->index, 12);
    for (const char* bad : {"", "-1", "1000", "3x", "Fit", " 1"}) EXPECT_FALSE(parseCameraChoice(bad)) << bad;
    Scene s;  // a scene file: its own camera is "file"; it has no glTF cameras
    s.camera.position = glm::vec3(1, 2, 3);
    expectNear(chooseCamera(s, *parseCameraChoice("file"), "s.json").position, {1, 2, 3});
    EXPECT_THROW(chooseCamera(s, *parseCameraChoice("0"), "s.json"), InputError);
    // Nothing bounded to fit (no spheres or meshes): the camera stays.
    expectNear(chooseCamera(s, *parseCameraChoice("fit"), "s.json").position, {1, 2, 3});
}

TEST(SceneLoad, ErrorsNameTheFile) {
    const fs::path dir(SHADELAB_TEST_OUTPUT_DIR);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.txt") << "hello";
    try {
        loadScene((dir / "scene.txt").string());
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "unknown scene type")) << e.what();
    }
    try {
        loadScene("/no/such/scene.json");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "/no/such/scene.json: no such file");
    }
}

TEST(SceneLoad, ImportSceneMeshesAppliesTransformAndOverride) {
    writeGltf("scene_quad.gltf", quad(), "[{\"mesh\":0}]");
    Scene s;
    Mesh m;
    m.source = "scene_quad.gltf";
    m.transform[3] = glm::vec4(0, 0, 7, 1);
    m.material.md = glm::vec3(0.1f, 0.2f, 0.3f);
    s.meshes.push_back(m);
    importSceneMeshes(s, SHADELAB_TEST_OUTPUT_DIR);
    ASSERT_EQ(s.meshes[0].parts.size(), 1u);
    expectNear(s.meshes[0].parts[0].geometry->positions[2], {1, 1, 7});
    expectNear(s.meshes[0].parts[0].material.md, {0.1f, 0.2f, 0.3f});
    expectNear(s.meshes[0].parts[0].material.ms, Material{}.ms);  // not overridden: the default material's

    s.meshes[0].source = "missing.glb";
    EXPECT_THROW(importSceneMeshes(s, SHADELAB_TEST_OUTPUT_DIR), InputError);
}

TEST(SceneLoad, BoundsFramingAndRig) {
    Bounds empty;
    EXPECT_TRUE(empty.empty());
    const Camera fallback = frameBounds(empty);
    expectNear(fallback.position, Camera{}.position);

    Scene s;
    s.spheres.push_back({"a", {0, 0, 0}, 1.0f, {}});
    s.spheres.push_back({"b", {10, 0, 0}, 2.0f, {}});
    s.planes.push_back({});  // unbounded; ignored
    const Bounds b = sceneBounds(s);
    expectNear(b.lo, {-1, -2, -2});
    expectNear(b.hi, {12, 2, 2});
    for (float fov : {20.0f, 45.0f, 90.0f}) {
        SCOPED_TRACE(fov);
        const Camera c = frameBounds(b, fov);
        EXPECT_FLOAT_EQ(c.fovY, fov);
        expectNear(c.target, {5.5f, 0, 0});
        expectFramed(c, b, 16.0f / 9.0f);
    }
    const std::vector<Light> rig = defaultLightRig(b);
    ASSERT_EQ(rig.size(), 2u);
    EXPECT_GT(rig[0].color.r, rig[0].color.b);  // warm key
    EXPECT_LT(rig[1].color.r, rig[1].color.b);  // cool fill
    EXPECT_GT(glm::length(rig[0].color), glm::length(rig[1].color));
}

}  // namespace
}  // namespace shadelab

namespace shadelab {
namespace {

// A glTF model's metallic-roughness materials survive the scene file: saved (the model as a mesh
// with its pbr fields overridden on one mesh) and loaded back, every part's baseColor, metallic and
// roughness are the same, and untouched parts keep the values imported from the file.
TEST(SceneLoad, GltfPbrMaterialsRoundTripThroughTheSceneFile) {
    REQUIRE_MODELS();
    const std::string engine = model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    Scene s = loadScene(engine);
    s.model = ShadingModel::Pbr;
    ASSERT_EQ(s.meshes.size(), 1u);
    std::vector<Material> imported;
    for (const MeshPart& p : s.meshes[0].parts) imported.push_back(p.material);
    const std::string text = sceneToJson(s);
    const fs::path dir(SHADELAB_TEST_OUTPUT_DIR);
    fs::create_directories(dir);
    const fs::path saved = dir / "engine_pbr_saved.json";
    std::ofstream(saved) << text;
    Scene back = loadScene(saved.string());
    EXPECT_EQ(back.model, ShadingModel::Pbr);
    ASSERT_EQ(back.meshes[0].parts.size(), imported.size());
    for (size_t i = 0; i < imported.size(); ++i) {
        expectNear(back.meshes[0].parts[i].material.baseColor, imported[i].baseColor);
        EXPECT_FLOAT_EQ(back.meshes[0].parts[i].material.metallic, imported[i].metallic);
        EXPECT_FLOAT_EQ(back.meshes[0].parts[i].material.roughness, imported[i].roughness);
    }
    // An edit of the pbr fields is an override in the file, and reads back exactly.
    back.meshes[0].material.baseColor = glm::vec3(0.9f, 0.5f, 0.1f);
    back.meshes[0].material.metallic = 1.0f;
    back.meshes[0].material.roughness = 0.3f;
    std::ofstream(saved) << sceneToJson(back);
    const Scene edited = loadScene(saved.string());
    for (const MeshPart& p : edited.meshes[0].parts) {
        expectNear(p.material.baseColor, {0.9f, 0.5f, 0.1f});
        EXPECT_FLOAT_EQ(p.material.metallic, 1.0f);
        EXPECT_FLOAT_EQ(p.material.roughness, 0.3f);
    }
    // Negative control: the engine's own materials are not all that edit.
    bool differs = false;
    for (const Material& m : imported) differs |= m.metallic != 1.0f || m.roughness != 0.3f;
    EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace shadelab
