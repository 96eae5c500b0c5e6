// The real viewer window under Xvfb, used as a teacher uses it: the probe reports the object
// and the NoL of the shared C++ shading and stays on the clicked point while the camera orbits; a broken
// shader reload keeps the last good program; dragging a light marker moves the light and its shadow; undo
// restores a removed light exactly; saving never writes over a model; a traced glass tree ends promptly after its
// frames; projector scale keeps the window's shape; status messages never move the controls. Without Xvfb the tests
// report SKIPPED with the reason.
#include "app_window_run.h"
#include "image/png.h"
#include "scene/coverage.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "shading/lighting.h"
#include "test_output.h"
#include "util/read_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <iterator>
#include <map>
#include <sstream>

using namespace shadelab;
using namespace shadelab::test;
namespace fs = std::filesystem;

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

TEST(AppWindow, TracedGlassTreeExitsPromptlyAfterItsFrames) {
    // The glass tree: 45 spheres with kr = kt = 1 at depth 64, every pixel glass. Before the ray tree was bounded
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
    // At --ui-scale 2 the panel once took half the window and the image became a cropped portrait.
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

TEST(AppWindow, ProbeStaysOnTheClickedPointWhileTheCameraOrbits) {
    // Orbiting once moved the probe to whatever the pixel showed next. Now a click anchors it to the
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
    // A status message once pushed the panel's controls down while it showed, so when it expired a
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

// At UI scale 2 the panel's status line can be out of view, so a status message also shows as a toast at the
// bottom of the visible image. Two runs make the same image: one undoes a shininess change (status "undone"),
// the other sets the shininess back by hand (no message, the negative control); their windows differ at the
// bottom only where the toast is, right of the panel.
TEST(AppWindow, StatusMessagesShowAsAToastOnTheImage) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const Scene scene = loadScene(scenePath);
    const std::string s0 = std::to_string(scene.spheres.at(0).material.s);
    auto window = [&](const std::string& name, const std::string& second) {
        const std::string shot = test::outputPath(name + ".png");
        const std::string script = writeText(name + ".json", R"([
            {"frame": 1, "action": "setShininess", "object": "#1", "s": 300},
            {"frame": 2, )" + second + R"(},
            {"frame": 4, "action": "windowScreenshot", "path": ")" +
                                                                 shot + R"("}])");
        Result v = view(scenePath + " --projector --frames 6 --script " + script);
        EXPECT_EQ(v.code, 0) << v.out;
        return readPng(shot);
    };
    const Image8 toast = window("toast_undo", R"("action": "undo")");
    const Image8 plain = window("toast_none", R"("action": "setShininess", "object": "#1", "s": )" + s0);
    ASSERT_EQ(toast.width, plain.width);
    ASSERT_EQ(toast.height, plain.height);
    int differing = 0, leftmost = toast.width;
    for (int y = toast.height * 2 / 3; y < toast.height; ++y)
        for (int x = 0; x < toast.width; ++x) {
            const uint8_t *a = toast.pixel(x, y), *b = plain.pixel(x, y);
            const bool same = a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
            if (same) continue;
            ++differing;
            leftmost = std::min(leftmost, x);
        }
    EXPECT_GT(differing, 300) << "no toast at the bottom of the image";
    EXPECT_GT(leftmost, toast.width * 35 / 100) << "the toast is not right of the panel, in the visible image";
}

// In projector mode (UI scale 2) the probe window lies inside what the panel leaves of the image and never over
// the probed point, for points across the image; where a side has no room it folds instead (the rule itself,
// with its negative control, is AppProbeWindow.InsideTheVisibleImageAndNeverOverThePoint). Read from the
// placements the viewer logs with --verbose.
TEST(AppWindow, ProjectorProbeWindowStaysInsideTheImageAndOffThePoint) {
    REQUIRE_XVFB();
    std::string actions;
    // Image pixels of the window-sized render (--projector opens about 1824x1026 on the tests' screen), right
    // of the panel: corners, edges and the middle of what it leaves.
    const int points[][2] = {{950, 120}, {1500, 120}, {1250, 500}, {1500, 850}, {1000, 850}};
    int frame = 2;
    for (const auto& p : points) {
        actions += R"({"frame": )" + std::to_string(frame) + R"(, "action": "probe", "x": )" + std::to_string(p[0]) +
                   R"(, "y": )" + std::to_string(p[1]) + "},";
        frame += 4;
    }
    const std::string script = writeText("projector_probe.json", "[" + actions.substr(0, actions.size() - 1) + "]");
    Result v = view(test::sourcePath("assets/scenes/default.json") + " --projector --verbose --frames " +
                    std::to_string(frame + 2) + " --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    // The last placement logged for each point: once the window has its size.
    std::map<std::pair<int, int>, std::string> last;
    std::istringstream lines(v.out);
    for (std::string line; std::getline(lines, line);) {
        float x, y, w, h, px, py, c, l, t, r, b;
        if (std::sscanf(line.c_str(), "shadelab: probe window %f %f %f %f point %f %f clearance %f visible %f %f %f %f",
                        &x, &y, &w, &h, &px, &py, &c, &l, &t, &r, &b) == 11)
            last[{int(px), int(py)}] = line;
    }
    ASSERT_EQ(last.size(), std::size(points)) << v.out;
    int folded = 0;
    for (const auto& [point, line] : last) {
        float x, y, w, h, px, py, c, l, t, r, b;
        std::sscanf(line.c_str(), "shadelab: probe window %f %f %f %f point %f %f clearance %f visible %f %f %f %f", &x,
                    &y, &w, &h, &px, &py, &c, &l, &t, &r, &b);
        EXPECT_GT(w, 100.0f) << line;
        if (line.find("(no room)") != std::string::npos) {
            ++folded;
            continue;
        }
        EXPECT_TRUE(x >= l && y >= t && x + w <= r && y + h <= b) << "outside the visible image: " << line;
        EXPECT_FALSE(x <= px && px <= x + w && y <= py && py <= y + h) << "over the probed point: " << line;
    }
    EXPECT_LT(folded, int(std::size(points))) << "every placement folded: the check would be blind";
}

// The ray view: the tree the viewer draws is the one the reference traces (the lines `render --ray-tree` prints
// for the same pixel); orbiting keeps it, traced from the eye of the click, so the class can walk around it; it
// is drawn over the image. Negative control: a new click after the orbit traces another tree.
TEST(AppWindow, RayTreeIsTheTracersAndStaysWhileTheCameraOrbits) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string before = test::outputPath("raytree_before.json"), after = test::outputPath("raytree_after.json");
    const std::string fresh = test::outputPath("raytree_fresh.json");
    const std::string drawn = test::outputPath("raytree_drawn.png"), bare = test::outputPath("raytree_bare.png");
    const std::string script = writeText("raytree_script.json", R"([
        {"frame": 2, "action": "probe", "x": 70, "y": 125},
        {"frame": 3, "action": "windowScreenshot", "path": ")" + bare +
                                                                    R"("},
        {"frame": 4, "action": "rayTree", "on": true},
        {"frame": 5, "action": "probeReport", "path": ")" + before + R"("},
        {"action": "windowScreenshot", "path": ")" + drawn + R"("},
        {"frame": 6, "action": "orbit", "yaw": 40, "pitch": 10},
        {"frame": 7, "action": "probeReport", "path": ")" + after + R"("},
        {"action": "probe", "x": 70, "y": 125},
        {"frame": 8, "action": "probeReport", "path": ")" + fresh + R"("}])");
    Result v = view(scenePath + " --size " + kSize + " --frames 10 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    const nlohmann::json a = nlohmann::json::parse(readFile(before)), b = nlohmann::json::parse(readFile(after));
    const nlohmann::json c = nlohmann::json::parse(readFile(fresh));
    ASSERT_TRUE(a.contains("ray_tree")) << a.dump();
    ASSERT_TRUE(b.contains("ray_tree")) << b.dump();
    ASSERT_TRUE(c.contains("ray_tree")) << c.dump();
    std::string lines;
    for (const auto& ray : a["ray_tree"]["rays"]) lines += "  " + ray["line"].get<std::string>() + "\n";
    EXPECT_NE(lines.find("blocked by shiny blue (sphere 2)"), std::string::npos) << lines;
    // The tracer's own tree for the pixel, as the command line prints it.
    Result cli = render(scenePath, test::outputPath("raytree_cli.png"), "--renderer trace --ray-tree 70,125");
    ASSERT_EQ(cli.code, 0) << cli.out;
    EXPECT_NE(cli.out.find(lines), std::string::npos) << "viewer:\n" << lines << "render:\n" << cli.out;
    EXPECT_EQ(a["ray_tree"]["rays"], b["ray_tree"]["rays"]) << "orbiting re-aimed the tree";
    EXPECT_NE(a["V"], b["V"]) << "the camera did move";
    EXPECT_NE(a["ray_tree"]["rays"], c["ray_tree"]["rays"]) << "a new click must trace from the new eye";
    EXPECT_NE(readFile(drawn), readFile(bare)) << "the tree is drawn over the image: " << drawn << ", " << bare;
}
