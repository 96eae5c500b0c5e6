// No output replaces a file the scene reads: the scene, its glTF model, the model's buffer and texture, the
// environment map, and the viewer's script, whichever command, flag or script action names it. Every case
// checks that the input is byte-identical afterwards; the negative controls write to a new file and over an
// existing file that is no input, and must succeed.
#include "app_window_run.h"
#include "cli_run.h"
#include "image/image.h"
#include "image/png.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace shadelab;
using test::haveXvfb;
using test::readAll;
using test::Result;

namespace {

// A scene that reads a .gltf (with an external buffer and PNG texture) and an .hdr environment. The model is
// any of assimp's; the small textured box keeps the test quick.
struct SceneFiles {
    std::string dir, scene, model, buffer, texture, hdr;
};

SceneFiles writeSceneFiles(const std::string& name) {
    SceneFiles f;
    f.dir = test::outputPath("inputs_never_overwritten/" + name);
    fs::remove_all(f.dir);
    fs::create_directories(f.dir);
    const fs::path box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF";
    fs::copy(box, f.dir, fs::copy_options::recursive);
    f.model = f.dir + "/BoxTextured.gltf";
    f.buffer = f.dir + "/BoxTextured0.bin";
    f.texture = f.dir + "/CesiumLogoFlat.png";
    f.hdr = f.dir + "/sky.hdr";
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
    for (int i = 0; i < 8; ++i) hdr += std::string("\x80\x80\x90\x81", 4);
    std::ofstream(f.hdr, std::ios::binary) << hdr;
    f.scene = f.dir + "/scene.json";
    std::ofstream(f.scene) << R"({"camera": {"position": [2, 2, 4], "target": [0, 0, 0]},
  "environment": {"hdr": "sky.hdr"}, "lights": [{"type": "point", "position": [3, 4, 5], "color": 1}],
  "objects": [{"type": "mesh", "source": "BoxTextured.gltf"}]})";
    return f;
}

bool haveBoxModel() { return fs::exists("/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf"); }

#define REQUIRE_BOX_MODEL() \
    if (!haveBoxModel()) GTEST_SKIP() << "assimp-testmodels not installed (scripts/install-deps.sh)"

std::vector<std::string> inputsOf(const SceneFiles& f) { return {f.scene, f.model, f.buffer, f.texture, f.hdr}; }

std::vector<std::string> snapshot(const std::vector<std::string>& files) {
    std::vector<std::string> bytes;
    for (const std::string& file : files) bytes.push_back(readAll(file));
    return bytes;
}

}  // namespace

TEST(InputsNeverOverwritten, RenderRefusesEveryFileTheSceneReads) {
    REQUIRE_BOX_MODEL();
    const SceneFiles f = writeSceneFiles("render");
    const std::vector<std::string> inputs = inputsOf(f), before = snapshot(inputs);
    for (const std::string& target : inputs) {
        for (const char* renderer : {"raster", "trace"}) {
            const Result r = test::run("render " + f.scene + " --renderer " + renderer + " --size 32x24 -o " + target);
            EXPECT_EQ(r.code, 1) << target << ": " << r.out;
            EXPECT_NE(r.out.find("refusing to overwrite an input"), std::string::npos) << r.out;
            EXPECT_EQ(test::lineCount(r.out), 1) << r.out;
        }
    }
    // The bare model as the scene: its buffer and texture are inputs too.
    for (const std::string& target : {f.buffer, f.texture}) {
        const Result r = test::run("render " + f.model + " --size 32x24 -o " + target);
        EXPECT_EQ(r.code, 1) << target << ": " << r.out;
    }
    EXPECT_EQ(snapshot(inputs), before) << "an input changed";
    // Negative controls: a new file and an existing file the scene does not read are written.
    const std::string fresh = f.dir + "/fresh.png", unrelated = f.dir + "/unrelated.png";
    std::ofstream(unrelated) << "old";
    EXPECT_EQ(test::run("render " + f.scene + " --size 32x24 -o " + fresh).code, 0);
    EXPECT_EQ(test::run("render " + f.scene + " --size 32x24 -o " + unrelated).code, 0);
    EXPECT_EQ(readPng(unrelated).width, 32);
}

TEST(InputsNeverOverwritten, ViewerFlagsRefuseTheSceneAndItsFilesBeforeTheWindowOpens) {
    REQUIRE_BOX_MODEL();
    const SceneFiles f = writeSceneFiles("view_flags");
    const std::vector<std::string> inputs = inputsOf(f), before = snapshot(inputs);
    // The scene file itself is refused before anything else, even without a display.
    for (const char* flag : {"--screenshot", "--window-screenshot", "--probe-report"}) {
        const Result r =
            test::run("view " + f.scene + " " + flag + " " + f.scene, "env -u DISPLAY -u WAYLAND_DISPLAY ");
        EXPECT_EQ(r.code, 1) << flag << ": " << r.out;
        EXPECT_NE(r.out.find("refusing to overwrite an input"), std::string::npos) << flag << ": " << r.out;
    }
    REQUIRE_XVFB();
    for (const std::string& target : {f.model, f.texture, f.hdr}) {
        const Result r = test::view(f.scene + " --size 64x48 --frames 2 --screenshot " + target);
        EXPECT_EQ(r.code, 1) << target << ": " << r.out;
        EXPECT_NE(r.out.find("refusing to overwrite an input"), std::string::npos) << r.out;
    }
    EXPECT_EQ(snapshot(inputs), before) << "an input changed";
    // Negative control: a new file is written.
    const Result ok = test::view(f.scene + " --size 64x48 --frames 2 --screenshot " + f.dir + "/shot.png");
    EXPECT_EQ(ok.code, 0) << ok.out;
    EXPECT_EQ(readPng(f.dir + "/shot.png").width, 64);
}

TEST(InputsNeverOverwritten, ScriptActionsRefuseTheSceneItsFilesAndTheScript) {
    REQUIRE_BOX_MODEL();
    REQUIRE_XVFB();
    const SceneFiles f = writeSceneFiles("script");
    const std::string script = f.dir + "/script.json";
    std::vector<std::string> inputs = inputsOf(f);
    inputs.push_back(script);
    // Every input is a target and every writing action is tried, one viewer run each (a run ends at its first
    // refusal): the actions rotate over the six inputs, so each meets at least one of them.
    const char* actions[] = {"screenshot", "windowScreenshot", "render", "probeReport", "screenshot", "saveScene"};
    for (size_t i = 0; i < inputs.size(); ++i) {
        const std::string& target = inputs[i];
        const char* action = actions[i % std::size(actions)];
        std::ofstream(script) << R"({"actions": [{"frame": 1, "action": "probe", "x": 32, "y": 24}, )"
                              << R"({"frame": 1, "action": ")" << action << R"(", "path": ")" << target << R"("}]})";
        const std::vector<std::string> before = snapshot(inputs);
        const Result r = test::view(f.scene + " --size 64x48 --frames 3 --script " + script);
        EXPECT_EQ(r.code, 1) << action << " onto " << target << ": " << r.out;
        EXPECT_NE(r.out.find("refusing to overwrite an input"), std::string::npos) << action << ": " << r.out;
        EXPECT_EQ(snapshot(inputs), before) << action << " onto " << target;
    }
    // Negative control: the same actions onto new files succeed.
    std::ofstream(script) << R"({"actions": [{"frame": 1, "action": "screenshot", "path": ")" << f.dir
                          << R"(/a.png"}, {"frame": 1, "action": "render", "path": ")" << f.dir << R"(/b.png"}]})";
    const Result ok = test::view(f.scene + " --size 64x48 --frames 3 --script " + script);
    EXPECT_EQ(ok.code, 0) << ok.out;
    EXPECT_TRUE(fs::exists(f.dir + "/a.png") && fs::exists(f.dir + "/b.png"));
}
