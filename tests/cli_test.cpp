// CLI tests: `shadelab render` writes a real PNG; bad input exits 1 with one line naming the
// file; usage errors exit 2; `compare` exits by its gates. What the CLI's outputs must never destroy is
// cli_outputs_test.cpp's.
#include "cli_run.h"
#include "image/png.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace shadelab;
using namespace shadelab::test;
namespace fs = std::filesystem;

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
    for (const char* flags :
         {"--time-limit 1", "--estimator bsdf", "--light-paths indirect", "--sampler independent"}) {
        Result bad = run("render " + scene + " -o " + out + " --renderer trace " + flags);
        EXPECT_EQ(bad.code, 2) << flags << ": " << bad.out;
        const std::string flag = std::string(flags).substr(0, std::string(flags).find(' '));
        EXPECT_NE(bad.out.find(flag + ": is for the path tracer"), std::string::npos) << bad.out;
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

// Compared with the rasterizer (one bounce), the reference traces one bounce too, unless --depth.
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
        {"--model gouraud",
         "shadelab: usage error: --model: expected phong, blinn-phong, pbr or disney, got 'gouraud'"},
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

// The one place the version is written is CMakeLists.txt's project(shadelab VERSION x.y.z): --version prints it,
// as the Python module's build_info and setup.py do.
TEST(Cli, VersionIsTheCMakeProjectVersion) {
    const std::string cmake = readAll(test::sourcePath("CMakeLists.txt"));
    std::smatch m;
    ASSERT_TRUE(std::regex_search(cmake, m, std::regex(R"(project\(\s*shadelab\s[^)]*VERSION\s+([0-9][0-9.]*))")))
        << "no project(shadelab VERSION ...) in CMakeLists.txt";
    Result r = run("--version");
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out, "shadelab " + m[1].str() + "\n");
}

TEST(Cli, HelpListsEveryCommand) {
    Result r = run("--help");
    ASSERT_EQ(r.code, 0);
    for (const char* command : {"render", "compare", "view"}) {
        const std::string entry = std::string("\n  ") + command + " ";
        EXPECT_NE(r.out.find(entry), std::string::npos) << command << " is not listed in:\n" << r.out;
    }
}

// docs/cli.md documents every flag each command's --help lists, so the reference never falls behind the binary
// (the viewer's only where this build has it).
TEST(Cli, DocsCoverEveryFlagOfEveryCommand) {
    const std::string docs = readAll(test::sourcePath("docs/cli.md"));
    const std::regex flag(R"(--[a-z][a-z0-9-]*)");
    for (const char* command : {"render", "compare", "view"}) {
        Result r = run(std::string(command) + " --help");
        if (r.code != 0 && std::string(command) == "view") continue;
        ASSERT_EQ(r.code, 0) << command << ": " << r.out;
        std::set<std::string> flags;
        for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), flag); it != std::sregex_iterator(); ++it)
            flags.insert(it->str());
        EXPECT_GE(flags.size(), 3u) << command << " --help lists almost no flags (the check would be blind):\n"
                                    << r.out;
        for (const std::string& f : flags)
            EXPECT_NE(docs.find("`" + f), std::string::npos) << command << " " << f << " is not in docs/cli.md";
    }
    // Negative control: the same check on the docs with one flag's entries spelt otherwise finds it missing.
    const std::string edited = std::regex_replace(docs, std::regex("`--exposure"), "`--exp0sure");
    EXPECT_EQ(edited.find("`--exposure"), std::string::npos);
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

// A glTF whose base-colour PNG is cut short: by default one warning and the factor alone (exit 0);
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

// A glTF file is a scene under phong: its sheen (pbr's layer) would vanish without a word. One warning line names
// the layer and says how to see it (an error under --strict); with --model pbr there is nothing to say (control).
TEST(Cli, LayersAnotherModelHidesAreSaidOnce) {
    const std::string model = test::sourcePath("assets/models/layers/sheen_grid.gltf");
    const std::string out = test::outputPath("layers_hidden.png");
    const Result phong = run("render " + model + " -o " + out + " --size 64x36");
    EXPECT_EQ(phong.code, 0) << phong.out;
    EXPECT_EQ(lineCount(phong.out), 1) << phong.out;
    EXPECT_NE(phong.out.find("sheen_grid.gltf: glTF's sheen shades only under pbr"), std::string::npos) << phong.out;
    EXPECT_NE(phong.out.find("--model pbr"), std::string::npos) << phong.out;
    EXPECT_EQ(run("render " + model + " -o " + out + " --size 64x36 --strict").code, 1);
    const Result pbr = run("render " + model + " -o " + out + " --size 64x36 --model pbr --strict");
    EXPECT_EQ(pbr.code, 0) << pbr.out;
    EXPECT_EQ(pbr.out, "");
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

// render --coverage writes the ids beside the image; compare --coverage-a/-b then puts silhouette pixels in the
// band. A picture spoiled only on silhouettes passes with coverage and fails without it; spoiled on one
// interior pixel, it fails with coverage too (the negative control).
TEST(CliCompare, CoverageFilesMakeSilhouettesTheBand) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string a = test::outputPath("cov_a.png"), ca = test::outputPath("cov_a-coverage.png");
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 160x90 --coverage " + ca).code, 0);
    const Image8 image = readPng(a), ids = readPng(ca);
    ASSERT_EQ(ids.width, 160);
    auto id = [&](int x, int y) {
        const uint8_t* p = ids.pixel(std::clamp(x, 0, 159), std::clamp(y, 0, 89));
        return p[0] | p[1] << 8 | p[2] << 16;
    };
    Image8 edges = image, inside = image;
    int silhouettes = 0;
    bool spoiledInside = false;
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x) {
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) edge |= id(x + dx, y + dy) != id(x, y);
            uint8_t* p = &(edge ? edges : inside).data[(size_t(y) * 160 + size_t(x)) * size_t(image.channels)];
            if (edge && (x + y) % 4 == 0) {
                p[0] = uint8_t(255 - p[0]);
                ++silhouettes;
            } else if (!edge && !spoiledInside && id(x, y) != 0 && x > 80) {
                p[0] = uint8_t(255 - p[0]);
                spoiledInside = true;
            }
        }
    ASSERT_GT(silhouettes, 50);
    ASSERT_TRUE(spoiledInside);
    const std::string b = test::outputPath("cov_b.png"), c = test::outputPath("cov_c.png");
    writePng(b, edges);
    writePng(c, inside);
    const std::string coverage = " --coverage-a " + ca + " --coverage-b " + ca;
    Result banded = run("compare " + a + " " + b + coverage);
    EXPECT_EQ(banded.code, 0) << banded.out;
    EXPECT_NE(banded.out.find("band"), std::string::npos) << banded.out;
    Result plain = run("compare " + a + " " + b);
    EXPECT_EQ(plain.code, 1) << "without coverage the silhouettes are interior pixels: " << plain.out;
    Result interior = run("compare " + a + " " + c + coverage);
    EXPECT_EQ(interior.code, 1) << interior.out;

    // Usage and input errors: one coverage alone, a coverage of the wrong size, --coverage where none is kept.
    Result alone = run("compare " + a + " " + b + " --coverage-a " + ca);
    EXPECT_EQ(alone.code, 2) << alone.out;
    EXPECT_NE(alone.out.find("--coverage-a: needs --coverage-b"), std::string::npos) << alone.out;
    const std::string small = test::outputPath("cov_small.png");
    ASSERT_EQ(
        run("render " + scene + " -o " + test::outputPath("cov_s.png") + " --size 80x45 --coverage " + small).code, 0);
    Result sized = run("compare " + a + " " + b + " --coverage-a " + ca + " --coverage-b " + small);
    EXPECT_EQ(sized.code, 2) << sized.out;
    EXPECT_NE(sized.out.find("coverage is 80x45"), std::string::npos) << sized.out;
    Result path = run("render " + scene + " -o " + c + " --renderer path --coverage " + small);
    EXPECT_EQ(path.code, 2) << path.out;
    Result self = run("render " + scene + " -o " + a + " --coverage " + a);
    EXPECT_EQ(self.code, 2) << self.out;
}

// A broken or missing shader: one line that names the shader file (and line for a compile error).
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

// --exposure and --view-transform: refused values are usage errors naming the flag, in one line (exit 2); a
// scene file's bad "display" is bad input naming the file and the field (exit 1); the flags override the
// file's display field by field.
TEST(CliDisplay, FlagsAndSceneFieldsRefuseBadValuesInOneLine) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::pair<const char*, const char*> usage[] = {
        {"--exposure 40", "shadelab: usage error: --exposure: must be in [-16, 16] stops, got 40"},
        {"--exposure -16.5", "shadelab: usage error: --exposure: must be in [-16, 16] stops, got -16.5"},
        {"--exposure nan", "shadelab: usage error: --exposure: must be in [-16, 16] stops, got nan"},
        {"--exposure bright", "shadelab: usage error: --exposure: expected a number, got 'bright'"},
        {"--view-transform aces", "shadelab: usage error: --view-transform: expected standard or filmic, got 'aces'"},
    };
    const std::string never = test::outputPath("display_never.png");
    fs::remove(never);
    for (const auto& [flags, message] : usage) {
        Result r = run("render " + scene + " -o " + never + " " + flags);
        EXPECT_EQ(r.code, 2) << flags;
        EXPECT_EQ(r.out, std::string(message) + "\n") << flags;
    }
    const std::pair<const char*, const char*> files[] = {
        {R"({"display": {"exposure": 40}})", "display.exposure: must be in [-16, 16] stops, got 40"},
        {R"({"display": {"exposure": "x"}})", "display.exposure: expected a number, got string"},
        {R"({"display": {"viewTransform": "aces"}})",
         "display.viewTransform: unknown view transform 'aces'; expected standard or filmic"},
    };
    int i = 0;
    for (const auto& [text, message] : files) {
        const std::string bad = writeText("display_bad_" + std::to_string(i++) + ".json", text);
        Result r = run("render " + bad + " -o " + never + " --size 16x12");
        EXPECT_EQ(r.code, 1) << text;
        EXPECT_EQ(r.out, "shadelab: error: " + bad + ": " + message + "\n") << text;
    }
    EXPECT_FALSE(fs::exists(never));
    // Good values: the file's display is used, and a flag overrides its field (the bytes equal those of the
    // same display given by flags alone).
    std::string text = readAll(scene);
    const size_t at = text.find('{');
    ASSERT_NE(at, std::string::npos);
    text.insert(at + 1, R"("display": {"exposure": -1.5, "viewTransform": "filmic"},)");
    const std::string filmicScene = writeText("display_filmic_scene.json", text);
    const std::string fromFile = test::outputPath("display_from_file.png"),
                      fromFlags = test::outputPath("display_from_flags.png"),
                      overridden = test::outputPath("display_overridden.png"),
                      plain = test::outputPath("display_plain.png");
    ASSERT_EQ(run("render " + filmicScene + " -o " + fromFile + " --size 96x54").code, 0);
    ASSERT_EQ(
        run("render " + scene + " -o " + fromFlags + " --size 96x54 --exposure -1.5 --view-transform filmic").code, 0);
    ASSERT_EQ(run("render " + filmicScene + " -o " + overridden +
                  " --size 96x54 --exposure 0 --view-transform "
                  "standard")
                  .code,
              0);
    ASSERT_EQ(run("render " + scene + " -o " + plain + " --size 96x54").code, 0);
    EXPECT_EQ(readAll(fromFile), readAll(fromFlags));
    EXPECT_EQ(readAll(overridden), readAll(plain));
    EXPECT_NE(readAll(fromFile), readAll(plain)) << "negative control: the display changed nothing";
}

namespace {

// Pixels whose three channels are all 255: clipped to white.
int whitePixels(const Image8& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const uint8_t* p = img.pixel(x, y);
            n += p[0] == 255 && p[1] == 255 && p[2] == 255;
        }
    return n;
}

}  // namespace

// The Cornell box's lamp (emission 40) and the ceiling around it clip to flat white under Standard. Under the
// filmic curve the ceiling keeps its gradation; the lamp itself is far above the fit's saturation point
// (x ~ 7.24), so it takes an exposure of -3 stops (lamp 5) to bring it below 255, where Standard at the same
// exposure still clips it: filmic at -3 has no white pixel at all.
TEST(CliDisplay, FilmicKeepsTheCornellLampFromClipping) {
    const std::string scene = test::sourcePath("assets/scenes/cornell.json");
    auto render = [&](const std::string& name, const std::string& flags) {
        const std::string out = test::outputPath("cornell_display_" + name + ".png");
        Result r = run("render " + scene + " -o " + out + " --size 96x72 --renderer path --spp 8 " + flags);
        EXPECT_EQ(r.code, 0) << r.out;
        return whitePixels(readPng(out));
    };
    const int standard = render("standard", ""), filmic = render("filmic", "--view-transform filmic");
    const int standardDark = render("standard_m3", "--exposure -3"),
              filmicDark = render("filmic_m3", "--exposure -3 --view-transform filmic");
    std::printf("white pixels (of %d): standard %d, filmic %d, standard -3 stops %d, filmic -3 stops %d\n", 96 * 72,
                standard, filmic, standardDark, filmicDark);
    EXPECT_GT(standard, 2 * filmic) << "filmic should recover the ceiling around the lamp; images in "
                                    << test::outputPath("");
    EXPECT_GT(standardDark, 50) << "Standard at -3 stops still clips the lamp (the negative control)";
    EXPECT_EQ(filmicDark, 0) << "filmic at -3 stops: no pixel should be clipped";
}
