// Raster against reference: every combination of {spheres on a checker plane, a glTF mesh} ×
// {ambient, +diffuse, +specular} × {Phong, Blinn-Phong} × {1 white light, 3 coloured lights} ×
// {s = 1, 32, 500} is rendered headless through EGL and by the CPU tracer, and gated as in design.md §4.
// Negative controls below must fail the same gates. Failures leave both images, the heatmap and the
// JSON report in build/test-output/reference_matrix_test/. The pbr model's matrix: {spheres, mesh} ×
// roughness {0.2, 0.5, 1} × metallic {0, 1} × {1, 3 lights}, its controls, and the model-equality check; the
// disney model's matrix over parameter sets that turn on each of its lobes, with a control per lobe.
#include "compare/compare_report.h"
#include "compare/image_compare.h"
#include "gl_fixture.h"
#include "image/encode.h"
#include "raster/offscreen.h"
#include "render_compare.h"
#include "scene/scene_load.h"
#include "trace/trace_image.h"

#include <algorithm>
#include <cstdlib>
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

// ---- The pbr model -------------------------------------------------------------------------------------
namespace {

struct PbrCase {
    Geometry geometry;
    LightRig lights;
    float roughness;
    float metallic;
};

std::string pbrCaseName(const PbrCase& c) {
    return std::string(c.geometry == Geometry::Spheres ? "spheres" : "mesh") +
           (c.lights == LightRig::OneWhite ? "_1white" : "_3coloured") + "_r" +
           std::to_string(int(c.roughness * 100.0f + 0.5f)) + "_m" + std::to_string(int(c.metallic));
}

// Every material's base colour is its diffuse colour (the checker's second tiles too: md2).
void setPbr(Material& m, float roughness, float metallic) {
    m.baseColor = m.md;
    m.roughness = roughness;
    m.metallic = metallic;
}

Scene makePbrScene(const PbrCase& c) {
    Scene scene = makeScene({c.geometry, TermSet::Specular, ShadingModel::Pbr, c.lights, 32.0f});
    for (Sphere& s : scene.spheres) setPbr(s.material, c.roughness, c.metallic);
    for (Plane& p : scene.planes) setPbr(p.material, c.roughness, c.metallic);
    for (Mesh& m : scene.meshes)
        for (MeshPart& part : m.parts) setPbr(part.material, c.roughness, c.metallic);
    return scene;
}

std::vector<PbrCase> allPbrCases() {
    std::vector<PbrCase> cases;
    for (Geometry g : {Geometry::Spheres, Geometry::Mesh})
        for (LightRig l : {LightRig::OneWhite, LightRig::ThreeColoured})
            for (float r : {0.2f, 0.5f, 1.0f})
                for (float m : {0.0f, 1.0f}) cases.push_back({g, l, r, m});
    return cases;
}

}  // namespace

class ReferencePbr : public test::GlTest, public ::testing::WithParamInterface<PbrCase> {};

TEST_P(ReferencePbr, RasterMatchesReference) {
    const PbrCase& c = GetParam();
    Scene scene = makePbrScene(c);
    CompareResult r = compareRenders(scene, scene, "pbr_" + pbrCaseName(c));
    EXPECT_TRUE(r.pass) << compareSummary(r);
    RecordProperty("interior_max", r.interior.max);
    RecordProperty("interior_fraction_over", std::to_string(r.interior.fractionOver()));
}

INSTANTIATE_TEST_SUITE_P(AllCombinations, ReferencePbr, ::testing::ValuesIn(allPbrCases()),
                         [](const ::testing::TestParamInfo<PbrCase>& p) { return pbrCaseName(p.param); });

TEST_F(ReferenceNegativeControls, PbrRoughnessTenPercentOffFails) {
    const PbrCase c{Geometry::Spheres, LightRig::OneWhite, 0.5f, 0.0f};
    Scene a = makePbrScene(c), b = makePbrScene(c);
    for (Sphere& s : b.spheres) s.material.roughness *= 1.1f;
    b.planes[0].material.roughness *= 1.1f;
    CompareResult r = compareRenders(a, b, "negative_pbr_roughness");
    EXPECT_FALSE(r.pass) << "a 10% roughness change passed the gates:\n" << compareSummary(r);
}

TEST_F(ReferenceNegativeControls, PbrMetallicFlippedFails) {
    const PbrCase c{Geometry::Spheres, LightRig::OneWhite, 0.5f, 0.0f};
    Scene a = makePbrScene(c), b = makePbrScene(c);
    for (Sphere& s : b.spheres) s.material.metallic = 1.0f - s.material.metallic;
    b.planes[0].material.metallic = 1.0f - b.planes[0].material.metallic;
    CompareResult r = compareRenders(a, b, "negative_pbr_metallic");
    EXPECT_FALSE(r.pass) << "flipping metallic passed the gates:\n" << compareSummary(r);
}

namespace {

// The disney model's matrix: {spheres, mesh} × {1, 3 lights} × five parameter sets that between them turn on
// every lobe (the defaults; subsurface and sheen; a clearcoat; an anisotropic metal; a rough, tinted specular).
struct DisneyCase {
    Geometry geometry;
    LightRig lights;
    const char* name;
    float roughness, metallic;
    DisneyParams params;
};

DisneyParams disneyWith(std::initializer_list<std::pair<float DisneyParams::*, float>> values) {
    DisneyParams p;
    for (const auto& [member, value] : values) p.*member = value;
    return p;
}

Scene makeDisneyScene(const DisneyCase& c) {
    Scene scene = makeScene({c.geometry, TermSet::Specular, ShadingModel::Disney, c.lights, 32.0f});
    const auto set = [&](Material& m) {
        setPbr(m, c.roughness, c.metallic);
        m.disney = c.params;
    };
    for (Sphere& s : scene.spheres) set(s.material);
    for (Plane& p : scene.planes) set(p.material);
    for (Mesh& m : scene.meshes)
        for (MeshPart& part : m.parts) set(part.material);
    // Where each lobe shows: a coat on dark paint, and both the coat and the sheen at grazing angles, under a
    // light behind the objects.
    if (c.params.clearcoat > 0.0f)
        for (Sphere& s : scene.spheres) s.material.baseColor *= 0.15f;
    if (c.params.sheen > 0.0f || c.params.clearcoat > 0.0f)
        scene.lights.push_back(test::pointLight({0.5f, 2.5f, -5.0f}, glm::vec3(0.35f)));
    return scene;
}

std::vector<DisneyCase> allDisneyCases() {
    using P = DisneyParams;
    const DisneyCase sets[] = {
        {Geometry::Spheres, LightRig::OneWhite, "defaults", 0.5f, 0.0f, P{}},
        {Geometry::Spheres, LightRig::OneWhite, "subsurface_sheen", 0.6f, 0.0f,
         disneyWith({{&P::subsurface, 1.0f}, {&P::sheen, 1.0f}, {&P::sheenTint, 0.5f}})},
        {Geometry::Spheres, LightRig::OneWhite, "clearcoat", 0.5f, 0.0f,
         disneyWith({{&P::clearcoat, 1.0f}, {&P::clearcoatGloss, 0.7f}})},
        {Geometry::Spheres, LightRig::OneWhite, "anisotropic_metal", 0.4f, 1.0f, disneyWith({{&P::anisotropic, 0.8f}})},
        {Geometry::Spheres, LightRig::OneWhite, "rough_tinted", 1.0f, 0.0f,
         disneyWith({{&P::specular, 1.0f}, {&P::specularTint, 1.0f}})},
    };
    std::vector<DisneyCase> cases;
    for (Geometry g : {Geometry::Spheres, Geometry::Mesh})
        for (LightRig l : {LightRig::OneWhite, LightRig::ThreeColoured})
            for (DisneyCase c : sets) {
                c.geometry = g;
                c.lights = l;
                cases.push_back(c);
            }
    return cases;
}

std::string disneyCaseName(const DisneyCase& c) {
    return std::string(c.geometry == Geometry::Spheres ? "spheres" : "mesh") +
           (c.lights == LightRig::OneWhite ? "_1white_" : "_3coloured_") + c.name;
}

}  // namespace

class ReferenceDisney : public test::GlTest, public ::testing::WithParamInterface<DisneyCase> {};

TEST_P(ReferenceDisney, RasterMatchesReference) {
    const DisneyCase& c = GetParam();
    Scene scene = makeDisneyScene(c);
    CompareResult r = compareRenders(scene, scene, "disney_" + disneyCaseName(c));
    EXPECT_TRUE(r.pass) << compareSummary(r);
    RecordProperty("interior_max", r.interior.max);
    RecordProperty("interior_fraction_over", std::to_string(r.interior.fractionOver()));
}

INSTANTIATE_TEST_SUITE_P(AllCombinations, ReferenceDisney, ::testing::ValuesIn(allDisneyCases()),
                         [](const ::testing::TestParamInfo<DisneyCase>& p) { return disneyCaseName(p.param); });

// The gates see each lobe: a clearcoat 30 % weaker, an anisotropy 0.1 lower, the sheen dropped. Disney's coat is a
// quarter-weight lobe with F0 = 0.04: 10 % of it moves fewer pixels by 3/255 than the gates' 0.1 % (the shader
// sweep, GlslDisneyEqualsCppOverSweep, notices 0.1 of it exactly).
TEST_F(ReferenceNegativeControls, DisneyLobeChangesFail) {
    const std::vector<DisneyCase> cases = allDisneyCases();
    const auto find = [&](const char* name) {
        return *std::find_if(cases.begin(), cases.end(),
                             [&](const DisneyCase& c) { return c.name == std::string(name); });
    };
    struct Control {
        const char* base;
        float DisneyParams::*member;
        float factor, offset;
    };
    const Control controls[] = {{"clearcoat", &DisneyParams::clearcoat, 0.7f, 0.0f},
                                {"anisotropic_metal", &DisneyParams::anisotropic, 1.0f, -0.1f},
                                {"subsurface_sheen", &DisneyParams::sheen, 0.0f, 0.0f}};
    for (const Control& k : controls) {
        const DisneyCase c = find(k.base);
        Scene a = makeDisneyScene(c), b = makeDisneyScene(c);
        for (Sphere& s : b.spheres) s.material.disney.*k.member = s.material.disney.*k.member * k.factor + k.offset;
        b.planes[0].material.disney.*k.member = b.planes[0].material.disney.*k.member * k.factor + k.offset;
        CompareResult r = compareRenders(a, b, std::string("negative_disney_") + k.base);
        EXPECT_FALSE(r.pass) << k.base << ": the changed lobe passed the gates:\n" << compareSummary(r);
    }
}

// design.md §7, model equality: with π-scaled lights a Lambertian scene (no specular term) renders the same
// under phong, blinn-phong and pbr, in each renderer, pixel for pixel. White and coloured lights, the
// checker floor, spheres and the mesh, with ambient and shadows on.
class ModelEquality : public test::GlTest {};

TEST_F(ModelEquality, LambertianSceneIsIdenticalUnderEveryModel) {
    for (Geometry g : {Geometry::Spheres, Geometry::Mesh}) {
        Scene scene = makeScene({g, TermSet::Diffuse, ShadingModel::Phong, LightRig::ThreeColoured, 32.0f});
        scene.terms.shadows = true;
        for (Sphere& s : scene.spheres) setPbr(s.material, 0.5f, 0.0f);
        for (Plane& p : scene.planes) setPbr(p.material, 0.5f, 0.0f);
        for (Mesh& m : scene.meshes)
            for (MeshPart& part : m.parts) setPbr(part.material, 0.5f, 0.0f);
        std::vector<Rendered> raster, traced;
        for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
            scene.model = model;
            raster.push_back(test::rasterizeWithCoverage(scene, kWidth, kHeight));
            traced.push_back(test::traceWithCoverage(scene, kWidth, kHeight));
        }
        for (size_t k = 1; k < raster.size(); ++k) {
            int worstRaster = 0, worstTraced = 0;
            for (size_t i = 0; i < raster[0].pixels.data.size(); ++i) {
                worstRaster =
                    std::max(worstRaster, std::abs(int(raster[k].pixels.data[i]) - int(raster[0].pixels.data[i])));
                worstTraced =
                    std::max(worstTraced, std::abs(int(traced[k].pixels.data[i]) - int(traced[0].pixels.data[i])));
            }
            EXPECT_EQ(worstRaster, 0) << "raster, model " << k << " against phong";
            EXPECT_EQ(worstTraced, 0) << "tracer, model " << k << " against phong";
        }
    }
}

// design.md §7's normalised lobes: the factor reaches both renderers (it scales ms in surfaceParams).
class ReferenceNormalized : public test::GlTest {};

TEST_F(ReferenceNormalized, NormalizedLobesMatchTheReference) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong})
        for (float s : {32.0f, 500.0f}) {
            Case c{Geometry::Spheres, TermSet::Specular, ShadingModel::Phong, LightRig::OneWhite, 32.0f};
            c.model = model;
            c.s = s;
            Scene scene = makeScene(c);
            scene.normalized = true;
            for (Sphere& sp : scene.spheres) sp.material.ms = glm::vec3(0.05f);  // keep the peak near 1
            scene.planes[0].material.ms = glm::vec3(0.05f);
            CompareResult r = compareRenders(scene, scene, "normalized_" + caseName(c));
            EXPECT_TRUE(r.pass) << caseName(c) << "\n" << compareSummary(r);
        }
}

TEST_F(ReferenceNegativeControls, NormalizedInOneRendererOnlyFails) {
    Scene a = makeScene(base_), b = makeScene(base_);
    b.normalized = true;
    CompareResult r = compareRenders(a, b, "negative_normalized");
    EXPECT_FALSE(r.pass) << "a normalised lobe in one renderer passed the gates:\n" << compareSummary(r);
}
