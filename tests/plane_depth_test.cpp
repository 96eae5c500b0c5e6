// The ground plane's depth is its exact ray–plane hit (shaders/plane.frag), so where a sphere meets the floor
// the rasterizer hides what the tracer hides. Seen from just above the floor, looking along it, a sphere half
// sunk into the plane and one standing on it agree with the Whitted tracer under the strict design.md §4
// gates. Negative control: the same plane shader with its depth taken halfway to the hit (a floor drawn in
// front of what stands on it, as implementations that interpolate the wedges' w = 0 depth differently do)
// fails the same gates over the spheres' lower parts.
#include "gl/shader_sources.h"
#include "gl_fixture.h"
#include "image/png.h"
#include "render_compare.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 256, kHeight = 160;

Scene lowFloorScene() {
    Scene scene = test::comparisonStage();
    scene.camera.position = {0.0f, 0.25f, 5.0f};  // a quarter unit above the floor
    scene.camera.target = {0.0f, 0.2f, 0.0f};     // looking along it, the horizon just above the middle
    scene.camera.fovY = 40.0f;
    scene.terms = Terms{true, true, true, false, false};  // local terms: no shadow-map edges, no mirrors
    Plane floor;
    floor.material = test::colourMaterial(glm::vec3(0.7f));
    floor.checker = Checker{glm::vec3(0.25f, 0.3f, 0.35f), 0.5f};
    scene.planes.push_back(floor);
    // Half sunk: the floor cuts it through its centre. Beside it, one that touches the floor at one point.
    scene.spheres.push_back({"sunk", {-0.7f, 0.0f, 0.0f}, 0.9f, test::colourMaterial({0.8f, 0.25f, 0.2f})});
    scene.spheres.push_back({"standing", {1.0f, 0.5f, 0.8f}, 0.5f, test::colourMaterial({0.2f, 0.4f, 0.8f})});
    scene.lights.push_back(test::pointLight({-3.0f, 5.0f, 4.0f}, glm::vec3(0.9f)));
    scene.lights.push_back(test::pointLight({4.0f, 2.0f, 3.0f}, glm::vec3(0.4f)));
    return scene;
}

// The embedded shaders written to `dir`, plane.frag's depth line replaced by `depthLine`. Empty when that
// line is not in plane.frag (the control would then test nothing).
std::string shadersWithPlaneDepth(const std::filesystem::path& dir, const std::string& depthLine) {
    std::filesystem::create_directories(dir);
    bool replaced = false;
    for (const gl::EmbeddedShader& s : gl::embeddedShaders()) {
        std::string text = s.text;
        if (std::string(s.name) == "plane.frag") {
            const std::string exact = "gl_FragDepth = depthOf(P);";
            const size_t at = text.find(exact);
            if (at == std::string::npos) return "";
            text.replace(at, exact.size(), depthLine);
            replaced = true;
        }
        std::ofstream(dir / s.name, std::ios::binary) << text;
    }
    return replaced ? dir.string() : "";
}

class PlaneDepth : public test::GlTest {};

TEST_F(PlaneDepth, SpheresOnTheFloorSeenFromLowMatchTheTracer) {
    const Scene scene = lowFloorScene();
    const CompareResult c =
        test::compareWithReference(scene, scene, kWidth, kHeight, std::nullopt, CompareGates{}, "plane_depth_low_view");
    EXPECT_TRUE(c.pass);
    // The image to look at, pass or fail (the evidence beside it is written on failure only).
    writePng(test::outputPath("plane_depth_low_view_raster.png"),
             test::rasterizeWithCoverage(scene, kWidth, kHeight).pixels);
}

TEST_F(PlaneDepth, AFloorInFrontOfItsHitFailsTheGates) {
    const std::filesystem::path dir =
        std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "plane_depth_shaders" / "halfway";
    const std::string shaders = shadersWithPlaneDepth(dir, "gl_FragDepth = depthOf(u_eye.xyz + 0.5f * t * dir);");
    ASSERT_FALSE(shaders.empty()) << "plane.frag no longer writes gl_FragDepth = depthOf(P);";
    raster::RasterRenderer wrong{gl::ShaderLibrary(shaders)};
    const Scene scene = lowFloorScene();
    wrong.uploadMeshes(scene);
    raster::OffscreenOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.coverage = true;
    raster::OffscreenResult out = raster::renderOffscreen(wrong, scene, o);
    const test::Rendered raster{std::move(out.pixels), std::move(out.coverage)};
    const test::Rendered traced = test::traceWithCoverage(scene, kWidth, kHeight, comparisonDepth(scene, std::nullopt));
    const CompareResult c = test::gateWithEvidence(raster, traced, CompareGates{}, "plane_depth_halfway_control");
    EXPECT_FALSE(c.pass) << "a floor drawn in front of the spheres passed the gates";
    // Its evidence (both images, the heatmap) is what the failure leaves; the fraction says it is more than a few
    // pixels: the band along where each sphere meets the floor (about 1 % here).
    EXPECT_GT(c.interior.fractionOver(), 0.005);
}

}  // namespace
