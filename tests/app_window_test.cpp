// Tests of the real viewer window under Xvfb (issue 4): after 30 frames its screenshot equals the
// headless `shadelab render` of the same scene and size; a scripted shininess change changes the
// screenshot and matches the headless render of the changed scene; the probe on a known pixel reports
// the object and the NoL of the shared C++ shading; a broken shader reload keeps the last good program; the
// raster flags and the setRaster action give the images `shadelab render` gives with those settings.
// Every comparison has a negative control. Without xvfb-run the tests report SKIPPED with the reason.
#include "image/compare.h"
#include "image/compare_report.h"
#include "image/png.h"
#include "scene/coverage.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "shading/lighting.h"
#include "test_output.h"
#include "util/atomic_file.h"
#include "util/read_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

constexpr const char* kSize = "320x180";
constexpr int kW = 320, kH = 180;

struct Result {
    int code = -1;
    std::string out;  // stdout and stderr together
};

Result shell(const std::string& cmd) {
    Result r;
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    while (size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

std::string binary() { return SHADELAB_BINARY; }

// The viewer in a fresh X server of its own. The screen is larger than any window the tests open.
Result view(const std::string& args, const std::string& env = "") {
    return shell(env + "xvfb-run -a -s '-screen 0 1920x1200x24' " + binary() + " view " + args);
}

Result render(const std::string& scene, const std::string& out, const std::string& flags = "") {
    return shell(binary() + " render " + scene + " --size " + kSize + " -o " + out + " " + flags);
}

bool haveXvfb() { return shell("command -v xvfb-run").code == 0; }

#define REQUIRE_XVFB() \
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found: apt-get install xvfb xauth (scripts/install-deps.sh)"

std::string writeText(const std::string& name, const std::string& text) {
    const std::string path = test::outputPath(name);
    writeFileAtomic(path, text);
    return path;
}

// Exact equality expected (same renderer, same shared conversion), plus the design.md §4 gates; on
// failure both images, the heatmap and the report stay in build/test-output.
void expectSameImage(const std::string& stem, const std::string& pathA, const std::string& pathB) {
    const Image8 a = readPng(pathA), b = readPng(pathB);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    const CompareResult r = compareImages(a, b);
    const bool exact = a.data == b.data;
    if (!exact || !r.pass) {
        const std::vector<std::string> files = writeCompareEvidence(test::outputPath(stem), a, b, r);
        ADD_FAILURE() << pathA << " vs " << pathB << (exact ? "" : ": not byte-identical") << "\n"
                      << compareSummary(r) << "evidence: " << files[0] << " ...";
    }
}

bool sameBytes(const std::string& pathA, const std::string& pathB) {
    return readPng(pathA).data == readPng(pathB).data;
}

glm::ivec2 pixelOf(const Scene& scene, const glm::vec3& p) {
    const ViewSetup v = makeViewSetup(scene, kW, kH);
    const glm::vec4 clip = v.viewProj * glm::vec4(p, 1.0f);
    return {int(std::floor((clip.x / clip.w * 0.5f + 0.5f) * float(kW))),
            int(std::floor((1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * float(kH)))};
}

}  // namespace

TEST(AppWindow, HelpAndNoDisplayNeedNoWindow) {
    Result help = shell("env -u DISPLAY -u WAYLAND_DISPLAY " + binary() + " view --help");
    EXPECT_EQ(help.code, 0) << help.out;
    EXPECT_NE(help.out.find("--screenshot"), std::string::npos);
    Result none = shell("env -u DISPLAY -u WAYLAND_DISPLAY " + binary() + " view " +
                        test::sourcePath("assets/scenes/default.json"));
    EXPECT_EQ(none.code, 1) << none.out;
    EXPECT_EQ(std::count(none.out.begin(), none.out.end(), '\n'), 1) << none.out;
    EXPECT_NE(none.out.find("shadelab render"), std::string::npos) << none.out;
    Result usage = shell(binary() + " view --size 0x10");
    EXPECT_EQ(usage.code, 2) << usage.out;
    // The raster flags are render's (cli/raster_flags.h): same names, ranges and messages.
    EXPECT_NE(help.out.find("--reflection-cube-size N"), std::string::npos) << help.out;
    Result badFlag = shell(binary() + " view --shadow-map-size 5");
    EXPECT_EQ(badFlag.code, 2) << badFlag.out;
    EXPECT_NE(badFlag.out.find("--shadow-map-size: expected auto or a whole number from 16 to 8192, got '5'"),
              std::string::npos)
        << badFlag.out;
    Result badScript =
        shell("env DISPLAY=:0 " + binary() + " view --script " + writeText("bad.json", "[{\"action\": 1}]"));
    EXPECT_EQ(badScript.code, 1) << badScript.out;
    EXPECT_NE(badScript.out.find("bad.json: actions[0].action:"), std::string::npos) << badScript.out;
}

TEST(AppWindow, ScreenshotAfter30FramesEqualsHeadlessRender) {
    REQUIRE_XVFB();
    for (const char* name : {"default", "torus"}) {
        SCOPED_TRACE(name);
        const std::string scene = test::sourcePath(std::string("assets/scenes/") + name + ".json");
        const std::string shot = test::outputPath(std::string(name) + "_view.png");
        const std::string ref = test::outputPath(std::string(name) + "_render.png");
        fs::remove(shot);
        Result v = view(scene + " --size " + kSize + " --frames 30 --screenshot " + shot);
        ASSERT_EQ(v.code, 0) << v.out;
        Result r = render(scene, ref);
        ASSERT_EQ(r.code, 0) << r.out;
        expectSameImage(std::string(name) + "_unchanged", shot, ref);
    }
}

TEST(AppWindow, ScriptedShininessChangeMatchesHeadlessRenderOfChangedScene) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string before = test::outputPath("shininess_before.png");
    const std::string after = test::outputPath("shininess_after.png");
    const std::string saved = test::outputPath("shininess_saved.json");
    const std::string script = writeText("shininess_script.json", R"({"actions": [
        {"frame": 10, "action": "screenshot", "path": ")" + before + R"("},
        {"frame": 12, "action": "setShininess", "object": "red plastic", "s": 4},
        {"frame": 14, "action": "saveScene", "path": ")" + saved + R"("}
    ]})");
    Result v = view(scenePath + " --size " + kSize + " --frames 30 --script " + script + " --screenshot " + after);
    ASSERT_EQ(v.code, 0) << v.out;

    // The changed scene, made independently, rendered headlessly.
    Scene changed = loadScene(scenePath);
    for (Sphere& s : changed.spheres)
        if (s.name == "red plastic") s.material.s = 4.0f;
    const std::string changedJson = sceneToJson(changed);
    const std::string changedPath = writeText("shininess_changed.json", changedJson);
    const std::string expected = test::outputPath("shininess_expected.png");
    ASSERT_EQ(render(changedPath, expected).code, 0);
    const std::string unchanged = test::outputPath("shininess_unchanged_render.png");
    ASSERT_EQ(render(scenePath, unchanged).code, 0);

    expectSameImage("shininess_after", after, expected);
    expectSameImage("shininess_before", before, unchanged);
    // Negative controls: the change is visible, in both directions.
    EXPECT_FALSE(sameBytes(before, after)) << "the shininess change did not change the screenshot";
    EXPECT_FALSE(sameBytes(before, expected)) << "the unchanged screenshot equals the changed scene's render";
    EXPECT_FALSE(sameBytes(after, unchanged));
    // What the viewer saved is the changed scene.
    EXPECT_EQ(sceneToJson(parseSceneJson(readFile(saved), saved)), changedJson);
}

TEST(AppWindow, RasterFlagsAndSetRasterMatchHeadlessRenders) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string flagged = test::outputPath("raster_view_flags.png");
    const std::string scripted = test::outputPath("raster_view_script.png");
    const std::string script = writeText("raster_script.json", R"({"actions": [
        {"frame": 5, "action": "screenshot", "path": ")" + flagged +
                                                                   R"("},
        {"frame": 6, "action": "setRaster", "shadowMapSize": "auto", "pcf": false, "reflectionCubeSize": 8}
    ]})");
    Result v = view(scenePath + " --size " + kSize + " --frames 10 --pcf --shadow-map-size 16 --script " + script +
                    " --screenshot " + scripted);
    ASSERT_EQ(v.code, 0) << v.out;
    const std::string expectFlagged = test::outputPath("raster_render_flags.png");
    const std::string expectScripted = test::outputPath("raster_render_cube8.png");
    const std::string plain = test::outputPath("raster_render_plain.png");
    ASSERT_EQ(render(scenePath, expectFlagged, "--pcf --shadow-map-size 16").code, 0);
    ASSERT_EQ(render(scenePath, expectScripted, "--reflection-cube-size 8").code, 0);
    ASSERT_EQ(render(scenePath, plain).code, 0);
    expectSameImage("raster_view_flags", flagged, expectFlagged);
    expectSameImage("raster_view_script", scripted, expectScripted);
    // Negative controls: each setting is visible.
    EXPECT_FALSE(sameBytes(flagged, plain)) << "--pcf --shadow-map-size 16 did not reach the viewer's scene";
    EXPECT_FALSE(sameBytes(scripted, plain)) << "setRaster reflectionCubeSize 8 did not change the image";
}

TEST(AppWindow, ProbeReportsObjectAndNoLOfSharedShading) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const Scene scene = loadScene(scenePath);
    size_t green = 0;
    while (green < scene.spheres.size() && scene.spheres[green].name != "matte green") ++green;
    ASSERT_LT(green, scene.spheres.size());
    const Sphere& sphere = scene.spheres[green];
    const glm::ivec2 px = pixelOf(scene, sphere.center + glm::vec3(-0.3f, 0.4f, 0.0f));
    const std::string onSphere = test::outputPath("probe_sphere.json");
    const std::string onFloor = test::outputPath("probe_floor.json");
    const std::string script = writeText("probe_script.json",
                                         "["
                                         R"({"frame": 2, "action": "probe", "x": )" +
                                             std::to_string(px.x) + R"(, "y": )" + std::to_string(px.y) +
                                             "},"
                                             R"({"action": "probeReport", "path": ")" +
                                             onSphere +
                                             R"("},)"
                                             R"({"action": "probe", "x": 160, "y": 175},)"
                                             R"({"action": "probeReport", "path": ")" +
                                             onFloor + R"("}])");
    Result v = view(scenePath + " --size " + kSize + " --frames 5 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;

    const nlohmann::json j = nlohmann::json::parse(readFile(onSphere));
    const uint32_t id = sphereCoverageId(scene, green);
    ASSERT_TRUE(j["hit"].get<bool>()) << j.dump();
    EXPECT_EQ(j["object"]["id"].get<uint32_t>(), id);
    EXPECT_EQ(j["coverage_id"].get<uint32_t>(), id) << "the rasterizer's coverage disagrees with the probe";
    // The C++ shading's NoL for this pixel, computed here from the shared functions.
    const ViewSetup vs = makeViewSetup(scene, kW, kH);
    const glm::vec3 dir = shading::cameraRayDirection(vs.forward, vs.right, vs.up, vs.tanHalfFovY, float(kW), float(kH),
                                                      px.x + 0.5f, px.y + 0.5f);
    const float t = shading::intersectSphere(vs.eye, dir, sphere.center, sphere.radius, 0.0f);
    ASSERT_GT(t, 0.0f);
    const glm::vec3 P = vs.eye + t * dir;
    const glm::vec3 N = glm::normalize(shading::faceForward((P - sphere.center) / sphere.radius, -dir));
    ASSERT_EQ(j["lights"].size(), scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const float NoL = glm::dot(N, glm::normalize(scene.lights[i].position - P));
        EXPECT_NEAR(j["lights"][i]["NoL"].get<float>(), NoL, 1e-5f) << "light " << i;
    }
    // Negative control: the floor pixel reports the plane, with another NoL.
    const nlohmann::json f = nlohmann::json::parse(readFile(onFloor));
    EXPECT_EQ(f["object"]["kind"], "plane");
    EXPECT_EQ(f["coverage_id"].get<uint32_t>(), planeCoverageId(scene, 0));
    EXPECT_GT(std::fabs(f["lights"][0]["NoL"].get<float>() - j["lights"][0]["NoL"].get<float>()), 1e-2f);
}

TEST(AppWindow, BrokenShaderReloadKeepsLastGoodProgram) {
    REQUIRE_XVFB();
    const fs::path broken = test::outputPath("broken_shaders");
    fs::remove_all(broken);
    fs::copy(test::sourcePath("shaders"), broken);
    { std::ofstream(broken / "sphere.frag", std::ios::app) << "this is not GLSL;\n"; }
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string shot = test::outputPath("reload_view.png");
    const std::string ref = test::outputPath("reload_render.png");
    const std::string script = writeText(
        "reload_script.json", R"([{"frame": 3, "action": "reloadShaders", "dir": ")" + broken.string() + R"("}])");
    Result v = view(scenePath + " --size " + kSize + " --frames 8 --script " + script + " --screenshot " + shot);
    ASSERT_EQ(v.code, 0) << v.out;
    EXPECT_NE(v.out.find("sphere.frag: line"), std::string::npos) << "the error should name file and line: " << v.out;
    ASSERT_EQ(render(scenePath, ref).code, 0);
    expectSameImage("reload", shot, ref);
}

TEST(AppWindow, ResizingKeepsRenderingCorrect) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string shot = test::outputPath("resize_view.png");
    const std::string small = test::outputPath("resize_small.png");
    const std::string script = writeText("resize_script.json", R"([
        {"frame": 2, "action": "resizeWindow", "width": 200, "height": 120},
        {"frame": 6, "action": "windowScreenshot", "path": ")" + small +
                                                                   R"("},
        {"frame": 8, "action": "resizeWindow", "width": 1, "height": 1},
        {"frame": 12, "action": "resizeWindow", "width": 900, "height": 600}])");
    // A fixed --size renders the same pixels at any window size; the window only shows them scaled.
    Result v = view(scenePath + " --size " + kSize + " --frames 20 --script " + script + " --screenshot " + shot);
    ASSERT_EQ(v.code, 0) << v.out;
    EXPECT_EQ(readPng(small).width, 200) << "the window did not shrink";
    const std::string ref = test::outputPath("resize_render.png");
    ASSERT_EQ(render(scenePath, ref).code, 0);
    expectSameImage("resize", shot, ref);
}

TEST(AppWindow, ProgressiveReferenceCompletesWhileTheWindowRuns) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string window = test::outputPath("difference_window.png");
    const std::string script = writeText("reference_script.json", R"([
        {"frame": 1, "action": "setMode", "mode": "difference"},
        {"action": "waitReference", "timeout": 120},
        {"action": "windowScreenshot", "path": ")" + window + R"("}])");
    Result v = view(scenePath + " --size 160x90 --frames 3 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    EXPECT_TRUE(fs::exists(window));
}

// Global mode: the path tracer in the window draws exactly what `shadelab render --renderer path` draws with
// the same number of samples (it is deterministic for any thread count and split into passes).
TEST(AppWindow, GlobalModeEqualsTheHeadlessPathTracer) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/local-vs-global.json");
    const std::string shot = test::outputPath("global_window.png");
    const std::string script = writeText("global_script.json", R"([
        {"frame": 1, "action": "setMode", "mode": "global"},
        {"action": "waitReference", "timeout": 120},
        {"action": "referenceScreenshot", "path": ")" + shot + R"("}])");
    Result v = view(scenePath + " --size 160x90 --frames 3 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    const std::string marker = "path traced, ";
    const size_t at = v.out.find(marker);
    ASSERT_NE(at, std::string::npos) << v.out;
    const int spp = std::atoi(v.out.c_str() + at + marker.size());
    ASSERT_GE(spp, 1) << v.out;
    const std::string headless = test::outputPath("global_headless.png");
    Result r = shell(binary() + " render " + scenePath + " --size 160x90 --renderer path --spp " + std::to_string(spp) +
                     " -o " + headless);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(sameBytes(shot, headless)) << spp << " samples: " << shot << " vs " << headless;
    // Negative control: one sample more is another image.
    Result more = shell(binary() + " render " + scenePath + " --size 160x90 --renderer path --spp " +
                        std::to_string(spp + 1) + " -o " + headless);
    ASSERT_EQ(more.code, 0) << more.out;
    EXPECT_FALSE(sameBytes(shot, headless));
}

TEST(AppWindow, TracedGlassTreeExitsPromptlyAfterItsFrames) {
    // Issue 11: 45 spheres with kr = kt = 1 at depth 64, every pixel glass. Before the ray tree was bounded
    // and cancellable inside a tree, the reference workers never stopped and the viewer never exited;
    // `timeout` turns such a hang into a failure (exit code 124) instead of a stuck test.
    REQUIRE_XVFB();
    const std::string script =
        writeText("glass_tree_script.json", R"([{"frame": 0, "action": "setMode", "mode": "traced"}])");
    const auto t0 = std::chrono::steady_clock::now();
    Result v = view(test::sourcePath("bench/glass-tree.json") + " --size 320x180 --frames 5 --script " + script,
                    "timeout 60 ");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("viewer, glass tree in Traced mode, --frames 5: exited after %.2f s (X server start included)\n",
                seconds);
    ASSERT_EQ(v.code, 0) << v.out;
}

TEST(AppWindow, UndoRestoresARemovedLightExactly) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string before = test::outputPath("undo_before.png"), removed = test::outputPath("undo_removed.png");
    const std::string undone = test::outputPath("undo_undone.png"), redone = test::outputPath("undo_redone.png");
    const std::string script = writeText("undo_script.json", R"({"actions": [
        {"frame": 4, "action": "screenshot", "path": ")" + before +
                                                                 R"("},
        {"frame": 5, "action": "removeLight", "index": 0},
        {"frame": 7, "action": "screenshot", "path": ")" + removed +
                                                                 R"("},
        {"frame": 8, "action": "orbit", "yaw": 0},
        {"frame": 9, "action": "undo"},
        {"frame": 11, "action": "screenshot", "path": ")" + undone +
                                                                 R"("},
        {"frame": 12, "action": "redo"},
        {"frame": 14, "action": "screenshot", "path": ")" + redone +
                                                                 R"("}
    ]})");
    Result v = view(scenePath + " --size " + kSize + " --frames 16 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    EXPECT_TRUE(sameBytes(before, undone)) << "undo did not restore the removed light exactly";
    EXPECT_TRUE(sameBytes(removed, redone)) << "redo did not remove it again";
    EXPECT_FALSE(sameBytes(before, removed)) << "negative control: removing the light changed nothing";
}

TEST(AppWindow, SaveNeverWritesOverAModel) {
    REQUIRE_XVFB();
    const std::string model = test::outputPath("save_target.gltf");
    fs::copy_file(test::sourcePath("assets/models/torus.gltf"), model, fs::copy_options::overwrite_existing);
    const std::string original = readFile(model);
    const std::string script =
        writeText("save_model_script.json", R"([{"action": "saveScene", "path": ")" + model + R"("}])");
    Result v =
        view(test::sourcePath("assets/scenes/default.json") + " --size " + kSize + " --frames 3 --script " + script);
    EXPECT_EQ(v.code, 1) << v.out;
    EXPECT_NE(v.out.find("refusing to save scene JSON over a glTF model"), std::string::npos) << v.out;
    EXPECT_EQ(readFile(model), original) << "the model was changed";
}

TEST(AppWindow, ProjectorScaleKeepsTheWindowsShape) {
    // Issue 15: at --ui-scale 2 the panel took half the window and the image became a cropped portrait.
    // Now a panel wider than a third of the window lies over the image, which keeps the window's shape.
    REQUIRE_XVFB();
    auto shapes = [&](const std::string& name, const std::string& flags) {
        const std::string shot = test::outputPath(name + "_image.png"), window = test::outputPath(name + "_window.png");
        Result v = view(test::sourcePath("assets/scenes/default.json") + " --frames 3 " + flags + " --screenshot " +
                        shot + " --window-screenshot " + window);
        EXPECT_EQ(v.code, 0) << v.out;
        const Image8 image = readPng(shot), win = readPng(window);
        return std::pair<double, double>(double(image.width) / image.height, double(win.width) / win.height);
    };
    const auto [image2, window2] = shapes("projector_scale2", "--ui-scale 2");
    EXPECT_NEAR(image2, window2, 0.01) << "at UI scale 2 the image must have the window's aspect ratio";
    EXPECT_GT(image2, 1.0) << "a landscape window gives a landscape image";
    const auto [imageP, windowP] = shapes("projector_flag", "--projector");
    EXPECT_NEAR(imageP, windowP, 0.01);
    EXPECT_NEAR(windowP, 16.0 / 9.0, 0.02) << "--projector opens a 16:9 window";
    // Negative control: at UI scale 1 the panel sits beside the image, which is then narrower than the window.
    const auto [image1, window1] = shapes("projector_scale1", "--ui-scale 1");
    EXPECT_LT(image1, window1 - 0.1);
}

TEST(AppWindow, DraggingALightMarkerMovesTheLightAndItsShadow) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    Scene scene = loadScene(scenePath);
    // Bring the key light into the frame first (it sits above it), where its marker can be grabbed.
    scene.lights[0].position = glm::vec3(-2.0f, 3.0f, 2.0f);
    const glm::ivec2 from = pixelOf(scene, scene.lights[0].position);
    const glm::ivec2 to(from.x + 90, from.y + 10);
    ASSERT_TRUE(from.x > 0 && from.y > 0 && to.x < kW && to.y < kH) << from.x << "," << from.y;
    const std::string before = test::outputPath("light_drag_before.png"),
                      after = test::outputPath("light_drag_after.png");
    const std::string saved = test::outputPath("light_drag_saved.json");
    const std::string script = writeText("light_drag_script.json", R"([
        {"frame": 1, "action": "setLight", "index": 0, "position": [-2, 3, 2]},
        {"frame": 3, "action": "screenshot", "path": ")" + before + R"("},
        {"action": "drag", "x0": )" + std::to_string(from.x) + R"(, "y0": )" +
                                                                       std::to_string(from.y) + R"(, "x1": )" +
                                                                       std::to_string(to.x) + R"(, "y1": )" +
                                                                       std::to_string(to.y) + R"(},
        {"action": "screenshot", "path": ")" + after + R"("},
        {"action": "saveScene", "path": ")" + saved + R"("}])");
    Result v = view(scenePath + " --size " + kSize + " --frames 4 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    const Scene moved = parseSceneJson(readFile(saved), saved);
    const glm::vec3 p = moved.lights[0].position;
    EXPECT_GT(glm::length(p - scene.lights[0].position), 0.3f) << "the drag did not move the light";
    // It went where the pointer went: it projects onto the drag's end, at the same depth from the camera.
    const glm::ivec2 landed = pixelOf(moved, p);
    EXPECT_LE(std::abs(landed.x - to.x), 1) << landed.x;
    EXPECT_LE(std::abs(landed.y - to.y), 1) << landed.y;
    const ViewSetup view = makeViewSetup(scene, kW, kH);
    EXPECT_NEAR(glm::dot(p - view.eye, view.forward), glm::dot(scene.lights[0].position - view.eye, view.forward),
                1e-3f);
    // The screenshot is the moved scene's render, and differs from before (its highlights and shadows moved).
    const std::string expected = test::outputPath("light_drag_expected.png");
    ASSERT_EQ(render(saved, expected).code, 0);
    expectSameImage("light_drag_after", after, expected);
    EXPECT_FALSE(sameBytes(before, after)) << "negative control: the drag changed nothing on screen";
}

TEST(AppWindow, StillFrameAccumulatesToTheSupersampledRender) {
    // Issue 15: while the view is still, the viewer accumulates the 16 grid samples of --spp 16, so edges,
    // shadow boundaries and the checker are smooth; screenshots and --screenshot stay the 1-spp render.
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string smooth = test::outputPath("smooth_view.png"), plain = test::outputPath("smooth_plain_view.png");
    const std::string script = writeText("smooth_script.json", R"([
        {"frame": 1, "action": "smoothScreenshot", "path": ")" + smooth +
                                                                   R"("},
        {"action": "screenshot", "path": ")" + plain + R"("}])");
    Result v = view(scenePath + " --size " + kSize + " --frames 2 --verbose --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    EXPECT_NE(v.out.find("smooth frame, 16 samples"), std::string::npos) << v.out;
    const std::string ss16 = test::outputPath("smooth_render_spp16.png"),
                      ss1 = test::outputPath("smooth_render_spp1.png");
    ASSERT_EQ(render(scenePath, ss16, "--spp 16").code, 0);
    ASSERT_EQ(render(scenePath, ss1).code, 0);
    // The same samples averaged in another order: within 1/255 (a running average in float against a box
    // filter of the k-times image), and within the design.md §4 gates.
    const CompareResult same = compareImages(readPng(smooth), readPng(ss16));
    if (!same.pass || same.all.max > 1)
        ADD_FAILURE() << compareSummary(same) << "evidence: "
                      << writeCompareEvidence(test::outputPath("smooth_vs_spp16"), readPng(smooth), readPng(ss16),
                                              same)[0];
    EXPECT_TRUE(sameBytes(plain, ss1)) << "a screenshot is still the 1-spp image 'shadelab render' gives";
    // Negative control: the smooth frame is not the aliased one.
    EXPECT_FALSE(sameBytes(smooth, ss1));
    const CompareResult aliased = compareImages(readPng(smooth), readPng(ss1));
    EXPECT_FALSE(aliased.pass) << "the 1-spp render should fail the gates against the smooth frame";
}

TEST(AppWindow, WhiteFurnaceRoundTripRestoresTheScreenshotByteForByte) {
    // Issue 12: the furnace button's action (whiteFurnace) and back. The furnace frame is the headless render of
    // the saved furnace scene; leaving it gives the first screenshot again, byte for byte.
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string before = test::outputPath("furnace_before.png");
    const std::string furnace = test::outputPath("furnace_on.png");
    const std::string after = test::outputPath("furnace_after.png");
    const std::string saved = test::outputPath("furnace_saved.json");
    for (const std::string& f : {before, furnace, after}) fs::remove(f);
    const std::string script = writeText("furnace_script.json", R"({"actions": [
        {"frame": 3, "action": "screenshot", "path": ")" + before + R"("},
        {"frame": 4, "action": "whiteFurnace", "on": true},
        {"frame": 5, "action": "screenshot", "path": ")" + furnace + R"("},
        {"action": "saveScene", "path": ")" + saved + R"("},
        {"frame": 6, "action": "whiteFurnace", "on": false},
        {"frame": 8, "action": "screenshot", "path": ")" + after + R"("}
    ]})");
    Result v = view(scenePath + " --size " + kSize + " --frames 10 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    EXPECT_TRUE(sameBytes(before, after)) << "leaving the furnace did not restore the image";
    const std::string expected = test::outputPath("furnace_render.png");
    ASSERT_EQ(render(saved, expected).code, 0);
    expectSameImage("furnace_on", furnace, expected);
    // Under Phong the furnace is lit by the ambient term alone, Ia·ma = 1 = the background: every pixel white.
    const Image8 white = readPng(furnace);
    EXPECT_EQ(std::count(white.data.begin(), white.data.end(), uint8_t(255)), std::ptrdiff_t(white.data.size()));
    // Negative controls: the furnace changes the image, and the restored one is not the furnace.
    EXPECT_FALSE(sameBytes(before, furnace));
    EXPECT_FALSE(sameBytes(after, furnace));
}

TEST(AppWindow, ProbeStaysOnTheClickedPointWhileTheCameraOrbits) {
    // Issue 15: orbiting moved the probe to whatever the pixel showed next. Now a click anchors it to the
    // surface point it hit; the report after an orbit names the same object and point, at a new pixel.
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const Scene scene = loadScene(scenePath);
    const Sphere& red = scene.spheres[0];
    const glm::ivec2 px = pixelOf(scene, red.center + glm::vec3(0.2f, 0.3f, red.radius * 0.8f));
    const std::string before = test::outputPath("anchor_before.json"), after = test::outputPath("anchor_after.json");
    const std::string fresh = test::outputPath("anchor_fresh.json");
    const std::string at = R"("x": )" + std::to_string(px.x) + R"(, "y": )" + std::to_string(px.y);
    const std::string script = writeText("anchor_script.json", R"([
        {"frame": 2, "action": "probe", )" + at + R"(},
        {"action": "probeReport", "path": ")" + before + R"("},
        {"frame": 3, "action": "orbit", "yaw": 20, "pitch": 8},
        {"frame": 4, "action": "probeReport", "path": ")" + after + R"("},
        {"action": "probe", )" + at + R"(},
        {"action": "probeReport", "path": ")" + fresh + R"("}])");
    Result v = view(scenePath + " --size " + kSize + " --frames 6 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    const nlohmann::json a = nlohmann::json::parse(readFile(before)), b = nlohmann::json::parse(readFile(after));
    const nlohmann::json c = nlohmann::json::parse(readFile(fresh));
    ASSERT_TRUE(a["hit"].get<bool>() && b["hit"].get<bool>()) << a.dump() << "\n" << b.dump();
    EXPECT_EQ(a["object"]["id"], b["object"]["id"]);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a["P"][i].get<double>(), b["P"][i].get<double>(), 1e-3) << i;
        EXPECT_NEAR(a["N"][i].get<double>(), b["N"][i].get<double>(), 1e-3) << "the same point, the same normal";
    }
    EXPECT_NE(a["V"], b["V"]) << "the eye moved, so V did";
    EXPECT_NE(a["pixel"], b["pixel"]) << "the point now projects elsewhere";
    // Negative control: a new click on the old pixel after the orbit probes another point.
    double moved = 0.0;
    for (int i = 0; i < 3; ++i) moved += std::fabs(c["P"][i].get<double>() - a["P"][i].get<double>());
    EXPECT_GT(moved, 0.05) << c.dump();
}

TEST(AppWindow, StatusMessagesNeverMoveTheControls) {
    // Issue 15: a status message pushed the panel's controls down while it showed, so when it expired a
    // click meant for Open landed on Save. The status line now has a fixed height, message or not.
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string quiet = test::outputPath("status_quiet.png"), told = test::outputPath("status_told.png");
    const std::string selected = test::outputPath("status_selected.png");
    const std::string script = writeText("status_script.json", R"([
        {"frame": 3, "action": "windowScreenshot", "path": ")" + quiet +
                                                                   R"("},
        {"frame": 4, "action": "open", "path": ")" + scenePath + R"("},
        {"frame": 6, "action": "windowScreenshot", "path": ")" + told +
                                                                   R"("},
        {"frame": 7, "action": "select", "object": "gold"},
        {"frame": 9, "action": "windowScreenshot", "path": ")" + selected +
                                                                   R"("}])");
    Result v = view(scenePath + " --size " + kSize + " --ui-scale 1 --frames 10 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    const Image8 a = readPng(quiet), b = readPng(told), c = readPng(selected);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    // The panel below its header and the two-line status area: 440 window units wide at most, and at most half
    // the window (app/viewer.cpp computeLayout), from y = 110 down.
    const int panelW = std::min(440, a.width / 2), top = 110;
    auto panelRowsDiffer = [&](const Image8& x, const Image8& y) {
        int rows = 0;
        for (int row = top; row < x.height; ++row)
            if (!std::equal(x.data.begin() + std::ptrdiff_t(size_t(row) * size_t(x.width) * 3),
                            x.data.begin() + std::ptrdiff_t((size_t(row) * size_t(x.width) + size_t(panelW)) * 3),
                            y.data.begin() + std::ptrdiff_t(size_t(row) * size_t(y.width) * 3)))
                ++rows;
        return rows;
    };
    EXPECT_FALSE(sameBytes(quiet, told)) << "the status message did not appear";
    EXPECT_EQ(panelRowsDiffer(a, b), 0) << "the controls moved when the message came";
    // Negative control: a real change in the panel (an object selected) is seen by the same comparison.
    EXPECT_GT(panelRowsDiffer(a, c), 0);
}

TEST(AppWindow, MovingPreviewOnlyWhileTheCameraMoves) {
    // Issue 15's orbit speed: while the camera moves the raster image is drawn at half size
    // (raster.movingPreview, on by default); once it stops, the full-size image is back. --stats counts the
    // half-size draws; the image at exit, after the camera stopped, is the full-size one either way.
    REQUIRE_XVFB();
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string out[2];
    std::string shot[2];
    for (int on = 0; on < 2; ++on) {
        const std::string tag = on ? "on" : "off";
        std::string actions = on ? "[" : R"([{"frame": 0, "action": "setRaster", "movingPreview": false},)";
        for (int f = 0; f < 5; ++f)
            actions += std::string(f ? "," : "") + R"({"frame": )" + std::to_string(f) +
                       R"(, "action": "orbit", "yaw": 3, "pitch": 0})";
        const std::string script = writeText("moving_preview_" + tag + ".json", actions + "]");
        shot[on] = test::outputPath("moving_preview_exit_" + tag + ".png");
        fs::remove(shot[on]);
        Result v =
            view(scene + " --size " + kSize + " --frames 9 --stats --script " + script + " --screenshot " + shot[on]);
        ASSERT_EQ(v.code, 0) << v.out;
        out[on] = v.out;
    }
    // Frames 1..4 moved the camera (frame 0 has no earlier camera to compare with).
    EXPECT_NE(out[1].find("half-size previews     4 of"), std::string::npos) << out[1];
    // Negative control: switched off, no frame is drawn at half size.
    EXPECT_NE(out[0].find("half-size previews     0 of"), std::string::npos) << out[0];
    expectSameImage("moving_preview_exit", shot[1], shot[0]);
}
