// Raster planar reflection against the reference: a kr = 0.5 checker mirror under three spheres,
// the tracer at depth 1, gated as design.md §4 with the reflected silhouettes added to the silhouette band;
// a kr that differs between the renderers must fail.
#include "compare/compare_report.h"
#include "compare/image_compare.h"
#include "gl_fixture.h"
#include "image/encode.h"
#include "raster/offscreen.h"
#include "render_compare.h"
#include "scene/coverage.h"
#include "test_output.h"
#include "trace/trace_image.h"

#include <memory>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 192, kHeight = 128;

raster::RasterRenderer& renderer() { return test::sharedRasterRenderer(); }

Scene mirrorScene(float kr) {
    Scene scene = test::comparisonStage();
    scene.terms = Terms{true, true, true, false, true};
    Plane floor;
    floor.material = test::colourMaterial(glm::vec3(0.6f));
    floor.material.kr = glm::vec3(kr);
    floor.checker = Checker{glm::vec3(0.2f), 0.75f};
    scene.planes.push_back(floor);
    const glm::vec3 colours[3] = {{0.8f, 0.2f, 0.2f}, {0.2f, 0.7f, 0.3f}, {0.2f, 0.3f, 0.9f}};
    const glm::vec3 centres[3] = {{-1.5f, 0.7f, 0.0f}, {0.0f, 1.0f, -0.6f}, {1.4f, 0.6f, 0.7f}};
    const float radii[3] = {0.6f, 0.8f, 0.5f};
    for (int i = 0; i < 3; ++i) scene.spheres.push_back({"", centres[i], radii[i], test::colourMaterial(colours[i])});
    Light key;
    key.position = {-3.0f, 5.0f, 4.0f};
    scene.lights.push_back(key);
    return scene;
}

// The scene's mirror image without the mirror: its coverage is what each mirror pixel reflects.
Scene reflectedOnly(Scene scene) {
    const Plane p = scene.planes[0];
    scene.planes.clear();
    for (Sphere& s : scene.spheres) s.center -= 2.0f * (glm::dot(p.normal, s.center) - p.offset) * p.normal;
    return scene;
}

// Mirror pixels get an id that also names the object they reflect, so reflected silhouettes fall into the
// silhouette band of compareImages exactly as direct ones do.
void addReflectedIds(std::vector<uint32_t>& coverage, const std::vector<uint32_t>& reflected, uint32_t mirrorId) {
    for (size_t i = 0; i < coverage.size(); ++i)
        if (coverage[i] == mirrorId) coverage[i] = mirrorId | ((reflected[i] + 1u) << 16);
}

using test::Rendered;

Rendered rasterize(const Scene& scene) { return test::rasterizeWithCoverage(scene, kWidth, kHeight); }
Rendered traceAtDepthOne(const Scene& scene) { return test::traceWithCoverage(scene, kWidth, kHeight, 1); }

// Each renderer supplies its own reflected coverage, from the mirrored scene, so reflected silhouettes fall
// in the silhouette band like direct ones.
CompareResult compareRenders(const Scene& rasterScene, const Scene& tracedScene, const std::string& name,
                             const CompareGates& gates = {}) {
    Rendered a = rasterize(rasterScene), b = traceAtDepthOne(tracedScene);
    const uint32_t mirrorId = planeCoverageId(rasterScene, 0);
    addReflectedIds(a.coverage, rasterize(reflectedOnly(rasterScene)).coverage, mirrorId);
    addReflectedIds(b.coverage, traceAtDepthOne(reflectedOnly(tracedScene)).coverage, mirrorId);
    return test::gateWithEvidence(a, b, gates, name);
}

}  // namespace

class RasterReflection : public test::GlTest {};

TEST_F(RasterReflection, MirrorPlaneMatchesReferenceAtDepthOne) {
    const Scene scene = mirrorScene(0.5f);
    CompareResult r = compareRenders(scene, scene, "reflection_mirror_plane");
    EXPECT_TRUE(r.pass) << compareSummary(r);
}

TEST_F(RasterReflection, MirrorPlaneWithShadowsMatchesReferenceUnderShadowGates) {
    Scene scene = mirrorScene(0.5f);
    scene.terms.shadows = true;
    CompareResult r = compareRenders(scene, scene, "reflection_with_shadows", test::kShadowEdgeGates);
    EXPECT_TRUE(r.pass) << compareSummary(r);
}

TEST_F(RasterReflection, KrDifferingBetweenRenderersFails) {
    CompareResult r = compareRenders(mirrorScene(0.5f), mirrorScene(0.4f), "negative_reflection_kr");
    EXPECT_FALSE(r.pass) << "a kr of 0.5 against 0.4 passed the reflection gates:\n" << compareSummary(r);
}

TEST_F(RasterReflection, ReflectionsOffRendersNoMirror) {
    Scene scene = mirrorScene(0.5f);
    scene.terms.reflections = false;
    Scene plain = scene;
    plain.planes[0].material.kr = glm::vec3(0.0f);
    raster::RasterRenderer& r = renderer();
    r.uploadMeshes(scene);
    const raster::RasterOutput a = raster::renderRaster(r, scene, kWidth, kHeight, false);
    const raster::RasterOutput b = raster::renderRaster(r, plain, kWidth, kHeight, false);
    EXPECT_TRUE(a.color.rgba == b.color.rgba);
}
