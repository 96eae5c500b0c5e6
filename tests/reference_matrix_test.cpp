// Raster against reference (issue 3): every combination of {spheres on a checker plane, a glTF mesh} ×
// {ambient, +diffuse, +specular} × {Phong, Blinn-Phong} × {1 white light, 3 coloured lights} ×
// {s = 1, 32, 500} is rendered headless through EGL and by the CPU tracer, and gated as in design.md §4.
// Negative controls below must fail the same gates. Failures leave both images, the heatmap and the
// JSON report in build/test-output/reference_matrix_test/.
#include "gl_fixture.h"
#include "image/compare.h"
#include "image/compare_report.h"
#include "image/encode.h"
#include "raster/offscreen.h"
#include "render_compare.h"
#include "scene/scene_load.h"
#include "trace/trace_image.h"

#include <memory>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 192, kHeight = 128;

enum class Geometry { Spheres, Mesh };
enum class TermSet { Ambient, Diffuse, Specular };
enum class LightRig { OneWhite, ThreeColoured };

struct Case {
    Geometry geometry;
    TermSet terms;
    ShadingModel model;
    LightRig lights;
    float s;
};

std::string caseName(const Case& c) {
    std::string n = c.geometry == Geometry::Spheres ? "spheres" : "mesh";
    n += c.terms == TermSet::Ambient ? "_ambient" : c.terms == TermSet::Diffuse ? "_diffuse" : "_specular";
    n += c.model == ShadingModel::Phong ? "_phong" : "_blinn";
    n += c.lights == LightRig::OneWhite ? "_1white" : "_3coloured";
    return n + "_s" + std::to_string(int(c.s));
}

Scene makeScene(const Case& c) {
    Scene scene = test::comparisonStage();
    scene.model = c.model;
    scene.terms = Terms{true, c.terms != TermSet::Ambient, c.terms == TermSet::Specular, false, false};

    Plane floor;
    floor.material = test::colourMaterial(glm::vec3(0.8f), c.s, 0.6f);
    floor.checker = Checker{glm::vec3(0.25f), 0.75f};
    scene.planes.push_back(floor);
    if (c.geometry == Geometry::Spheres) {
        const glm::vec3 colours[3] = {{0.8f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.3f}, {0.2f, 0.3f, 0.9f}};
        const glm::vec3 centres[3] = {{-1.5f, 0.6f, 0.0f}, {0.0f, 0.8f, -0.6f}, {1.4f, 0.5f, 0.7f}};
        const float radii[3] = {0.6f, 0.8f, 0.5f};
        for (int i = 0; i < 3; ++i)
            scene.spheres.push_back({"", centres[i], radii[i], test::colourMaterial(colours[i], c.s, 0.6f)});
    } else {
        Mesh torus;
        torus.source = test::sourcePath("assets/models/torus.gltf");
        torus.transform[3] = glm::vec4(0.0f, 0.75f, 0.0f, 1.0f);
        torus.material.md = glm::vec3(0.8f, 0.5f, 0.3f);
        torus.material.ma = glm::vec3(0.8f, 0.5f, 0.3f);
        torus.material.ms = glm::vec3(0.6f);
        torus.material.s = c.s;
        scene.meshes.push_back(torus);
        importSceneMeshes(scene, "");
    }
    if (c.lights == LightRig::OneWhite) {
        scene.lights.push_back(test::pointLight({-3.0f, 5.0f, 4.0f}, glm::vec3(1.0f)));
    } else {
        scene.lights.push_back(test::pointLight({-3.0f, 4.0f, 3.0f}, {0.7f, 0.1f, 0.1f}));
        scene.lights.push_back(test::pointLight({3.0f, 5.0f, 2.0f}, {0.1f, 0.6f, 0.1f}));
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, -0.6f));
        sun.color = {0.1f, 0.1f, 0.7f};
        scene.lights.push_back(sun);
    }
    return scene;
}

CompareResult compareRenders(const Scene& rasterScene, const Scene& tracedScene, const std::string& name) {
    return test::gateWithEvidence(test::rasterizeWithCoverage(rasterScene, kWidth, kHeight),
                                  test::traceWithCoverage(tracedScene, kWidth, kHeight), CompareGates{}, name);
}

std::vector<Case> allCases() {
    std::vector<Case> cases;
    for (Geometry g : {Geometry::Spheres, Geometry::Mesh})
        for (TermSet t : {TermSet::Ambient, TermSet::Diffuse, TermSet::Specular})
            for (ShadingModel m : {ShadingModel::Phong, ShadingModel::BlinnPhong})
                for (LightRig l : {LightRig::OneWhite, LightRig::ThreeColoured})
                    for (float s : {1.0f, 32.0f, 500.0f}) cases.push_back({g, t, m, l, s});
    return cases;
}

}  // namespace

class ReferenceMatrix : public test::GlTest, public ::testing::WithParamInterface<Case> {};

TEST_P(ReferenceMatrix, RasterMatchesReference) {
    const Case& c = GetParam();
    Scene scene = makeScene(c);
    CompareResult r = compareRenders(scene, scene, caseName(c));
    EXPECT_TRUE(r.pass) << compareSummary(r);
    RecordProperty("interior_max", r.interior.max);
    RecordProperty("interior_fraction_over", std::to_string(r.interior.fractionOver()));
}

INSTANTIATE_TEST_SUITE_P(AllCombinations, ReferenceMatrix, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& p) { return caseName(p.param); });

// Negative controls: each is one deliberate difference between the two renderers' scenes, and the same
// gates must reject it. If one of these passes, the matrix above proves nothing.
class ReferenceNegativeControls : public test::GlTest {
protected:
    Case base_{Geometry::Spheres, TermSet::Specular, ShadingModel::Phong, LightRig::OneWhite, 32.0f};
};

TEST_F(ReferenceNegativeControls, ShininessTenPercentOffFails) {
    Scene a = makeScene(base_), b = makeScene(base_);
    for (Sphere& s : b.spheres) s.material.s *= 1.1f;
    b.planes[0].material.s *= 1.1f;
    CompareResult r = compareRenders(a, b, "negative_shininess");
    EXPECT_FALSE(r.pass) << "a 10% shininess change passed the gates:\n" << compareSummary(r);
}

// At s = 32 the torus's highlight covers about 20 pixels at this size, so a 10 % change (max 4/255 on 14
// pixels, 0.06 %) is below what a 0.1 % fraction gate can see. At s = 1 the lobe spans the whole mesh and
// the same change must fail. The sphere control above covers s = 32.
TEST_F(ReferenceNegativeControls, MeshShininessTenPercentOffFails) {
    Case c = base_;
    c.geometry = Geometry::Mesh;
    c.s = 1.0f;
    Scene a = makeScene(c), b = makeScene(c);
    for (MeshPart& p : b.meshes[0].parts) p.material.s *= 1.1f;
    CompareResult r = compareRenders(a, b, "negative_mesh_shininess");
    EXPECT_FALSE(r.pass) << "a 10% shininess change on the mesh passed the gates:\n" << compareSummary(r);
}

TEST_F(ReferenceNegativeControls, LightColourChangedFails) {
    Case c = base_;
    c.lights = LightRig::ThreeColoured;
    Scene a = makeScene(c), b = makeScene(c);
    b.lights[1].color = {0.1f, 0.45f, 0.1f};
    CompareResult r = compareRenders(a, b, "negative_light_colour");
    EXPECT_FALSE(r.pass) << "a changed light colour passed the gates:\n" << compareSummary(r);
}

TEST_F(ReferenceNegativeControls, PhongAgainstBlinnPhongFails) {
    Scene a = makeScene(base_), b = makeScene(base_);
    b.model = ShadingModel::BlinnPhong;
    CompareResult r = compareRenders(a, b, "negative_phong_vs_blinn");
    EXPECT_FALSE(r.pass) << "Phong against Blinn-Phong passed the gates:\n" << compareSummary(r);
}
