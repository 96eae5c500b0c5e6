// CLI tests (issue 2): `shadelab render` writes a real PNG; bad input exits 1 with one line naming the
// file; usage errors exit 2; a failed render leaves no output file behind.
#include "image/png.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

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
    text.replace(at, key.size(), R"({"type": "point", "position": [0, 1.5, 0]}, {"type": "point", "name": "warm key", "position": [1, 1.5, 0])");
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
    std::string bad = writeText("badcolor.json",
                                R"({"lights": [{"type": "point", "position": [0, 1, 0], "color": [1, 1]}]})");
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
        {"--model gouraud", "shadelab: usage error: --model: expected phong or blinn-phong, got 'gouraud'"},
        {"--renderer gpu", "shadelab: usage error: --renderer: expected raster, trace or both, got 'gpu'"},
        {"--terms ambient,glow", "shadelab: usage error: --terms: unknown term 'glow'; expected ambient, diffuse, "
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
    EXPECT_EQ(render(withRaster, "raster_flags_file_overridden.png", "--shadow-map-size auto --reflection-cube-size 128"),
              render(scene, "raster_flags_pcf_only.png", "--pcf"));
    EXPECT_EQ(render(withRaster, "raster_flags_all_overridden.png",
                     "--shadow-map-size auto --reflection-cube-size 128 --no-pcf"),
              base)
        << "--no-pcf turns the file's PCF off";
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
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                             fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
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
    Result r = run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 320x180",
                   "trap '' XFSZ; ulimit -f 8; ");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("File too large"), std::string::npos) << r.out;
    EXPECT_EQ(readAll(dir + "/out.png"), "previous");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliNothingLost, FullDisk) {
    std::string dir = test::outputPath("fulldisk");
    fs::create_directories(dir);
    if (std::system(("mountpoint -q " + dir + " || mount -t tmpfs -o size=64k tmpfs " + dir + " 2>/dev/null").c_str()) != 0)
        GTEST_SKIP() << "cannot mount a small tmpfs here (needs root); FileSizeLimitHitMidWrite covers the write path";
    for (const std::string& f : listDir(dir)) fs::remove(dir + "/" + f);
    std::ofstream(dir + "/out.png") << "previous";
    Result r = run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 640x360");
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
