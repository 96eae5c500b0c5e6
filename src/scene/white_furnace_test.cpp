// whiteFurnaceScene and leaveWhiteFurnace: the furnace sets only background, Ia, lights, terms and
// materials; every material is white; leaving restores the scene exactly (controls: the furnace scene itself,
// and a restore from the wrong scene, must differ).
#include "scene/white_furnace.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"

#include <gtest/gtest.h>

using namespace shadelab;

namespace {

std::string sourcePath(const std::string& rel) { return std::string(SHADELAB_SOURCE_DIR) + "/" + rel; }

void expectWhite(const Material& m, const std::string& where) {
    SCOPED_TRACE(where);
    EXPECT_EQ(m.ma, glm::vec3(1.0f));
    EXPECT_EQ(m.baseColor, glm::vec3(1.0f));
    EXPECT_EQ(m.md + m.ms, glm::vec3(1.0f));
    EXPECT_EQ(m.ms.x, m.ms.y);
    EXPECT_EQ(m.ms.y, m.ms.z);
    EXPECT_EQ(m.kr, glm::vec3(0.0f));
    EXPECT_EQ(m.kt, glm::vec3(0.0f));
}

Scene withMesh() {
    Scene s = loadScene(sourcePath("assets/scenes/default.json"));
    Mesh mesh;
    mesh.name = "two parts";
    MeshPart a, b;
    a.material.ms = glm::vec3(0.9f, 0.6f, 0.3f);
    b.material.ms = glm::vec3(0.1f);
    b.material.kr = glm::vec3(0.5f);
    mesh.parts = {a, b};
    s.meshes.push_back(mesh);
    return s;
}

}  // namespace

TEST(WhiteFurnace, EveryMaterialWhiteUniformEnvironmentNoLights) {
    const Scene scene = withMesh();
    ASSERT_FALSE(scene.lights.empty());
    const Scene f = whiteFurnaceScene(scene);
    EXPECT_EQ(f.background, glm::vec3(1.0f));
    EXPECT_EQ(f.ambient, glm::vec3(1.0f));
    EXPECT_TRUE(f.lights.empty());
    EXPECT_TRUE(f.terms.ambient && f.terms.diffuse && f.terms.specular);
    EXPECT_FALSE(f.terms.shadows || f.terms.reflections);
    for (const Sphere& s : f.spheres) expectWhite(s.material, s.name);
    for (const Plane& p : f.planes) {
        expectWhite(p.material, p.name);
        if (p.checker) {
            EXPECT_EQ(p.checker->md2, p.material.md);
        }
    }
    for (const MeshPart& part : f.meshes.back().parts) expectWhite(part.material, "mesh part");
    EXPECT_NEAR(f.meshes.back().parts[1].material.ms.x, 0.6f, 1e-6f);  // the first part's mean ms, for all
    // The lobe's shape is kept: exponent, roughness and metallic.
    for (size_t i = 0; i < f.spheres.size(); ++i) {
        EXPECT_EQ(f.spheres[i].material.s, scene.spheres[i].material.s);
        EXPECT_EQ(f.spheres[i].material.roughness, scene.spheres[i].material.roughness);
        EXPECT_EQ(f.spheres[i].material.metallic, scene.spheres[i].material.metallic);
    }
    // Nothing else changes.
    EXPECT_EQ(f.camera.position, scene.camera.position);
    EXPECT_EQ(f.model, scene.model);
    EXPECT_EQ(f.spheres.size(), scene.spheres.size());
    EXPECT_EQ(f.title, scene.title);
    // A saved furnace scene (a mesh's override included) loads as the same furnace.
    const std::string torus = sourcePath("assets/scenes/torus.json");
    const Scene furnaceTorus = whiteFurnaceScene(loadScene(torus));
    ASSERT_FALSE(furnaceTorus.meshes.empty());
    Scene reloaded = parseSceneJson(sceneToJson(furnaceTorus), torus);
    importSceneMeshes(reloaded, sourcePath("assets/scenes"));
    EXPECT_EQ(sceneToJson(reloaded), sceneToJson(furnaceTorus));
    expectWhite(reloaded.meshes[0].parts[0].material, "reloaded mesh");
}

TEST(WhiteFurnace, WithoutTheAmbientTermOnlyTheEnvironmentLights) {
    WhiteFurnaceSettings settings;
    settings.ambient = false;
    settings.radiance = 0.5f;
    const Scene f = whiteFurnaceScene(loadScene(sourcePath("assets/scenes/default.json")), settings);
    EXPECT_FALSE(f.terms.ambient);
    EXPECT_EQ(f.ambient, glm::vec3(0.0f));
    EXPECT_EQ(f.background, glm::vec3(0.5f));
}

TEST(WhiteFurnace, LeavingRestoresTheSceneExactly) {
    for (const char* name : {"default", "shininess-row", "three-lights", "torus"}) {
        SCOPED_TRACE(name);
        const Scene scene = loadScene(sourcePath(std::string("assets/scenes/") + name + ".json"));
        const Scene f = whiteFurnaceScene(scene);
        EXPECT_NE(sceneToJson(f), sceneToJson(scene)) << "control: the furnace changes the scene";
        const Scene back = leaveWhiteFurnace(scene, f);
        EXPECT_EQ(sceneToJson(back), sceneToJson(scene));
        for (size_t i = 0; i < scene.meshes.size(); ++i)
            for (size_t k = 0; k < scene.meshes[i].parts.size(); ++k)
                EXPECT_EQ(back.meshes[i].parts[k].material.md, scene.meshes[i].parts[k].material.md);
        // Control: leaving to another scene is not the same scene.
        EXPECT_NE(sceneToJson(leaveWhiteFurnace(f, f)), sceneToJson(scene));
    }
}

TEST(WhiteFurnace, LeavingKeepsTheCameraAndModelChangedMeanwhile) {
    const Scene scene = loadScene(sourcePath("assets/scenes/default.json"));
    Scene f = whiteFurnaceScene(scene);
    f.camera.position += glm::vec3(1.0f, 2.0f, 3.0f);
    f.model = ShadingModel::Pbr;
    f.normalized = !scene.normalized;
    const Scene back = leaveWhiteFurnace(scene, f);
    EXPECT_EQ(back.camera.position, f.camera.position);
    EXPECT_EQ(back.model, ShadingModel::Pbr);
    EXPECT_EQ(back.normalized, f.normalized);
    EXPECT_EQ(back.lights.size(), scene.lights.size());
    EXPECT_EQ(back.background, scene.background);
}
