// `render -o x.exr` and `compare a.exr b.exr` run as a user runs them: the EXR holds the floats each renderer had
// before the 8-bit conversion (so converting it gives the PNG's bytes), compare passes an image against itself
// and fails against a changed render, and bad names, mixed kinds and hostile files are refused in one line.
#include "cli_run.h"
#include "image/encode.h"
#include "image/exr.h"
#include "image/png.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace shadelab;
using namespace shadelab::test;
namespace fs = std::filesystem;

namespace {

std::string freshDir(const std::string& name) {
    const std::string dir = test::outputPath(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

const std::string kScene = test::sourcePath("assets/scenes/default.json");

}  // namespace

// For every renderer, the EXR converted by the one conversion (toImage8) is the PNG the same command writes:
// the file holds the linear floats before encoding, unclamped.
TEST(CliExr, RenderWritesTheFloatsBeforeEncodingForEveryRenderer) {
    const std::string dir = freshDir("every_renderer");
    for (const char* renderer : {"raster", "trace", "path"}) {
        const std::string flags = std::string(" --size 40x30 --renderer ") + renderer +
                                  (std::string(renderer) == "path" ? " --spp 2 --depth 1" : "");
        const std::string png = dir + "/" + renderer + ".png", exr = dir + "/" + renderer + ".exr";
        ASSERT_EQ(run("render " + kScene + " -o " + png + flags).code, 0);
        const Result r = run("render " + kScene + " -o " + exr + flags + " --verbose");
        ASSERT_EQ(r.code, 0) << r.out;
        EXPECT_NE(r.out.find("linear EXR, float"), std::string::npos) << r.out;
        const ExrImage image = readExr(exr);
        ASSERT_EQ(image.width, 40);
        ASSERT_EQ(image.height, 30);
        ASSERT_EQ(image.layers.size(), 1u) << renderer;
        const ImageF linear = colourOf(image, exr);
        const Image8 converted = toImage8(linear, Encoding::Srgb, {}, nullptr), written = readPng(png);
        EXPECT_EQ(converted.data, written.data) << renderer << ": " << exr << " does not convert to " << png;
        float brightest = 0.0f;
        for (float v : linear.rgba) brightest = std::max(brightest, v);
        EXPECT_GT(brightest, 0.05f) << renderer << ": a lit scene";
        // Negative control: the other encoding's conversion differs from the PNG.
        EXPECT_NE(toImage8(linear, Encoding::Linear, {}, nullptr).data, written.data) << renderer;
    }
    // Both: the raster's colour, and the reference's as layer "trace" (equal to --renderer trace's floats).
    const std::string both = dir + "/both.exr";
    ASSERT_EQ(run("render " + kScene + " -o " + both + " --size 40x30 --renderer both").code, 0);
    const ExrImage image = readExr(both);
    ASSERT_NE(image.layer("trace"), nullptr);
    EXPECT_EQ(image.layer("")->samples, readExr(dir + "/raster.exr").layer("")->samples);
    EXPECT_EQ(image.layer("trace")->samples, readExr(dir + "/trace.exr").layer("")->samples);
}

TEST(CliExr, HalfPrecisionOnRequest) {
    const std::string dir = freshDir("half");
    ASSERT_EQ(run("render " + kScene + " -o " + dir + "/f.exr --size 64x48").code, 0);
    const Result r = run("render " + kScene + " -o " + dir + "/h.exr --size 64x48 --exr-precision half");
    ASSERT_EQ(r.code, 0) << r.out;
    const ImageF f = colourOf(readExr(dir + "/f.exr"), "f"), h = colourOf(readExr(dir + "/h.exr"), "h");
    size_t moved = 0;
    for (size_t i = 0; i < f.rgba.size(); ++i) {
        EXPECT_LE(std::fabs(f.rgba[i] - h.rgba[i]), std::fabs(f.rgba[i]) * std::ldexp(1.0f, -11) + 6e-8f) << i;
        moved += f.rgba[i] != h.rgba[i];
    }
    EXPECT_GT(moved, 0u) << "control: half is not float";
    EXPECT_LT(fs::file_size(dir + "/h.exr"), fs::file_size(dir + "/f.exr"));
}

TEST(CliExr, CompareAnExrWithItselfPassesAndWithAChangedRenderFails) {
    const std::string dir = freshDir("compare");
    const std::string a = dir + "/a.exr", b = dir + "/b.exr";
    ASSERT_EQ(run("render " + kScene + " -o " + a + " --size 64x48").code, 0);
    ASSERT_EQ(run("render " + kScene + " -o " + b + " --size 64x48 --model blinn-phong").code, 0);
    const Result same =
        run("compare " + a + " " + a + " --diff " + dir + "/same_heat.png --json " + dir + "/same.json");
    EXPECT_EQ(same.code, 0) << same.out;
    EXPECT_NE(same.out.find("linear RGB (OpenEXR)"), std::string::npos) << same.out;
    EXPECT_NE(same.out.find("verdict: PASS"), std::string::npos) << same.out;
    // Negative control: Phong against Blinn-Phong at the scene's exponents.
    const Result changed = run("compare " + a + " " + b + " --diff " + dir + "/heat.png --json " + dir + "/r.json");
    EXPECT_EQ(changed.code, 1) << changed.out;
    EXPECT_NE(changed.out.find("verdict: FAIL"), std::string::npos) << changed.out;
    const Image8 heat = readPng(dir + "/heat.png");
    EXPECT_EQ(heat.width, 64);
    size_t lit = 0;
    for (uint8_t v : heat.data) lit += v > 0;
    EXPECT_GT(lit, 0u) << "the heatmap shows the difference: " << dir << "/heat.png";
    EXPECT_NE(readAll(dir + "/r.json").find("\"verdict\": \"fail\""), std::string::npos);
    // The gates are flags: a wide enough one passes the same pair.
    EXPECT_EQ(run("compare " + a + " " + b + " --rel-threshold 1e6 --rel-hard-max 1e6 --max-rel-rmse 1e6 -q").code, 0);
}

TEST(CliExr, NamesKindsAndFlagsAreChecked) {
    const std::string dir = freshDir("names");
    // An unknown extension: a usage error listing the formats, nothing written.
    for (const std::string name : {"out.jpg", "out", "out.exr.txt"}) {
        const Result r = run("render " + kScene + " -o " + dir + "/" + name + " --size 16x12");
        EXPECT_EQ(r.code, 2) << name << ": " << r.out;
        EXPECT_NE(r.out.find(".png or .exr"), std::string::npos) << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
        EXPECT_FALSE(fs::exists(dir + "/" + name));
    }
    EXPECT_EQ(run("render " + kScene + " -o " + dir + "/UPPER.EXR --size 16x12").code, 0) << "control: any case";
    EXPECT_EQ(readExr(dir + "/UPPER.EXR").width, 16);
    const Result precisionOnPng = run("render " + kScene + " -o " + dir + "/p.png --exr-precision half");
    EXPECT_EQ(precisionOnPng.code, 2) << precisionOnPng.out;
    EXPECT_NE(precisionOnPng.out.find("--exr-precision: only for an .exr output"), std::string::npos);
    const Result badPrecision = run("render " + kScene + " -o " + dir + "/p.exr --exr-precision double");
    EXPECT_EQ(badPrecision.code, 2) << badPrecision.out;
    EXPECT_NE(badPrecision.out.find("--exr-precision: expected half or float, got 'double'"), std::string::npos)
        << badPrecision.out;

    // -o onto an input (through a link named .exr) is refused, the input untouched.
    const std::string scene = dir + "/scene.json";
    fs::copy_file(kScene, scene);
    fs::create_symlink("scene.json", dir + "/scene.exr");
    const std::string before = readAll(scene);
    const Result onto = run("render " + scene + " -o " + dir + "/scene.exr --size 16x12");
    EXPECT_EQ(onto.code, 1) << onto.out;
    EXPECT_NE(onto.out.find("refusing to overwrite an input"), std::string::npos) << onto.out;
    EXPECT_EQ(lineCount(onto.out), 1) << onto.out;
    EXPECT_EQ(readAll(scene), before);

    // compare: a .png against an .exr, and an 8-bit gate on two EXR files, are usage errors.
    const std::string png = dir + "/p.png", exr = dir + "/UPPER.EXR";
    ASSERT_EQ(run("render " + kScene + " -o " + png + " --size 16x12").code, 0);
    for (const std::string& args : {png + " " + exr, exr + " " + png}) {
        const Result mixed = run("compare " + args);
        EXPECT_EQ(mixed.code, 2) << mixed.out;
        EXPECT_NE(mixed.out.find("compare two .png files (8-bit gates) or two .exr files"), std::string::npos)
            << mixed.out;
        EXPECT_EQ(lineCount(mixed.out), 1) << mixed.out;
    }
    EXPECT_EQ(run("compare " + exr + " " + exr + " --threshold 5").code, 2);
    EXPECT_EQ(run("compare " + png + " " + png + " --rel-threshold 0.1").code, 2);
    // compare's outputs never replace an input EXR.
    const std::string exrBefore = readAll(exr);
    const Result diffOntoInput = run("compare " + exr + " " + exr + " --diff " + exr);
    EXPECT_EQ(diffOntoInput.code, 2) << diffOntoInput.out;
    EXPECT_EQ(readAll(exr), exrBefore);
}

TEST(CliExr, HostileExrIsRefusedInOneLineNamingTheFile) {
    const std::string dir = freshDir("hostile");
    const std::string good = dir + "/good.exr";
    ASSERT_EQ(run("render " + kScene + " -o " + good + " --size 32x24").code, 0);
    const std::string bytes = readAll(good);
    const auto write = [&](const std::string& name, const std::string& content) {
        std::ofstream(dir + "/" + name, std::ios::binary) << content;
        return dir + "/" + name;
    };
    std::string huge = bytes;
    const size_t at = huge.find(std::string("dataWindow\0box2i\0", 17));
    ASSERT_NE(at, std::string::npos);
    const int32_t box[4] = {0, 0, 1 << 30, 1 << 30};
    std::memcpy(&huge[at + 21], box, sizeof box);
    for (const std::string& bad : {write("empty.exr", ""), write("text.exr", "not an image\n"),
                                   write("cut.exr", bytes.substr(0, bytes.size() / 2)), write("huge.exr", huge)}) {
        const Result r = run("compare " + good + " " + bad);
        EXPECT_EQ(r.code, 2) << bad << ": " << r.out;
        EXPECT_NE(r.out.find("shadelab: error: " + bad + ": "), std::string::npos) << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
    }
    EXPECT_EQ(run("compare " + good + " " + good + " -q").code, 0) << "control";
}

// --passes adds the first hit's albedo, normal and depth for every renderer, the path tracer's variance, and
// with --denoise the raw estimate; the layers hold what they say (unit normals, positive depth, the lamp's
// albedo 1) and the denoised colour differs from the raw one.
TEST(CliExr, PassesAndTheDenoisedPreview) {
    const std::string dir = freshDir("passes");
    const std::string cornell = test::sourcePath("assets/scenes/cornell.json");
    for (const char* renderer : {"raster", "trace"}) {
        const std::string exr = dir + "/" + renderer + ".exr";
        const Result r = run("render " + cornell + " -o " + exr + " --size 40x30 --passes --renderer " + renderer);
        ASSERT_EQ(r.code, 0) << r.out;
        const ExrImage image = readExr(exr);
        ASSERT_EQ(image.layers.size(), 4u) << renderer;
        EXPECT_NE(image.layer("albedo"), nullptr);
        EXPECT_NE(image.layer("depth"), nullptr);
    }
    const std::string exr = dir + "/path.exr";
    const Result r =
        run("render " + cornell + " -o " + exr + " --size 40x30 --spp 4 --renderer path --passes --denoise");
    ASSERT_EQ(r.code, 0) << r.out;
    const ExrImage image = readExr(exr);
    for (const char* name : {"albedo", "normal", "depth", "variance", "raw"})
        ASSERT_NE(image.layer(name), nullptr) << name << " missing from " << exr;
    const ExrLayer& n = *image.layer("normal");
    ASSERT_EQ(n.channels, (std::vector<std::string>{"X", "Y", "Z"}));
    const ExrLayer& depth = *image.layer("depth");
    for (size_t p = 0; p < depth.samples.size(); ++p) {
        const float len = std::sqrt(n.samples[3 * p] * n.samples[3 * p] + n.samples[3 * p + 1] * n.samples[3 * p + 1] +
                                    n.samples[3 * p + 2] * n.samples[3 * p + 2]);
        ASSERT_NEAR(len, 1.0f, 1e-3f) << "pixel " << p << ": the closed box has a surface everywhere";
        ASSERT_GT(depth.samples[p], 0.0f) << "pixel " << p;
    }
    float variance = 0.0f;
    for (float v : image.layer("variance")->samples) variance = std::max(variance, v);
    EXPECT_GT(variance, 0.0f) << "4 samples of a path-traced box are noisy";
    EXPECT_NE(colourOf(image, exr).rgba.size(), 0u);
    const ExrLayer& raw = *image.layer("raw");
    const ExrLayer& colour = image.layers.front();
    EXPECT_NE(raw.samples, colour.samples) << "the colour is the denoised preview, not the raw estimate";
}

TEST(CliExr, DenoiseAndPassesAreRefusedWhereTheyDoNotApply) {
    const std::string dir = freshDir("passes_refused");
    Result r = run("render " + kScene + " -o " + dir + "/a.png --size 16x16 --passes");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find("--passes: only for an .exr output"), std::string::npos) << r.out;
    r = run("render " + kScene + " -o " + dir + "/a.png --size 16x16 --denoise");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find("--denoise: is for the path tracer (renderer path), not raster"), std::string::npos) << r.out;
}
