// The real viewer window under Xvfb against the headless renderers: after 30 frames its screenshot
// equals `shadelab render` of the same scene and size; a scripted shininess change, the raster flags and the
// setRaster action, the Global mode, the still frame's accumulation and the white furnace round trip give the
// images the headless path gives for the same settings; resizing keeps them right. Every comparison has a
// negative control. Without Xvfb the tests report SKIPPED with the reason. What a user does with the
// window (probe, drag, undo, save) is app_window_interaction_test.cpp's.
#include "app_window_run.h"
#include "compare/compare_evidence.h"
#include "compare/image_compare.h"
#include "image/png.h"
#include "scene/scene_json.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "shading/lighting.h"
#include "test_output.h"
#include "util/read_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <utility>

using namespace shadelab;
using namespace shadelab::test;
namespace fs = std::filesystem;

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

// The script action `render` is `shadelab render` of the state saved as a scene: the same request, the same
// bytes, for each engine, at a size and sample count other than the window's.
TEST(AppWindow, ScriptRenderEqualsTheCommandLinesRenderOfTheSavedState) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string saved = test::outputPath("script_render_state.json");
    struct Case {
        const char* name;
        const char* keys;   // the action's request keys
        const char* flags;  // the same request on the command line
    };
    const Case cases[] = {
        {"raster", R"("spp": 4)", "--renderer raster --spp 4"},
        {"trace", R"("renderer": "trace", "spp": 4, "depth": 2)", "--renderer trace --spp 4 --depth 2"},
        {"path", R"("renderer": "path", "spp": 3, "lightPaths": "indirect")",
         "--renderer path --spp 3 --light-paths indirect"},
    };
    std::string actions = R"({"frame": 4, "action": "setShininess", "object": "red plastic", "s": 4},)";
    int frame = 6;
    for (const Case& c : cases)
        actions += R"({"frame": )" + std::to_string(frame++) + R"(, "action": "render", "path": ")" +
                   test::outputPath(std::string("script_render_") + c.name + ".png") + R"(", "size": [96, 54], )" +
                   c.keys + "},";
    actions += R"({"frame": 10, "action": "saveScene", "path": ")" + saved + R"("})";
    const std::string script = writeText("script_render.json", R"({"actions": [)" + actions + "]}");
    Result v = view(scenePath + " --size " + kSize + " --frames 14 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    for (const Case& c : cases) {
        const std::string scripted = test::outputPath(std::string("script_render_") + c.name + ".png");
        const std::string cli = test::outputPath(std::string("script_render_") + c.name + "_cli.png");
        ASSERT_EQ(render(saved, cli, std::string("--size 96x54 ") + c.flags).code, 0) << c.name;
        expectSameImage(std::string("script_render_") + c.name, scripted, cli);
        // Negative control: the scene as loaded, before the edit, is another image.
        const std::string unedited = test::outputPath(std::string("script_render_") + c.name + "_unedited.png");
        ASSERT_EQ(render(scenePath, unedited, std::string("--size 96x54 ") + c.flags).code, 0) << c.name;
        EXPECT_FALSE(sameBytes(scripted, unedited)) << c.name << ": the edit did not reach the scripted render";
    }
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
// The samples per pixel the viewer printed for a referenceScreenshot of `shot`, and whether it was denoised.
static std::pair<int, bool> pathTracedSamples(const std::string& out, const std::string& shot) {
    const std::string marker = shot + ": path traced, ";
    const size_t at = out.find(marker);
    if (at == std::string::npos) return {0, false};
    const size_t end = out.find('\n', at);
    const std::string line = out.substr(at, end == std::string::npos ? std::string::npos : end - at);
    return {std::atoi(line.c_str() + marker.size()), line.find(", denoised") != std::string::npos};
}

// Global mode shows the denoised preview by default and the raw estimate one switch away; each equals the
// headless path tracer's PNG of as many samples, with and without --denoise.
TEST(AppWindow, GlobalModeEqualsTheHeadlessPathTracer) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/local-vs-global.json");
    const std::string denoisedShot = test::outputPath("global_window_denoised.png"),
                      rawShot = test::outputPath("global_window.png");
    const std::string script = writeText("global_script.json", R"([
        {"frame": 1, "action": "setMode", "mode": "global"},
        {"action": "waitReference", "timeout": 120},
        {"action": "referenceScreenshot", "path": ")" + denoisedShot +
                                                                   R"("},
        {"action": "setGlobal", "denoise": false},
        {"action": "referenceScreenshot", "path": ")" + rawShot + R"("}])");
    Result v = view(scenePath + " --size 160x90 --frames 3 --script " + script);
    ASSERT_EQ(v.code, 0) << v.out;
    const auto [denoisedSpp, denoised] = pathTracedSamples(v.out, denoisedShot);
    const auto [spp, rawDenoised] = pathTracedSamples(v.out, rawShot);
    ASSERT_GE(denoisedSpp, 1) << v.out;
    ASSERT_GE(spp, 1) << v.out;
    EXPECT_TRUE(denoised) << "the preview is denoised by default: " << v.out;
    EXPECT_FALSE(rawDenoised) << v.out;
    const auto headless = [&](const std::string& name, int n, const std::string& flags) {
        const std::string path = test::outputPath(name);
        Result r = shell(binary() + " render " + scenePath + " --size 160x90 --renderer path --spp " +
                         std::to_string(n) + " " + flags + " -o " + path);
        EXPECT_EQ(r.code, 0) << r.out;
        return path;
    };
    EXPECT_TRUE(sameBytes(rawShot, headless("global_headless.png", spp, ""))) << spp << " samples: " << rawShot;
    EXPECT_TRUE(sameBytes(denoisedShot, headless("global_headless_denoised.png", denoisedSpp, "--denoise")))
        << denoisedSpp << " samples, denoised: " << denoisedShot;
    // Negative controls: one sample more is another image, and the denoised preview is not the raw estimate.
    EXPECT_FALSE(sameBytes(rawShot, headless("global_headless_more.png", spp + 1, "")));
    EXPECT_FALSE(sameBytes(denoisedShot, headless("global_headless_raw.png", denoisedSpp, "")));
}

TEST(AppWindow, StillFrameAccumulatesToTheSupersampledRender) {
    // While the view is still, the viewer accumulates the 16 grid samples of --spp 16, so edges,
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
    // The furnace button's action (whiteFurnace) and back. The furnace frame is the headless render of
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

TEST(AppWindow, MovingPreviewOnlyWhileTheCameraMoves) {
    // For the orbit's speed (docs/viewer.md, "Moving preview"): while the camera moves the raster image is drawn at
    // half size (raster.movingPreview, on by default); once it stops, the full-size image is back. --stats counts the
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

// The display in the window: --exposure/--view-transform and the setDisplay action give screenshots equal to
// `shadelab render` with the same flags, and a render action inherits the display the window shows; each
// differs from the Standard render (negative control).
TEST(AppWindow, DisplayFlagsAndSetDisplayMatchHeadlessRenders) {
    REQUIRE_XVFB();
    const std::string scenePath = test::sourcePath("assets/scenes/default.json");
    const std::string flagged = test::outputPath("display_view_flags.png");
    const std::string scripted = test::outputPath("display_view_script.png");
    const std::string rendered = test::outputPath("display_view_render_action.png");
    fs::remove(rendered);
    const std::string script = writeText("display_script.json", R"({"actions": [
        {"frame": 5, "action": "screenshot", "path": ")" + flagged +
                                                                    R"("},
        {"frame": 6, "action": "setDisplay", "exposure": 1.5},
        {"frame": 7, "action": "render", "renderer": "trace", "path": ")" +
                                                                    rendered + R"("}
    ]})");
    Result v = view(scenePath + " --size " + kSize + " --frames 10 --exposure -1 --view-transform filmic --script " +
                    script + " --screenshot " + scripted);
    ASSERT_EQ(v.code, 0) << v.out;
    const std::string expectFlagged = test::outputPath("display_render_flags.png");
    const std::string expectScripted = test::outputPath("display_render_script.png");
    const std::string expectRendered = test::outputPath("display_render_trace.png");
    const std::string plain = test::outputPath("display_render_plain.png");
    ASSERT_EQ(render(scenePath, expectFlagged, "--exposure -1 --view-transform filmic").code, 0);
    ASSERT_EQ(render(scenePath, expectScripted, "--exposure 1.5 --view-transform filmic").code, 0);
    ASSERT_EQ(render(scenePath, expectRendered, "--renderer trace --exposure 1.5 --view-transform filmic").code, 0);
    ASSERT_EQ(render(scenePath, plain).code, 0);
    expectSameImage("display_view_flags", flagged, expectFlagged);
    expectSameImage("display_view_script", scripted, expectScripted);
    EXPECT_TRUE(sameBytes(rendered, expectRendered)) << rendered << " vs " << expectRendered;
    EXPECT_FALSE(sameBytes(flagged, plain)) << "--exposure/--view-transform did not reach the screenshot";
    EXPECT_FALSE(sameBytes(scripted, flagged)) << "setDisplay did not change the screenshot";
}

// The side panel's kept pixels (app/panel_cache.h): while the camera orbits, most frames copy the panel's pixels
// from the last frame that drew it, and $SHADELAB_PANEL_CACHE=verify draws it as well on those frames and compares:
// no frame differs, also across a selection and a shininess change that redraw it. Negative control: with
// "verify-stale" the kept pixels are served after the panel changed, and the comparison sees it.
TEST(AppWindow, SidePanelKeptPixelsEqualThePanelDrawnAgain) {
    REQUIRE_XVFB();
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string actions = "[";
    for (int f = 0; f < 24; ++f) {
        actions += std::string(f ? "," : "") + R"({"frame": )" + std::to_string(f) +
                   R"(, "action": "orbit", "yaw": 1, "pitch": 0})";
        if (f == 8) actions += R"(, {"frame": 8, "action": "select", "object": "red plastic"})";
        if (f == 16) actions += R"(, {"frame": 16, "action": "setShininess", "object": "red plastic", "s": 90})";
    }
    const std::string script = writeText("panel_cache.json", actions + "]");
    const auto counts = [&](const std::string& mode) {
        Result v = view(scene + " --size " + kSize + " --frames 30 --stats --script " + script,
                        "SHADELAB_PANEL_CACHE=" + mode + " ");
        EXPECT_EQ(v.code, 0) << v.out;
        size_t drawn = 0, copied = 0, whole = 0, compared = 0, differing = 0;
        const size_t a = v.out.find("side panel             drawn in"), b = v.out.find("side panel verified");
        EXPECT_NE(a, std::string::npos) << v.out;
        EXPECT_NE(b, std::string::npos) << v.out;
        if (a != std::string::npos)
            std::sscanf(v.out.c_str() + a,
                        "side panel drawn in %zu frames, its kept pixels copied in %zu, drawn with "
                        "the rest in %zu",
                        &drawn, &copied, &whole);
        if (b != std::string::npos)
            std::sscanf(v.out.c_str() + b, "side panel verified %zu frames compared, %zu differing", &compared,
                        &differing);
        return std::array<size_t, 4>{drawn, copied, compared, differing};
    };
    const std::array<size_t, 4> verify = counts("verify");
    EXPECT_GE(verify[0], 3u);   // drawn at the start, after the selection and after the edit (at least)
    EXPECT_GE(verify[1], 10u);  // most orbit frames copy the kept pixels
    EXPECT_EQ(verify[2], verify[1]);
    EXPECT_EQ(verify[3], 0u) << "frames whose kept panel differed from the panel drawn again";
    const std::array<size_t, 4> stale = counts("verify-stale");
    EXPECT_GT(stale[3], 0u) << "stale kept pixels went unnoticed";
}
