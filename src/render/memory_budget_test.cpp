// The memory budget every front end holds a render to: --max-memory's sizes, the request's floor in check() (a
// limit no render of the request could fit is refused by field), the estimate's parts (each grows with what it
// counts), the over-limit reason, and the environment map's load refused from its header before a pixel is
// decoded. The measured side (a real process's peak against the estimate) is tests/hostile_input_test.cpp's.
#include "render/memory_budget.h"

#include "render/render_request.h"
#include "scene/environment_load.h"
#include "scene/scene_load.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace shadelab;
using render::Engine;
using render::RenderRequest;

namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;

Scene defaultScene() { return loadScene(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/default.json"); }

RenderRequest request(Engine engine, int width, int height) {
    RenderRequest r;
    r.engine = engine;
    r.width = width;
    r.height = height;
    return r;
}

std::string reasonOf(const RenderRequest& r) {
    const std::optional<render::RequestProblem> p = render::check(r);
    return p ? p->field + ": " + p->reason : "";
}

std::string writeFile(const std::string& name, const std::string& bytes) {
    const std::filesystem::path dir(SHADELAB_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

}  // namespace

TEST(MemoryBudget, SizesAreReadAsTheCommandLineWritesThem) {
    EXPECT_EQ(render::parseMemorySize("512M"), 512 * kMiB);
    EXPECT_EQ(render::parseMemorySize("512MiB"), 512 * kMiB);
    EXPECT_EQ(render::parseMemorySize("2G"), 2048 * kMiB);
    EXPECT_EQ(render::parseMemorySize("1.5g"), 1536 * kMiB);
    EXPECT_EQ(render::parseMemorySize("4096"), 4096 * kMiB);  // a bare number is MiB
    EXPECT_EQ(render::parseMemorySize("0.5"), kMiB / 2);
    for (const char* bad : {"lots", "", "0", "-1", "1T", "nan", "inf", "1e30G", "12 M", "0.0000001"}) {
        try {
            render::parseMemorySize(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const SettingError& e) {
            EXPECT_EQ(e.field(), "max_memory");
            EXPECT_EQ(e.reason(), "expected a size such as 512M or 2G, got '" + std::string(bad) + "'");
        }
    }
}

TEST(MemoryBudget, CheckRefusesALimitBelowWhatAnyRenderOfTheRequestNeeds) {
    for (Engine e : {Engine::Raster, Engine::Trace, Engine::Both, Engine::Path}) {
        RenderRequest r = request(e, 64, 48);
        EXPECT_EQ(reasonOf(r), "") << toString(e);  // unset: the default, checked against the scene later
        const uint64_t least = render::minimumRenderBytes(r);
        r.maxMemory = least;
        EXPECT_EQ(reasonOf(r), "") << toString(e);
        r.maxMemory = least - 1;
        EXPECT_EQ(reasonOf(r).rfind("max_memory: must be at least ", 0), 0u) << reasonOf(r);
        EXPECT_NE(reasonOf(r).find("for a 64x48 " + std::string(toString(e)) + " render"), std::string::npos);
        // The negative control of the old budget: 1 MiB was accepted for a 108 MB raster render.
        r.maxMemory = kMiB;
        EXPECT_NE(reasonOf(r).find("got 1 MiB"), std::string::npos) << reasonOf(r);
    }
    // Whatever the scene, the process and the rasterizer's GL context come first: more than 64 MiB for a 1x1
    // raster render, and the pixels of a 16384² path render (about 20 GiB) with any scene.
    EXPECT_GT(render::minimumRenderBytes(request(Engine::Raster, 1, 1)), 64 * kMiB);
    EXPECT_GT(render::minimumRenderBytes(request(Engine::Path, 16384, 16384)), 20000 * kMiB);
    EXPECT_LT(render::minimumRenderBytes(request(Engine::Trace, 1, 1)), 16 * kMiB);
}

TEST(MemoryBudget, TheEstimateCountsWhatTheSceneAdds) {
    Scene scene = defaultScene();
    for (Engine e : {Engine::Raster, Engine::Trace, Engine::Both, Engine::Path}) {
        const RenderRequest r = request(e, 320, 180);
        EXPECT_GE(render::estimateRenderBytes(scene, r), render::minimumRenderBytes(r)) << toString(e);
        EXPECT_GE(render::estimateRenderBytes(scene, r, render::RenderOutput::Image), render::minimumRenderBytes(r));
    }
    // Python keeps the rasterizer's linear floats: 16 bytes a pixel more than the PNG's rows.
    const RenderRequest raster = request(Engine::Raster, 1024, 1024);
    EXPECT_GE(render::estimateRenderBytes(scene, raster, render::RenderOutput::Image),
              render::estimateRenderBytes(scene, raster) + 1024 * 1024 * 8);
    // Shadow maps: an 8192² map is 256 MiB a layer; without shadows there are none.
    const uint64_t base = render::estimateRenderBytes(scene, raster);
    scene.raster.shadowMapSize = 8192;
    EXPECT_GE(render::estimateRenderBytes(scene, raster), base + 256 * kMiB);
    scene.terms.shadows = false;
    EXPECT_LT(render::estimateRenderBytes(scene, raster), base);
    // Reflection cubes: 6 faces, 12 bytes a texel, for each reflective sphere (the default scene's mirror):
    // 2048² faces instead of 128² add 6·(2048² − 128²)·12 bytes.
    scene = defaultScene();
    ASSERT_EQ(scene.raster.reflectionCubeSize, 128);
    scene.raster.reflectionCubeSize = 2048;
    EXPECT_GE(render::estimateRenderBytes(scene, raster), base + 6 * (2048ull * 2048 - 128 * 128) * 12);
}

TEST(MemoryBudget, TheEnvironmentMapIsCounted) {
    Scene sky = loadScene(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/pbr-sky.json");
    ASSERT_TRUE(sky.environment && sky.environment->map);
    const uint64_t atlas = sky.environment->map->atlas.size() * sizeof(float);
    // The rasterizer uploads the atlas; the path tracer builds its sampler over level 0's texels.
    Scene withoutMap = sky;
    withoutMap.environment->map = nullptr;
    EXPECT_GE(render::estimateRenderBytes(sky, request(Engine::Raster, 64, 48)),
              render::estimateRenderBytes(withoutMap, request(Engine::Raster, 64, 48)) + atlas);
    const uint64_t side = uint64_t(sky.environment->map->size);
    EXPECT_GE(render::estimateRenderBytes(sky, request(Engine::Path, 64, 48)),
              render::estimateRenderBytes(withoutMap, request(Engine::Path, 64, 48)) + 6 * side * side * 16);
    // The load: the file, its pixels as floats (16 Mpixels: 192 MiB) and the prefilter's cube and atlas.
    EXPECT_GE(environmentLoadBytes(4096, 4096, 0), 4096ull * 4096 * 12);
    EXPECT_GT(environmentLoadBytes(4096, 4096, 64 * kMiB), environmentLoadBytes(4096, 4096, 0));
}

TEST(MemoryBudget, AnEnvironmentMapOverTheLimitIsRefusedFromItsHeader) {
    // A header that claims 4096x4096 pixels and holds none: decoding it would fail as truncated, so the limit's
    // message proves the refusal came from the header, before a pixel (192 MiB of floats) was allocated.
    const std::string path =
        writeFile("claims-16-mpixels.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4096 +X 4096\n");
    try {
        loadPrefilteredHdr(path, {}, MemoryLimit{100 * kMiB, "--max-memory"});
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": a 4096x4096 environment map needs about " +
                                             render::memoryText(environmentLoadBytes(4096, 4096, 48), true) +
                                             " to read and prefilter, over the limit of 100 MiB (--max-memory)");
    }
    // The negative control: without the limit the same file goes on to be decoded, and is truncated.
    try {
        loadPrefilteredHdr(path);
        ADD_FAILURE() << "decoded a file without pixels";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("file is truncated"), std::string::npos) << e.what();
    }
}

TEST(MemoryBudget, OverTheLimitNamesTheNeedAndTheLimit) {
    const Scene scene = defaultScene();
    RenderRequest r = request(Engine::Path, 16384, 16384);
    r.maxMemory = 30000 * kMiB;
    EXPECT_FALSE(render::memoryProblem(scene, r));
    r.engine = Engine::Both;
    r.maxMemory = render::minimumRenderBytes(r);
    const uint64_t need = render::estimateRenderBytes(scene, r);
    ASSERT_GT(need, *r.maxMemory);  // the default scene's shadow maps and mirror sphere's cube
    EXPECT_EQ(*render::memoryProblem(scene, r), "a 16384x16384 both render of this scene needs about " +
                                                    render::memoryText(need, true) + ", over the limit of " +
                                                    render::memoryText(*r.maxMemory));
    r.maxMemory = need;
    EXPECT_FALSE(render::memoryProblem(scene, r));
    r.maxMemory = need - 1;
    EXPECT_TRUE(render::memoryProblem(scene, r));
    EXPECT_EQ(render::memoryText(1), "1 byte");
    EXPECT_EQ(render::memoryText(1000), "1000 bytes");
    EXPECT_EQ(render::memoryText(kMiB + 1), "1 MiB");
    EXPECT_EQ(render::memoryText(kMiB + 1, true), "2 MiB");
}

TEST(MemoryBudget, TheDefaultIsHalfOfMemoryWithinTheAddressSpaceLimit) {
    const uint64_t limit = render::defaultMaxMemory();
    EXPECT_GT(limit, 0u);
    RenderRequest r;
    EXPECT_EQ(render::memoryLimit(r), limit);
    r.maxMemory = 123 * kMiB;
    EXPECT_EQ(render::memoryLimit(r), 123 * kMiB);
}

// What the CLI warms for a software raster render: the context's share, the colour and depth targets and the
// 8-bit image; nothing for a trace; and a band's target, not the whole image's, once the image is drawn in bands.
TEST(MemoryBudget, TheSoftwareRasterHeapIsTheContextTheTargetsAndTheImage) {
    const uint64_t hd = render::softwareRasterHeapBytes(request(Engine::Raster, 1920, 1080));
    EXPECT_EQ(hd, 24 * kMiB + uint64_t(1920) * 1080 * (12 + 4 + 3));
    EXPECT_EQ(render::softwareRasterHeapBytes(request(Engine::Trace, 1920, 1080)), 0u);
    EXPECT_EQ(render::softwareRasterHeapBytes(request(Engine::Path, 1920, 1080)), 0u);
    EXPECT_LT(render::softwareRasterHeapBytes(request(Engine::Raster, 320, 180)), hd);
    // 8K is four-plus bands of about 2 M samples each: the targets stay near 1080p's, the image grows.
    const uint64_t eightK = render::softwareRasterHeapBytes(request(Engine::Raster, 7680, 4320));
    EXPECT_LT(eightK, hd + uint64_t(7680) * 4320 * 3);
    EXPECT_GT(eightK, uint64_t(7680) * 4320 * 3);
}
