// Numbers that overflow: a texture transform or texture coordinates that send uv to infinity or NaN, .hdr
// texels at the format's maximum, emission and radii at a float's limit. Each case runs the real binary (an
// out-of-bounds read fails under ASan even when it does not crash) and checks the image it writes: no pixel
// without a finite value, and none of the silent black that used to follow. The negative control makes the
// rasterizer write NaN: the command line must count those pixels and say so.
#include "cli_run.h"
#include "image/image.h"
#include "image/png.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace shadelab;
using test::run;

namespace {

std::string dirFor(const std::string& name) {
    const std::string dir = test::outputPath("hostile_numbers/" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writeBytes(const std::string& path, const void* data, size_t size) {
    std::ofstream(path, std::ios::binary).write(static_cast<const char*>(data), std::streamsize(size));
}

// A textured quad facing +z (uv = `uvScale` × the corner's unit uv), its 4×4 checker texture, and
// `transform` as the base-colour texture's KHR_texture_transform (raw JSON). Returns the .gltf path.
std::string writeTexturedQuad(const std::string& dir, const std::string& transform, float uvScale = 1.0f) {
    const float pos[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const float uv[8] = {0, uvScale, uvScale, uvScale, uvScale, 0, 0, 0};
    const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    std::vector<char> bin(sizeof pos + sizeof uv + sizeof idx);
    std::memcpy(bin.data(), pos, sizeof pos);
    std::memcpy(bin.data() + sizeof pos, uv, sizeof uv);
    std::memcpy(bin.data() + sizeof pos + sizeof uv, idx, sizeof idx);
    writeBytes(dir + "/quad.bin", bin.data(), bin.size());
    Image8 tex;
    tex.width = tex.height = 4;
    tex.channels = 3;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int k = 0; k < 3; ++k) tex.data.push_back((x + y) % 2 ? 230 : 40);
    writePng(dir + "/tex.png", tex);
    const std::string gltf = R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_texture_transform"],
  "buffers": [{"uri": "quad.bin", "byteLength": 92}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "images": [{"uri": "tex.png"}], "textures": [{"source": 0}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
                  "extensions": {"KHR_texture_transform": )" +
                             transform + R"(}}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    std::ofstream(dir + "/quad.gltf") << gltf;
    return dir + "/quad.gltf";
}

// The mean 8-bit level of a PNG, and the share of its pixels that are pure black.
struct Levels {
    double mean = -1;
    double blackShare = 1;
};
Levels levelsOf(const std::string& png) {
    const Image8 img = readPng(png);
    Levels l{0, 0};
    size_t black = 0;
    for (size_t i = 0; i < img.data.size(); i += size_t(img.channels)) {
        int sum = 0;
        for (int k = 0; k < 3; ++k) sum += img.data[i + size_t(k)];
        l.mean += sum / 3.0;
        black += sum == 0;
    }
    const double pixels = double(img.width) * img.height;
    l.mean /= pixels;
    l.blackShare = double(black) / pixels;
    return l;
}

const char* kNoFiniteValue = "have no finite value";

}  // namespace

TEST(HostileNumbers, TextureTransformsThatOverflowNeitherCrashNorBlackenTheImage) {
    struct Case {
        const char* name;
        std::string transform;
        float uvScale;
        const char* warning;  // expected in the output, or nullptr
    };
    const Case cases[] = {
        {"scale_1e38", R"({"scale": [1e38, 1e38]})", 1.0f, nullptr},
        {"rotation_1e308", R"({"rotation": 1e308})", 1.0f, "rotation is not finite; ignored"},
        {"offset_1e308", R"({"offset": [1e308, 0]})", 1.0f, "offset must be two finite numbers; ignored"},
        {"texcoord_3e38_scale_2", R"({"scale": [2, 2]})", 3e38f, nullptr},
        {"texcoord_huge", R"({"texCoord": 1e300})", 1.0f, "texCoord is not a whole number"},
    };
    for (const Case& c : cases) {
        const std::string dir = dirFor(c.name);
        const std::string model = writeTexturedQuad(dir, c.transform, c.uvScale);
        for (const char* renderer : {"trace", "path", "raster"}) {
            const std::string out = dir + "/" + renderer + ".png";
            const test::Result r =
                run(std::string("render ") + model + " --renderer " + renderer + " --size 48x36 --spp 4 -o " + out);
            EXPECT_EQ(r.code, 0) << c.name << " " << renderer << ": " << r.out;
            EXPECT_EQ(r.out.find(kNoFiniteValue), std::string::npos) << c.name << " " << renderer << ": " << r.out;
            if (c.warning) {
                EXPECT_NE(r.out.find(c.warning), std::string::npos) << c.name << " " << renderer << ": " << r.out;
            }
            if (r.code == 0) {
                EXPECT_LT(levelsOf(out).blackShare, 0.5) << c.name << " " << renderer << " " << out;
            }
        }
    }
}

// An .hdr whose every texel is RGBE (255, 255, 255, 255), about 1.7e38: a sky that must render white, and the
// same map with one such texel in an ordinary grey sky.
TEST(HostileNumbers, HdrTexelsAtTheFormatsMaximumRenderAsTheHugeFiniteValuesTheyAre) {
    for (bool onlyOne : {false, true}) {
        const std::string dir = dirFor(onlyOne ? "hdr_one_max_texel" : "hdr_max_sky");
        const int w = 16, h = 8;
        std::string hdr =
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " + std::to_string(w) + "\n";
        for (int i = 0; i < w * h; ++i) {
            const bool max = !onlyOne || i == 37;
            const unsigned char v = max ? 255 : 128;
            const unsigned char rgbe[4] = {v, v, v, v};
            hdr.append(reinterpret_cast<const char*>(rgbe), 4);
        }
        writeBytes(dir + "/sky.hdr", hdr.data(), hdr.size());
        std::ofstream(dir + "/scene.json") << R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
  "environment": {"hdr": "sky.hdr"}, "lights": [],
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"baseColor": 0.8, "roughness": 0.4}}],
  "model": "pbr"})";
        for (const char* renderer : {"raster", "trace", "path"}) {
            const std::string out = dir + "/" + renderer + ".png";
            const test::Result r =
                run(std::string("render ") + dir + "/scene.json --renderer " + renderer + " --size 40x30 -o " + out);
            ASSERT_EQ(r.code, 0) << renderer << ": " << r.out;
            EXPECT_EQ(r.out.find(kNoFiniteValue), std::string::npos) << renderer << ": " << r.out;
            const Levels l = levelsOf(out);
            EXPECT_LT(l.blackShare, 0.01) << renderer << " " << out;
            if (!onlyOne) {
                EXPECT_GT(l.mean, 250.0) << renderer << " " << out << ": a sky of 1.7e38 is white";
            }
        }
    }
}

// Values beyond the scene limits are refused with the field and the bound; values at the limits render with
// every pixel finite.
TEST(HostileNumbers, EmissionAndRadiiAtAFloatsLimitAreRefusedAndThoseAtTheBoundRender) {
    const std::string dir = dirFor("limits");
    auto scene = [&](const std::string& name, const std::string& emission, const std::string& radius) {
        const std::string path = dir + "/" + name + ".json";
        std::ofstream(path) << R"({"camera": {"position": [0, 0, 6], "target": [0, 0, 0]},
  "lights": [{"type": "point", "position": [2, 3, 4], "color": 1}],
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
              {"type": "sphere", "name": "lamp", "center": [0, 0, -)" +
                                   radius + R"(], "radius": )" + radius + R"(, "material": {"emission": )" + emission +
                                   R"(}}]})";
        return path;
    };
    const test::Result emission = run("render " + scene("emission", "3.4e38", "1") + " -o " + dir + "/e.png");
    EXPECT_EQ(emission.code, 1) << emission.out;
    EXPECT_NE(emission.out.find("emission"), std::string::npos) << emission.out;
    EXPECT_NE(emission.out.find("1e+15"), std::string::npos) << emission.out;
    const test::Result radius = run("render " + scene("radius", "1", "1e30") + " -o " + dir + "/r.png");
    EXPECT_EQ(radius.code, 1) << radius.out;
    EXPECT_NE(radius.out.find("radius"), std::string::npos) << radius.out;
    EXPECT_FALSE(fs::exists(dir + "/e.png") || fs::exists(dir + "/r.png"));

    const std::string atBound = scene("at_bound", "1e15", "1e14");
    for (const char* renderer : {"raster", "trace", "path"}) {
        const std::string out = dir + "/" + renderer + ".png";
        const test::Result r =
            run("render " + atBound + " --renderer " + std::string(renderer) + " --size 40x30 --spp 4 -o " + out);
        EXPECT_EQ(r.code, 0) << renderer << ": " << r.out;
        EXPECT_EQ(r.out.find(kNoFiniteValue), std::string::npos) << renderer << ": " << r.out;
        if (r.code == 0) {
            EXPECT_LT(levelsOf(out).blackShare, 0.05) << renderer << " " << out;
        }
    }
}

// Negative control: the scene bounds leave no file-borne overflow to show, so a fragment shader is made to
// write NaN (SHADELAB_SHADER_DIR: a copy of shaders/ with sphere.frag's output replaced). The command line
// must count those pixels and say so in one warning, and --strict must refuse to write the image.
TEST(HostileNumbers, NegativeControlNanFromTheRendererIsCountedAndSaid) {
    const std::string dir = dirFor("nan_shader");
    fs::copy(test::sourcePath("shaders"), dir + "/shaders", fs::copy_options::recursive);
    std::string frag = test::readAll(dir + "/shaders/sphere.frag");
    const std::string line = "o_color = vec4(I, 1.0f);";
    ASSERT_NE(frag.find(line), std::string::npos) << "sphere.frag changed; update this test";
    frag.replace(frag.find(line), line.size(), "o_color = vec4(I * sqrt(-1.0f - dot(I, I)), 1.0f);");
    std::ofstream(dir + "/shaders/sphere.frag") << frag;
    std::ofstream(dir + "/scene.json") << R"({"camera": {"position": [0, 0, 6], "target": [0, 0, 0]},
  "lights": [{"type": "point", "position": [2, 3, 4], "color": 1}],
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
    const std::string env = "SHADELAB_SHADER_DIR=" + dir + "/shaders ";
    const test::Result r = run("render " + dir + "/scene.json --size 40x30 -o " + dir + "/nan.png", env);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find(kNoFiniteValue), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("raster: "), std::string::npos) << r.out;
    EXPECT_EQ(test::lineCount(r.out), 1) << r.out;
    const test::Result strict =
        run("render " + dir + "/scene.json --strict --size 40x30 -o " + dir + "/strict.png", env);
    EXPECT_EQ(strict.code, 1) << strict.out;
    EXPECT_NE(strict.out.find("an error under --strict"), std::string::npos) << strict.out;
    EXPECT_FALSE(fs::exists(dir + "/strict.png"));
    // And without the altered shader the same scene renders with every pixel finite.
    const test::Result plain = run("render " + dir + "/scene.json --size 40x30 -o " + dir + "/plain.png");
    EXPECT_EQ(plain.code, 0) << plain.out;
    EXPECT_EQ(plain.out.find(kNoFiniteValue), std::string::npos) << plain.out;
}
