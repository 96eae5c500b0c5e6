// The viewer's partial redraw (raster_renderer.h setPartialRedraw, redraw_plan.h): after material edits, a
// renderer that redraws only the edited objects (and re-renders only the touched parts of environment
// cubes) must give bit for bit the colour and coverage of a renderer that draws everything.
#include "gl_fixture.h"
#include "image/encode.h"
#include "image/png.h"
#include "raster/raster_renderer.h"
#include "scene/scene_load.h"
#include "test_output.h"
#include "trace/trace_test_util.h"

#include <cstring>
#include <functional>
#include <string>

using namespace shadelab;

namespace {

constexpr int kWidth = 320, kHeight = 180;

struct Drawn {
    ImageF color;
    std::vector<uint32_t> coverage;
};

Drawn drawWith(raster::RasterRenderer& r, const Scene& scene) {
    r.draw(scene, kWidth, kHeight, true);
    Drawn d;
    r.target().readColor(d.color);
    r.target().readCoverage(d.coverage);
    return d;
}

// Pixels whose colour differs in any bit.
size_t differingPixels(const ImageF& a, const ImageF& b) {
    size_t n = 0;
    for (size_t i = 0; i + 4 <= a.rgba.size() && i + 4 <= b.rgba.size(); i += 4)
        n += std::memcmp(&a.rgba[i], &b.rgba[i], 4 * sizeof(float)) != 0;
    return n + (a.rgba.size() != b.rgba.size() ? 1 : 0);
}

void writeEvidence(const std::string& name, const Drawn& partial, const Drawn& full) {
    writePng(test::outputPath(name + "_partial.png"),
             toImage8(partial.color, Encoding::Srgb, DisplaySettings{}, nullptr));
    writePng(test::outputPath(name + "_full.png"), toImage8(full.color, Encoding::Srgb, DisplaySettings{}, nullptr));
}

// The lecture scene plus a mesh of two icosphere parts, the first a mirror (its own environment cube).
Scene lessonWithMesh() {
    Scene scene = loadScene(test::sourcePath("assets/scenes/default.json"));
    Material chrome;
    chrome.md = glm::vec3(0.1f);
    chrome.ms = glm::vec3(0.8f);
    chrome.s = 200.0f;
    chrome.kr = glm::vec3(0.5f);
    Material clay;
    clay.md = glm::vec3(0.6f, 0.4f, 0.3f);
    Mesh mesh;
    mesh.name = "icospheres";
    mesh.parts.push_back(trace::test::icospherePart({-0.6f, 0.4f, 2.8f}, 0.4f, 2, chrome));
    mesh.parts.push_back(trace::test::icospherePart({0.9f, 0.35f, 2.9f}, 0.35f, 2, clay));
    scene.meshes.push_back(mesh);
    return scene;
}

struct Edit {
    std::string name;
    std::function<void(Scene&)> apply;
    bool partial;  // what the edited renderer should have done
};

}  // namespace

class RasterPartial : public test::GlTest {};

TEST_F(RasterPartial, MaterialEditsRedrawOnlyTheirObjectsBitForBit) {
    Scene scene = lessonWithMesh();
    raster::RasterRenderer edited, full;
    edited.setPartialRedraw(true);
    edited.uploadMeshes(scene);
    full.uploadMeshes(scene);
    Drawn before = drawWith(edited, scene);
    EXPECT_FALSE(edited.lastDraw().partial);

    const std::vector<Edit> edits = {
        {"shininess", [](Scene& s) { s.spheres[0].material.s = 77.0f; }, true},
        {"mirror_own_material", [](Scene& s) { s.spheres[4].material.ms = glm::vec3(0.5f); }, true},
        {"two_spheres", [](Scene& s) { s.spheres[1].material.md *= 0.5f, s.spheres[3].material.s = 8.0f; }, true},
        {"floor_checker", [](Scene& s) { s.planes[0].checker->md2 = glm::vec3(0.4f); }, true},
        {"mirror_mesh_part", [](Scene& s) { s.meshes[0].parts[0].material.ms = glm::vec3(0.3f); }, true},
        {"plain_mesh_part", [](Scene& s) { s.meshes[0].parts[1].material.s = 3.0f; }, true},
        {"nothing", [](Scene&) {}, true},
        {"camera", [](Scene& s) { s.camera.position.x += 0.3f; }, false},
        {"after_camera", [](Scene& s) { s.spheres[2].material.md = glm::vec3(0.9f); }, true},
        {"light", [](Scene& s) { s.lights[0].position.y += 1.0f; }, false},
        {"after_light", [](Scene& s) { s.spheres[0].material.kr = glm::vec3(0.2f); }, true},  // a new mirror
    };
    for (const Edit& e : edits) {
        e.apply(scene);
        const Drawn partial = drawWith(edited, scene);
        EXPECT_EQ(edited.lastDraw().partial, e.partial) << e.name;
        const Drawn reference = drawWith(full, scene);
        const size_t diff = differingPixels(partial.color, reference.color);
        EXPECT_EQ(diff, 0u) << e.name << ": " << diff << " pixels differ; images in " << test::outputPath("");
        EXPECT_TRUE(partial.coverage == reference.coverage) << e.name;
        if (diff) writeEvidence("partial_" + e.name, partial, reference);
        // Negative control: every edit but "nothing" changes pixels, so keeping the last image would fail.
        if (e.name != "nothing") {
            EXPECT_GT(differingPixels(before.color, reference.color), 50u) << e.name;
        }
        before = reference;
    }
}

// Jittered samples go to their own target: the centre image and its coverage stay, and redrawing the same
// state afterwards draws nothing.
TEST_F(RasterPartial, SamplesLeaveTheCentreImage) {
    const Scene scene = loadScene(test::sourcePath("assets/scenes/default.json"));
    raster::RasterRenderer r;
    r.setPartialRedraw(true);
    r.uploadMeshes(scene);
    const Drawn centre = drawWith(r, scene);
    ImageF sample;
    r.drawSample(scene, kWidth, kHeight, glm::vec2(0.375f, -0.125f)).readColor(sample);
    // Control: the sample really is another image.
    EXPECT_GT(differingPixels(sample, centre.color), 100u);
    const Drawn again = drawWith(r, scene);
    EXPECT_TRUE(r.lastDraw().partial);
    EXPECT_EQ(r.lastDraw().partialIds, 0);
    EXPECT_EQ(differingPixels(again.color, centre.color), 0u);
    EXPECT_TRUE(again.coverage == centre.coverage);
    // invalidate() makes the next draw a full one, with the same pixels.
    r.invalidate();
    const Drawn redrawn = drawWith(r, scene);
    EXPECT_FALSE(r.lastDraw().partial);
    EXPECT_EQ(differingPixels(redrawn.color, centre.color), 0u);
}
