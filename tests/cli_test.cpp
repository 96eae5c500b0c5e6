// CLI tests (issue 2): `shadelab render` writes a real PNG; bad input exits 1 with one line naming the
// file; usage errors exit 2; a failed render leaves no output file behind; outputs never destroy (issue 11).
#include "image/png.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <spawn.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

struct Result {
    int code = -1;
    std::string out;  // stdout and stderr together
};

// Runs shadelab with `args`; `env` is prepended to the shell command (e.g. "VAR=value ").
Result run(const std::string& args, const std::string& env = "") {
    std::string cmd = env + std::string(SHADELAB_BINARY) + " " + args + " 2>&1";
    Result r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    while (size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
    int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

std::string writeText(const std::string& name, const std::string& text) {
    std::string path = test::outputPath(name);
    std::ofstream(path) << text;
    return path;
}

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

int lineCount(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

}  // namespace

TEST(Cli, RenderDefaultSceneWritesNonTrivialPng) {
    std::string out = test::outputPath("default.png");
    fs::remove(out);
    Result r = run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + out + " --size 320x180");
    ASSERT_EQ(r.code, 0) << r.out;
    Image8 img = readPng(out);
    EXPECT_EQ(img.width, 320);
    EXPECT_EQ(img.height, 180);
    std::set<uint32_t> colours;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const uint8_t* p = img.pixel(x, y);
            colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
        }
    EXPECT_GT(colours.size(), 500u) << "a lit scene has many distinct colours; image: " << out;
}

// The path tracer from the command line: the lesson scenes render, the summary line names the sample count
// and the noise, the indirect part is darker than the whole, and its flags are refused with other renderers.
TEST(CliPath, PathTracesTheLessonScenesAndSaysHowNoisy) {
    for (const char* scene : {"cornell", "local-vs-global"}) {
        const std::string out = test::outputPath(std::string("path_") + scene + ".png");
        fs::remove(out);
        Result r = run("render " + test::sourcePath(std::string("assets/scenes/") + scene + ".json") + " -o " + out +
                       " --size 64x48 --renderer path --spp 5 --depth 3");
        ASSERT_EQ(r.code, 0) << r.out;
        EXPECT_NE(r.out.find("path traced 5 samples per pixel"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("mean standard error"), std::string::npos) << r.out;
        const Image8 img = readPng(out);
        EXPECT_EQ(img.width, 64);
        double sum = 0.0;
        for (uint8_t v : img.data) sum += v;
        EXPECT_GT(sum / double(img.data.size()), 20.0) << "a lit box; image: " << out;
    }
    const std::string all = test::outputPath("path_lvg_all.png"), indirect = test::outputPath("path_lvg_indirect.png");
    const std::string scene = test::sourcePath("assets/scenes/local-vs-global.json");
    ASSERT_EQ(run("render " + scene + " -o " + all + " --size 48x36 --renderer path --spp 8").code, 0);
    ASSERT_EQ(
        run("render " + scene + " -o " + indirect + " --size 48x36 --renderer path --spp 8 --light-paths indirect")
            .code,
        0);
    double a = 0.0, b = 0.0;
    for (uint8_t v : readPng(all).data) a += v;
    for (uint8_t v : readPng(indirect).data) b += v;
    EXPECT_LT(b, 0.9 * a) << "indirect light alone is darker than all light: " << all << " " << indirect;
    EXPECT_GT(b, 0.1 * a) << "a closed white box bounces much light: " << indirect;
}

TEST(CliPath, TimeLimitStopsAtAWholeSampleCountAndPathFlagsNeedThePathRenderer) {
    const std::string out = test::outputPath("path_time_limit.png");
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    Result r = run("render " + scene + " -o " + out + " --size 64x36 --renderer path --spp 100000 --time-limit 0.5");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("(time limit)"), std::string::npos) << r.out;
    for (const char* flags : {"--time-limit 1", "--estimator bsdf", "--light-paths indirect"}) {
        Result bad = run("render " + scene + " -o " + out + " --renderer trace " + flags);
        EXPECT_EQ(bad.code, 2) << flags << ": " << bad.out;
        EXPECT_NE(bad.out.find("is for --renderer path"), std::string::npos) << bad.out;
    }
    Result spp = run("render " + scene + " -o " + out + " --renderer path --spp 7 --size 16x9");
    EXPECT_EQ(spp.code, 0) << "any sample count, not only squares: " << spp.out;
    Result grid = run("render " + scene + " -o " + out + " --renderer trace --spp 7");
    EXPECT_EQ(grid.code, 2) << grid.out;
}

TEST(Cli, RenderGlbAsScene) {
    const std::string model = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!fs::exists(model)) GTEST_SKIP() << "assimp-testmodels not installed: " << model;
    std::string out = test::outputPath("box.png");
    Result r = run("render " + model + " -o " + out + " --size 200x150 --model blinn-phong");
    ASSERT_EQ(r.code, 0) << r.out;
    Image8 img = readPng(out);
    EXPECT_EQ(img.width, 200);
    const uint8_t* centre = img.pixel(100, 75);
    EXPECT_GT(int(centre[0]) + centre[1] + centre[2], 30) << "the box should be lit at the image centre: " << out;
}

// Issue 5: compared with the rasterizer (one bounce), the reference traces one bounce too, unless --depth.
TEST(Cli, BothTracesTheReferenceAtDepthOneUnlessDepthIsGiven) {
    // The default scene with a kr 0.3 floor: the floor and the mirror sphere see each other, so depth 2 and
    // more add reflections of reflections.
    std::string text = readAll(test::sourcePath("assets/scenes/default.json"));
    const std::string floor = R"("material": {"ma": 0.8, "md": 0.8, "ms": 0.1, "s": 16})";
    const size_t at = text.find(floor);
    ASSERT_NE(at, std::string::npos) << "the default floor's material changed; update this test";
    text.replace(at, floor.size(), R"("material": {"ma": 0.8, "md": 0.8, "ms": 0.1, "s": 16, "kr": 0.3})");
    const std::string scene = writeText("both_depth_scene.json", text);
    const std::string one = test::outputPath("both_depth_default.png"), five = test::outputPath("both_depth_5.png");
    Result a = run("render " + scene + " -o " + one + " --size 160x90 --renderer both");
    ASSERT_EQ(a.code, 0) << a.out;
    EXPECT_NE(a.out.find("traced (depth 1)"), std::string::npos) << a.out;
    Result b = run("render " + scene + " -o " + five + " --size 160x90 --renderer both --depth 5");
    ASSERT_EQ(b.code, 0) << b.out;
    EXPECT_NE(b.out.find("traced (depth 5)"), std::string::npos) << b.out;
    EXPECT_NE(readPng(one).data, readPng(five).data) << one << " and " << five << " should differ";
}

// Shadow maps beyond the memory budget are refused with one line, not allocated lazily and killed later.
TEST(Cli, ShadowMapsOverBudgetAreAClearError) {
    std::string text = readAll(test::sourcePath("assets/scenes/default.json"));
    const std::string key = R"({"type": "point", "name": "warm key", "position": [-5, 7, 5])";
    const size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos) << "the default key light changed; update this test";
    // Two point lights among the spheres: two cube maps, 12 layers of 8192² (3 GiB).
    text.replace(
        at, key.size(),
        R"({"type": "point", "position": [0, 1.5, 0]}, {"type": "point", "name": "warm key", "position": [1, 1.5, 0])");
    const std::string scene = writeText("shadow_budget_scene.json", text);
    const std::string out = test::outputPath("shadow_budget.png");
    fs::remove(out);
    Result r = run("render " + scene + " -o " + out + " --size 64x36 --shadow-map-size 8192");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("budget"), std::string::npos) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(run("render " + scene + " -o " + out + " --size 64x36").code, 0) << "control: auto size fits";
}

TEST(Cli, MissingFileExitsOneNamingIt) {
    std::string out = test::outputPath("never.png");
    fs::remove(out);
    Result r = run("render /nonexistent/scene.json -o " + out);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("/nonexistent/scene.json"), std::string::npos) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, MalformedJsonExitsOneWithPlace) {
    std::string bad = writeText("bad.json", "{\n  \"lights\": [\n    {\"type\": \"point\",, }\n  ]\n}\n");
    std::string out = test::outputPath("bad.png");
    fs::remove(out);
    Result r = run("render " + bad + " -o " + out);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("bad.json"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("line 3"), std::string::npos) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, WrongFieldTypeNamesJsonPath) {
    std::string bad =
        writeText("badcolor.json", R"({"lights": [{"type": "point", "position": [0, 1, 0], "color": [1, 1]}]})");
    Result r = run("render " + bad + " -o " + test::outputPath("badcolor.png"));
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("lights[0].color"), std::string::npos) << r.out;
}

TEST(Cli, UsageErrorsExitTwo) {
    std::string scene = test::sourcePath("assets/scenes/default.json");
    EXPECT_EQ(run("").code, 2);
    EXPECT_EQ(run("frobnicate").code, 2);
    EXPECT_EQ(run("render").code, 2);
    EXPECT_EQ(run("render " + scene).code, 2) << "no -o";
    EXPECT_EQ(run("render " + scene + " -o x.png --size 0x10").code, 2);
    EXPECT_EQ(run("render " + scene + " -o x.png --size -5x10").code, 2);
    EXPECT_EQ(run("render " + scene + " -o x.png --size 16385x10").code, 2);
    EXPECT_EQ(run("render " + scene + " -o x.png --model gouraud").code, 2);
    EXPECT_EQ(run("render " + scene + " -o x.png --terms ambient,glow").code, 2);
    EXPECT_EQ(run("render " + scene + " -o x.png --encoding gamma").code, 2);
    EXPECT_EQ(run("render " + scene + " -o x.png --bogus").code, 2);
    EXPECT_FALSE(fs::exists("x.png"));
}

// One name table per enum: the flags accept the tables' words (aliases included) and their errors name the
// flag and list the words; image/ and scene/ know no flags.
TEST(Cli, EnumFlagsListTheirWordsAndAcceptTheSameAliasesAsSceneFiles) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::pair<const char*, const char*> cases[] = {
        {"--encoding gamma", "shadelab: usage error: --encoding: expected srgb or linear, got 'gamma'"},
        {"--model gouraud", "shadelab: usage error: --model: expected phong, blinn-phong or pbr, got 'gouraud'"},
        {"--renderer gpu", "shadelab: usage error: --renderer: expected raster, trace, both or path, got 'gpu'"},
        {"--terms ambient,glow",
         "shadelab: usage error: --terms: unknown term 'glow'; expected ambient, diffuse, "
         "specular, shadows, reflections or none"},
    };
    for (const auto& [flags, message] : cases) {
        Result r = run("render " + scene + " -o x.png " + flags);
        EXPECT_EQ(r.code, 2) << flags;
        EXPECT_EQ(r.out, std::string(message) + "\n") << flags;
    }
    // "blinn" on the command line and in a scene file give the same pixels as "blinn-phong".
    const std::string canonical = test::outputPath("model_blinn_phong.png");
    const std::string alias = test::outputPath("model_blinn.png"), file = test::outputPath("model_blinn_file.png");
    std::string text = readAll(scene);
    const size_t at = text.find(R"("model": "phong")");
    ASSERT_NE(at, std::string::npos) << "the default scene's model changed; update this test";
    text.replace(at, 16, R"("model": "blinn")");
    const std::string blinnScene = writeText("model_blinn_scene.json", text);
    ASSERT_EQ(run("render " + scene + " -o " + canonical + " --size 96x54 --model blinn-phong").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + alias + " --size 96x54 --model blinn").code, 0);
    Result r = run("render " + blinnScene + " -o " + file + " --size 96x54");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(readAll(alias), readAll(canonical));
    EXPECT_EQ(readAll(file), readAll(canonical));
}

TEST(Cli, HelpExitsZero) {
    Result r = run("--help");
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("render"), std::string::npos);
    r = run("render --help");
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("--size"), std::string::npos);
    EXPECT_NE(r.out.find("--encoding"), std::string::npos);
    EXPECT_NE(r.out.find("--shadow-map-size N|auto"), std::string::npos);
    EXPECT_NE(r.out.find("--pcf"), std::string::npos);
}

// Hiding glvnd's EGL vendor files makes every EGL platform fail, as on a machine without Mesa's EGL.
const std::string kNoEgl = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json ";

TEST(Cli, NoUsableBackendListsWhatWasTried) {
    std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string out = test::outputPath("nobackend.png");
    fs::remove(out);
    Result r = run("render " + scene + " -o " + out + " --gl-backend egl-device", kNoEgl);
    const std::string& text = r.out;
    EXPECT_EQ(r.code, 1) << text;
    EXPECT_NE(text.find("egl-device ("), std::string::npos) << text;
    EXPECT_NE(text.find("apt-get install"), std::string::npos) << text;
    EXPECT_EQ(lineCount(text), 1) << text;
    EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, AutoFallsBackToOSMesaWithoutEgl) {
    std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string out = test::outputPath("osmesa.png");
    if (!fs::exists("/usr/lib/x86_64-linux-gnu/libOSMesa.so.8")) GTEST_SKIP() << "libOSMesa not installed";
    Result r = run("render " + scene + " -o " + out + " --size 64x36 --verbose", kNoEgl);
    const std::string& text = r.out;
    EXPECT_EQ(r.code, 0) << text;
    EXPECT_NE(text.find("gl backend osmesa"), std::string::npos) << text;
    EXPECT_NE(text.find("gl: egl-device:"), std::string::npos) << "the log should show the EGL attempts: " << text;
}

TEST(Cli, EncodingLinearIsDarkerThanSrgb) {
    // Linear encoding skips the sRGB curve, which lifts dark values, so the same scene comes out darker.
    std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string a = test::outputPath("enc_srgb.png"), b = test::outputPath("enc_linear.png");
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 160x90").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --size 160x90 --encoding linear").code, 0);
    Image8 s = readPng(a), l = readPng(b);
    long sumS = 0, sumL = 0;
    for (size_t i = 0; i < s.data.size(); ++i) {
        sumS += s.data[i];
        sumL += l.data[i];
    }
    EXPECT_GT(sumS, sumL + long(s.data.size()) * 5) << a << " vs " << b;
}

TEST(Cli, RasterFlagsRefuseBadValuesWithExitTwo) {
    std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string out = test::outputPath("raster_flags_bad.png");
    fs::remove(out);
    const std::pair<const char*, const char*> cases[] = {
        {"--shadow-map-size 5", "--shadow-map-size: expected auto or a whole number from 16 to 8192, got '5'"},
        {"--shadow-map-size huge", "--shadow-map-size: expected auto or a whole number from 16 to 8192, got 'huge'"},
        {"--shadow-map-size 16384", "got '16384'"},
        {"--shadow-bias -1", "--shadow-bias: expected a number from 0 to 64, got '-1'"},
        {"--shadow-bias nan", "--shadow-bias: expected a number from 0 to 64, got 'nan'"},
        {"--normal-bias 64.5", "--normal-bias: expected a number from 0 to 64, got '64.5'"},
        {"--normal-bias 1x", "got '1x'"},
        {"--reflection-cube-size 4", "--reflection-cube-size: expected a whole number from 8 to 2048, got '4'"},
        {"--reflection-cube-size 128.5", "got '128.5'"},
        {"--pcf=on", "unknown option '--pcf=on'"},
        {"--shadow-bias", "--shadow-bias needs a value"},
    };
    for (const auto& [flags, message] : cases) {
        Result r = run("render " + scene + " -o " + out + " " + flags);
        EXPECT_EQ(r.code, 2) << flags << ": " << r.out;
        EXPECT_NE(r.out.find(message), std::string::npos) << flags << ": " << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
        EXPECT_FALSE(fs::exists(out)) << flags;
    }
}

TEST(Cli, RasterFlagsOverrideTheScenesRasterSettings) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    auto render = [](const std::string& input, const std::string& name, const std::string& flags) {
        const std::string out = test::outputPath(name);
        Result r = run("render " + input + " -o " + out + " --size 160x90 " + flags);
        EXPECT_EQ(r.code, 0) << flags << ": " << r.out;
        return r.code == 0 ? readPng(out).data : std::vector<uint8_t>();
    };
    const std::vector<uint8_t> base = render(scene, "raster_flags_base.png", "");
    ASSERT_FALSE(base.empty());
    // The scene's defaults restated change nothing (the negative control for the differences below).
    EXPECT_EQ(render(scene, "raster_flags_defaults.png",
                     "--shadow-map-size auto --shadow-bias 1 --normal-bias=1.5 --reflection-cube-size 128"),
              base);
    EXPECT_NE(render(scene, "raster_flags_pcf.png", "--pcf"), base) << "PCF softens the shadow edges";
    EXPECT_NE(render(scene, "raster_flags_map16.png", "--shadow-map-size 16"), base) << "16-texel maps are coarse";
    EXPECT_NE(render(scene, "raster_flags_cube8.png", "--reflection-cube-size 8"), base)
        << "the mirror sphere's 8-texel cube is blurred";
    // The flags override the file's "raster" object, and mean what its fields mean.
    std::string text = readAll(scene);
    ASSERT_EQ(text.substr(0, 1), "{");
    const std::string withRaster =
        writeText("raster_flags_scene.json",
                  R"({"raster": {"shadowMapSize": 16, "pcf": true, "reflectionCubeSize": 8},)" + text.substr(1));
    const std::vector<uint8_t> fromFile = render(withRaster, "raster_flags_from_file.png", "");
    EXPECT_EQ(render(scene, "raster_flags_as_file.png", "--shadow-map-size 16 --pcf --reflection-cube-size 8"),
              fromFile);
    EXPECT_NE(fromFile, base);
    EXPECT_EQ(
        render(withRaster, "raster_flags_file_overridden.png", "--shadow-map-size auto --reflection-cube-size 128"),
        render(scene, "raster_flags_pcf_only.png", "--pcf"));
    EXPECT_EQ(render(withRaster, "raster_flags_all_overridden.png",
                     "--shadow-map-size auto --reflection-cube-size 128 --no-pcf"),
              base)
        << "--no-pcf turns the file's PCF off";
}

// A glTF whose base-colour PNG is cut short (issue 16): by default one warning and the factor alone (exit 0);
// under --strict that line is the error (exit 1), and nothing is written.
TEST(Cli, StrictMakesAnInputWarningAnErrorAndWritesNothing) {
    const std::string intact = test::sourcePath("assets/models/textures/uv_checker.gltf");
    std::string text = readAll(intact);
    const std::string key = "data:image/png;base64,";
    size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos);
    at += key.size() + 40;  // 40 base64 characters: the signature and part of the header
    const size_t end = text.find('"', at);
    ASSERT_NE(end, std::string::npos);
    text.erase(at, end - at);
    const std::string model = writeText("strict_truncated.gltf", text);
    const std::string out = test::outputPath("strict_truncated.png");
    fs::remove(out);

    const Result lenient = run("render " + model + " -o " + out + " --size 64x64");
    EXPECT_EQ(lenient.code, 0) << lenient.out;
    EXPECT_NE(lenient.out.find("warning: "), std::string::npos) << lenient.out;
    EXPECT_TRUE(fs::exists(out));
    fs::remove(out);

    const Result strict = run("render " + model + " -o " + out + " --size 64x64 --strict");
    EXPECT_EQ(strict.code, 1) << strict.out;
    EXPECT_EQ(lineCount(strict.out), 1) << strict.out;
    EXPECT_NE(strict.out.find("error: "), std::string::npos) << strict.out;
    EXPECT_NE(strict.out.find("strict_truncated.gltf: images[0]"), std::string::npos) << strict.out;
    EXPECT_NE(strict.out.find("--strict"), std::string::npos) << strict.out;
    EXPECT_FALSE(fs::exists(out));

    // Negative control: the intact model has nothing to warn about, so --strict renders it.
    const Result clean = run("render " + intact + " -o " + out + " --size 64x64 --strict");
    EXPECT_EQ(clean.code, 0) << clean.out;
    EXPECT_TRUE(fs::exists(out));
}

TEST(CliCompare, ExitCodesFollowTheGates) {
    std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string a = test::outputPath("cmp_a.png"), b = test::outputPath("cmp_b.png"), c = test::outputPath("cmp_c.png");
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 160x90").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --size 160x90").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + c + " --size 160x90 --model blinn-phong").code, 0);
    Result same = run("compare " + a + " " + b);
    EXPECT_EQ(same.code, 0) << same.out;
    EXPECT_NE(same.out.find("PASS"), std::string::npos) << same.out;
    // Negative control: Phong against Blinn-Phong at the same exponent must fail the gates.
    std::string heat = test::outputPath("cmp_heat.png"), json = test::outputPath("cmp_report.json");
    fs::remove(heat);
    Result differ = run("compare " + a + " " + c + " --diff " + heat + " --json " + json);
    EXPECT_EQ(differ.code, 1) << differ.out;
    EXPECT_NE(differ.out.find("FAIL"), std::string::npos) << differ.out;
    EXPECT_EQ(readPng(heat).width, 160);
    std::ifstream in(json);
    std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(report.find("\"pass\": false"), std::string::npos) << report;
}

TEST(CliCompare, ErrorsExitTwo) {
    std::string scene = test::sourcePath("assets/scenes/default.json");
    std::string a = test::outputPath("cmp_small.png"), b = test::outputPath("cmp_big.png");
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 64x36").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --size 96x54").code, 0);
    Result sizes = run("compare " + a + " " + b);
    EXPECT_EQ(sizes.code, 2) << sizes.out;
    EXPECT_NE(sizes.out.find("image sizes differ: 64x36"), std::string::npos) << sizes.out;
    EXPECT_EQ(run("compare " + a + " /nonexistent.png").code, 2);
    EXPECT_EQ(run("compare " + a).code, 2);
    EXPECT_EQ(run("compare " + a + " " + a + " --threshold 300").code, 2);
}

// Nothing lost (issue 6): a render that cannot be written fails with one line, leaves the existing file as
// it was and leaves no temporary file behind.
namespace {

std::vector<std::string> listDir(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST(CliNothingLost, ReadOnlyFolder) {
    std::string dir = test::outputPath("readonly");
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir + "/out.png") << "previous";
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
    // Root ignores folder permissions: run as the unprivileged user `nobody` instead.
    std::string asUser = geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
    if (!asUser.empty() && std::system((asUser + "test -x " + std::string(SHADELAB_BINARY) + " -a -r " +
                                        test::sourcePath("assets/scenes/default.json"))
                                           .c_str()) != 0) {
        fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
        GTEST_SKIP() << "user nobody cannot reach the build tree here, so a permission test cannot be staged";
    }
    Result r = run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 64x36",
                   asUser);
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("Permission denied"), std::string::npos) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_EQ(readAll(dir + "/out.png"), "previous");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliNothingLost, FileSizeLimitHitMidWrite) {
    // RLIMIT_FSIZE makes write() fail part-way (EFBIG), as a disk that fills up during the write would.
    std::string dir = test::outputPath("fsize");
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir + "/out.png") << "previous";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 320x180",
            "trap '' XFSZ; ulimit -f 8; ");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("File too large"), std::string::npos) << r.out;
    EXPECT_EQ(readAll(dir + "/out.png"), "previous");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliNothingLost, FullDisk) {
    std::string dir = test::outputPath("fulldisk");
    fs::create_directories(dir);
    if (std::system(
            ("mountpoint -q " + dir + " || mount -t tmpfs -o size=64k tmpfs " + dir + " 2>/dev/null").c_str()) != 0)
        GTEST_SKIP() << "cannot mount a small tmpfs here (needs root); FileSizeLimitHitMidWrite covers the write path";
    for (const std::string& f : listDir(dir)) fs::remove(dir + "/" + f);
    std::ofstream(dir + "/out.png") << "previous";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 640x360");
    std::vector<std::string> left = listDir(dir);
    std::string kept = readAll(dir + "/out.png");
    (void)std::system(("umount " + dir).c_str());
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("No space left on device"), std::string::npos) << r.out;
    EXPECT_EQ(kept, "previous");
    EXPECT_EQ(left, std::vector<std::string>{"out.png"});
}

// A broken or missing shader (issue 6): one line that names the shader file (and line for a compile error).
TEST(CliShaders, BrokenOrMissingShaderNamesFileAndLine) {
    std::string dir = test::outputPath("shaders_broken");
    fs::remove_all(dir);
    fs::copy(test::sourcePath("shaders"), dir);
    std::string scene = test::sourcePath("assets/scenes/default.json");
    {
        std::string text = readAll(dir + "/sphere.frag");
        size_t main = text.find("void main() {");
        ASSERT_NE(main, std::string::npos);
        text.insert(main + 13, "\n    this is not glsl;");
        std::ofstream(dir + "/sphere.frag") << text;
    }
    Result r = run("render " + scene + " -o " + test::outputPath("broken.png") + " --size 32x18",
                   "SHADELAB_SHADER_DIR=" + dir + " ");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("shaders/sphere.frag: line "), std::string::npos) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;

    fs::copy_file(test::sourcePath("shaders/sphere.frag"), dir + "/sphere.frag", fs::copy_options::overwrite_existing);
    fs::remove(dir + "/plane.frag");
    r = run("render " + scene + " -o " + test::outputPath("broken.png") + " --size 32x18",
            "SHADELAB_SHADER_DIR=" + dir + " ");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("plane.frag"), std::string::npos) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    // Negative control: the intact copy renders.
    fs::copy_file(test::sourcePath("shaders/plane.frag"), dir + "/plane.frag");
    EXPECT_EQ(run("render " + scene + " -o " + test::outputPath("intact.png") + " --size 32x18",
                  "SHADELAB_SHADER_DIR=" + dir + " ")
                  .code,
              0);
}

// Outputs that never destroy (issue 11): an output is never one of the inputs, never a device, FIFO or a
// link to one; `-o -` is stdout; the file and then its folder are fsynced around the rename; a signal
// during the write leaves no temporary file.
namespace {

std::string freshDir(const std::string& name) {
    const std::string dir = test::outputPath(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return fs::canonical(dir).string();
}

struct SplitResult {
    int code = -1;
    std::string out;  // stdout alone, possibly binary
    std::string err;
};

// Runs shadelab with stdout and stderr captured apart.
// The capture files are named after the running test: ctest runs tests in parallel processes.
SplitResult runSplit(const std::string& args) {
    const std::string stem = std::string("split_") + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::string out = test::outputPath(stem + "_stdout.bin"), err = test::outputPath(stem + "_stderr.txt");
    const int status = std::system((std::string(SHADELAB_BINARY) + " " + args + " > " + out + " 2> " + err).c_str());
    SplitResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readAll(out);
    r.err = readAll(err);
    return r;
}

// The environment that loads write_probe (tests/write_probe.cpp) into shadelab.
std::vector<std::string> probeEnvironment(const std::string& log, int fsyncDelayMs) {
    return {"LD_PRELOAD=" + std::string(SHADELAB_WRITE_PROBE), "SHADELAB_PROBE_LOG=" + log,
            "SHADELAB_PROBE_FSYNC_DELAY_MS=" + std::to_string(fsyncDelayMs),
            // A sanitizer build accepts the preload; Mesa's allocations are not ours to leak-check (test.sh).
            "ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=0"};
}

std::vector<std::string> linesWith(const std::string& text, const std::string& needle) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (line.find(needle) != std::string::npos) lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

}  // namespace

TEST(CliOutputs, RenderOntoItsSceneIsRefused) {
    const std::string dir = freshDir("out_is_scene");
    const std::string scene = dir + "/scene.json";
    fs::copy_file(test::sourcePath("assets/scenes/default.json"), scene);
    const std::string before = readAll(scene);
    for (const std::string& output : {scene, dir + "/./scene.json"}) {
        Result r = run("render " + scene + " -o " + output + " --size 32x18");
        EXPECT_EQ(r.code, 1) << r.out;
        EXPECT_NE(r.out.find("shadelab: error: " + output + ": refusing to overwrite an input with the output (-o)"),
                  std::string::npos)
            << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
        EXPECT_EQ(readAll(scene), before);
    }
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"scene.json"});
    // Negative control: another name in the same folder is written.
    EXPECT_EQ(run("render " + scene + " -o " + dir + "/other.png --size 32x18").code, 0);
}

TEST(CliOutputs, RenderOntoItsModelIsRefused) {
    const std::string dir = freshDir("out_is_model");
    fs::create_directories(dir + "/models");
    fs::create_directories(dir + "/scenes");
    const std::string gltf = dir + "/models/torus.gltf", scene = dir + "/scenes/torus.json";
    fs::copy_file(test::sourcePath("assets/models/torus.gltf"), gltf);
    fs::copy_file(test::sourcePath("assets/scenes/torus.json"), scene);  // names ../models/torus.gltf
    const std::string before = readAll(gltf);

    Result direct = run("render " + gltf + " -o " + gltf + " --size 32x18");
    EXPECT_EQ(direct.code, 1) << direct.out;
    EXPECT_NE(direct.out.find(gltf + ": refusing to overwrite an input with the output (-o)"), std::string::npos)
        << direct.out;
    EXPECT_EQ(lineCount(direct.out), 1) << direct.out;
    // The model a scene loads is an input too; it is known once the scene is read, before the render.
    Result viaScene = run("render " + scene + " -o " + gltf + " --size 32x18");
    EXPECT_EQ(viaScene.code, 1) << viaScene.out;
    EXPECT_NE(viaScene.out.find(gltf + ": refusing to overwrite an input with the output (-o): it is " + dir +
                                "/scenes/../models/torus.gltf"),
              std::string::npos)
        << viaScene.out;
    EXPECT_EQ(lineCount(viaScene.out), 1) << viaScene.out;
    EXPECT_EQ(readAll(gltf), before);
    EXPECT_EQ(run("render " + scene + " -o " + dir + "/torus.png --size 32x18").code, 0) << "control";

    const std::string glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!fs::exists(glb)) GTEST_SKIP() << "assimp-testmodels not installed: " << glb;
    fs::copy_file(glb, dir + "/box.glb");
    const std::string glbBefore = readAll(dir + "/box.glb");
    Result binary = run("render " + dir + "/box.glb -o " + dir + "/box.glb --size 32x18");
    EXPECT_EQ(binary.code, 1) << binary.out;
    EXPECT_NE(binary.out.find("refusing to overwrite an input"), std::string::npos) << binary.out;
    EXPECT_EQ(readAll(dir + "/box.glb"), glbBefore);
}

TEST(CliOutputs, CompareOutputsOntoInputsAreRefused) {
    const std::string dir = freshDir("compare_out_is_input");
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string a = dir + "/a.png", b = dir + "/b.png";
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 48x27").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --size 48x27 --model blinn-phong").code, 0);
    const std::string aBefore = readAll(a), bBefore = readAll(b);
    // compare's own convention: 2 for any error (1 means "outside the gates").
    for (const std::string& flags : {"--diff " + a, "--json " + b, "--diff " + dir + "/c.png --json " + a}) {
        Result r = run("compare " + a + " " + b + " " + flags);
        EXPECT_EQ(r.code, 2) << flags << "\n" << r.out;
        EXPECT_NE(r.out.find("refusing to overwrite an input with the output (--"), std::string::npos) << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
        EXPECT_EQ(readAll(a), aBefore);
        EXPECT_EQ(readAll(b), bBefore);
    }
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"a.png", "b.png"})) << "refused before anything is written";
}

TEST(CliOutputs, FifoIsRefusedWithoutBlocking) {
    const std::string dir = freshDir("out_fifo");
    const std::string fifo = dir + "/out.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    // `timeout` turns a writer that opens the FIFO (and waits for a reader forever) into exit 124.
    Result r = run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + fifo + " --size 32x18",
                   "timeout 10 ");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find(fifo + ": refusing to replace a FIFO; only regular files are written"), std::string::npos)
        << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_TRUE(fs::is_fifo(fifo));
    const std::string png = test::outputPath("cmp_fifo_input.png");
    ASSERT_EQ(run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + png + " --size 16x9").code, 0);
    Result cmp = run("compare " + png + " " + png + " --diff " + fifo, "timeout 10 ");
    EXPECT_EQ(cmp.code, 2) << cmp.out;
    EXPECT_NE(cmp.out.find("refusing to replace a FIFO"), std::string::npos) << cmp.out;
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(CliOutputs, DevicesAndLinksToThemAreRefused) {
    // -o /dev/null, /dev/full or a /dev/stdout that is a pipe, staged with private nodes and links to them.
    // Never the real ones: as root, a writer that follows links and renames replaces the system's device
    // (it happened once, checking that this test fails without the type check).
    const std::string dir = freshDir("out_device");
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    auto expectRefused = [&](const std::string& name, const std::string& what) {
        Result r = run("render " + scene + " -o " + dir + "/" + name + " --size 32x18", "timeout 10 ");
        EXPECT_EQ(r.code, 1) << name << ": " << r.out;
        EXPECT_NE(r.out.find(dir + "/" + name + ": refusing to replace " + what), std::string::npos) << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
    };
    ASSERT_EQ(::mkfifo((dir + "/pipe").c_str(), 0644), 0);
    fs::create_symlink("pipe", dir + "/to-pipe.png");
    expectRefused("to-pipe.png", "a FIFO (through a symlink)");
    EXPECT_TRUE(fs::is_symlink(dir + "/to-pipe.png"));
    EXPECT_TRUE(fs::is_fifo(dir + "/pipe"));

    // A character device made here (a copy of /dev/null: major 1, minor 3). mknod needs root.
    const std::string node = dir + "/null";
    if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
        GTEST_SKIP() << "mknod " << node << ": " << std::strerror(errno) << " (making a device node needs root)";
    expectRefused("null", "a character device; only regular files are written");
    fs::create_symlink("null", dir + "/to-null.png");
    expectRefused("to-null.png", "a character device (through a symlink)");
    EXPECT_TRUE(fs::is_character_file(node));
    EXPECT_TRUE(fs::is_symlink(dir + "/to-null.png"));
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"null", "pipe", "to-null.png", "to-pipe.png"}));
}

TEST(CliOutputs, DashWritesThePngToStdout) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string file = test::outputPath("stdout_reference.png");
    ASSERT_EQ(run("render " + scene + " -o " + file + " --size 160x90").code, 0);
    // --verbose and --timings talk on stderr, so stdout carries the PNG alone.
    SplitResult r = runSplit("render " + scene + " -o - --size 160x90 --verbose --timings");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, readAll(file)) << "stdout holds exactly the bytes -o FILE writes";
    EXPECT_NE(r.err.find("wrote stdout"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists("-")) << "no file named '-' in the working folder";
    // -o /dev/stdout means the same (isStdout, output_file_test); not run here, since a regression would
    // replace the system's /dev/stdout link when the tests run as root.
}

TEST(CliOutputs, CompareWritesJsonOrHeatmapToStdout) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string a = test::outputPath("stdout_cmp_a.png"), b = test::outputPath("stdout_cmp_b.png");
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 48x27").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --size 48x27 --model blinn-phong").code, 0);
    SplitResult json = runSplit("compare " + a + " " + b + " --json -");
    EXPECT_EQ(json.code, 1) << json.err;  // Phong against Blinn-Phong fails the gates
    EXPECT_EQ(json.out.rfind("{", 0), 0u) << json.out;
    EXPECT_NE(json.out.find("\"pass\": false"), std::string::npos) << json.out;
    EXPECT_EQ(json.out.find("FAIL"), std::string::npos) << "the summary goes to stderr";
    EXPECT_NE(json.err.find("FAIL"), std::string::npos) << json.err;

    const std::string heat = test::outputPath("stdout_cmp_heat.png");
    ASSERT_EQ(run("compare " + a + " " + b + " --diff " + heat).code, 1);
    SplitResult diff = runSplit("compare " + a + " " + b + " --diff - -q");
    EXPECT_EQ(diff.code, 1) << diff.err;
    EXPECT_EQ(diff.out, readAll(heat));
    EXPECT_EQ(diff.err, "FAIL\n");
    EXPECT_EQ(runSplit("compare " + a + " " + b + " --diff - --json -").code, 2) << "one stdout, one output";
}

TEST(CliOutputs, LongestOutputNamesWork) {
    // 254 bytes: the old "<name>.tmp.<pid>.<n>" temporary pushed it past NAME_MAX (255).
    const std::string dir = freshDir("long_name");
    const std::string name = std::string(250, 'x') + ".png";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/" + name + " --size 32x18");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(readPng(dir + "/" + name).width, 32);
    EXPECT_EQ(listDir(dir), std::vector<std::string>{name});
}

TEST(CliOutputs, FileThenFolderAreSyncedAroundTheRename) {
    const std::string dir = freshDir("sync_order");
    const std::string log = test::outputPath("sync_order_probe.log");
    fs::remove(log);
    std::string env;
    for (const std::string& v : probeEnvironment(log, 0)) env += v + " ";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 32x18", env);
    ASSERT_EQ(r.code, 0) << r.out;
    const std::vector<std::string> calls = linesWith(readAll(log), dir);
    ASSERT_GE(calls.size(), 3u) << readAll(log);
    // The data is durable before it gets the name, and the name is durable before shadelab says done.
    EXPECT_EQ(calls.front().rfind("fsync file " + dir + "/", 0), 0u) << calls.front();
    EXPECT_EQ(calls[calls.size() - 2].rfind("rename " + dir + "/.shadelab.", 0), 0u) << calls[calls.size() - 2];
    EXPECT_NE(calls[calls.size() - 2].find(" " + dir + "/out.png"), std::string::npos) << calls[calls.size() - 2];
    EXPECT_EQ(calls.back(), "fsync dir " + dir);
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliOutputs, SignalDuringTheWriteLeavesNothing) {
    // The probe holds the fsync of the new file for 5 s: the data is written and nothing is renamed yet.
    // The signal arrives then, as a Ctrl-C, kill or closed terminal would during a slow write.
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        SCOPED_TRACE(strsignal(sig));
        const std::string dir = freshDir("signal_" + std::to_string(sig));
        std::ofstream(dir + "/out.png") << "previous";
        const std::string log = test::outputPath("signal_probe_" + std::to_string(sig) + ".log");
        fs::remove(log);

        std::vector<std::string> args = {SHADELAB_BINARY, "render", scene, "-o", dir + "/out.png", "--size", "64x36"};
        std::vector<std::string> env = probeEnvironment(log, 5000);
        for (char** e = environ; *e; ++e) env.push_back(*e);
        std::vector<char*> argv, envp;
        for (std::string& a : args) argv.push_back(a.data());
        for (std::string& e : env) envp.push_back(e.data());
        argv.push_back(nullptr);
        envp.push_back(nullptr);
        // Default dispositions: a test runner started in the background ignores SIGINT, and its children too.
        posix_spawnattr_t attr;
        posix_spawnattr_init(&attr);
        sigset_t defaults, none;
        sigemptyset(&defaults);
        sigemptyset(&none);
        for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, s);
        posix_spawnattr_setsigdefault(&attr, &defaults);
        posix_spawnattr_setsigmask(&attr, &none);
        posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
        pid_t pid = -1;
        ASSERT_EQ(posix_spawn(&pid, SHADELAB_BINARY, nullptr, &attr, argv.data(), envp.data()), 0);
        posix_spawnattr_destroy(&attr);

        bool midWrite = false, exited = false;
        int status = 0;
        for (int waited = 0; waited < 20000 && !midWrite && !exited; waited += 5) {
            midWrite = !linesWith(readAll(log), "fsync file " + dir + "/").empty();
            exited = !midWrite && ::waitpid(pid, &status, WNOHANG) == pid;
            if (!midWrite && !exited) ::usleep(5000);
        }
        if (!exited) {
            ::kill(pid, midWrite ? sig : SIGKILL);
            ::waitpid(pid, &status, 0);
        }
        ASSERT_TRUE(midWrite) << "the render never reached the write; probe log:\n" << readAll(log);
        EXPECT_TRUE(WIFSIGNALED(status)) << "exit code " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        EXPECT_EQ(WIFSIGNALED(status) ? WTERMSIG(status) : 0, sig) << "ended by the signal itself";
        EXPECT_TRUE(linesWith(readAll(log), "rename").empty()) << readAll(log);
        EXPECT_EQ(readAll(dir + "/out.png"), "previous");
        EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
    }
}
