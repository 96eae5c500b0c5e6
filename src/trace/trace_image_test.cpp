// Whole-image tracing: determinism across thread counts and tilings (floats, 8-bit pixels and PNG bytes),
// the k×k supersampling grid, the progressive API (every tile once, cancel, restart, progress), and the
// validation of TraceSettings. Failing image comparisons leave both images in the test output folder.
#include "trace/trace_image.h"
#include "image/encode.h"
#include "image/png.h"
#include "scene/view.h"
#include "shading/lighting.h"
#include "trace/progressive_trace.h"
#include "trace/trace_test_util.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

using namespace shadelab;
using namespace shadelab::trace;
using Clock = std::chrono::steady_clock;

namespace {

// Meshes (an icosphere and a box), spheres (a mirror, a glass one), a reflective checker plane, three lights,
// shadows and reflections: every code path of the integrator.
Scene busyScene() {
    Scene sc;
    sc.camera.position = {0.5f, 2.0f, 6.0f};
    sc.camera.target = {0.0f, 0.6f, 0.0f};
    sc.lights = {Light{}, Light{}, Light{}};
    sc.lights[0].position = {3, 5, 4};
    sc.lights[1].position = {-4, 3, 2};
    sc.lights[1].color = {0.4f, 0.5f, 0.9f};
    sc.lights[2].type = LightType::Directional;
    sc.lights[2].direction = {0.3f, -1.0f, -0.2f};
    sc.lights[2].color = glm::vec3(0.3f);
    Material shiny = test::plainMaterial({0.1f, 0.05f, 0.05f}, {0.7f, 0.2f, 0.2f}, glm::vec3(0.5f), 40.0f);
    shiny.kr = glm::vec3(0.3f);
    Material glass = test::plainMaterial(glm::vec3(0.0f), glm::vec3(0.05f), glm::vec3(0.8f), 200.0f);
    glass.kt = glm::vec3(0.9f);
    Material mirror = test::plainMaterial(glm::vec3(0.0f));
    mirror.kr = glm::vec3(0.9f);
    sc.spheres = {Sphere{"glass", {1.3f, 0.6f, 1.0f}, 0.6f, glass},
                  Sphere{"mirror", {-1.5f, 0.8f, -0.5f}, 0.8f, mirror}};
    Plane floor{"floor",
                {0, 1, 0},
                0.0f,
                test::plainMaterial(glm::vec3(0.1f), glm::vec3(0.8f)),
                Checker{{0.1f, 0.1f, 0.3f}, 0.5f}};
    floor.material.kr = glm::vec3(0.2f);
    sc.planes = {floor};
    sc.meshes = {Mesh{}, Mesh{}};
    sc.meshes[0].parts = {test::icospherePart({0.0f, 0.7f, 0.0f}, 0.7f, 3, shiny)};
    sc.meshes[1].parts = {test::cubePart({-0.4f, 0.0f, 1.2f}, {0.2f, 0.6f, 1.8f})};
    return sc;
}

TraceSettings settings(int w, int h, int threads, int spp = 1) {
    TraceSettings s;
    s.width = w;
    s.height = h;
    s.threads = threads;
    s.spp = spp;
    return s;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Bit-identical floats, coverage, 8-bit pixels and PNG bytes; on failure both images are left behind
// (except for negative controls, which are meant to differ).
::testing::AssertionResult identical(const TraceOutput& a, const TraceOutput& b, const std::string& name,
                                     bool evidence = true) {
    const Image8 a8 = toImage8(a.color, Encoding::Srgb, DisplaySettings{}, nullptr),
                 b8 = toImage8(b.color, Encoding::Srgb, DisplaySettings{}, nullptr);
    const char* what = !sameBits(a.color.rgba, b.color.rgba) ? "float pixels"
                       : a.coverage != b.coverage            ? "coverage"
                       : a8.data != b8.data                  ? "8-bit pixels"
                       : encodePng(a8) != encodePng(b8)      ? "PNG bytes"
                                                             : nullptr;
    if (!what) return ::testing::AssertionSuccess();
    if (evidence) {
        test::writeEvidence(name + "_a", a.color);
        test::writeEvidence(name + "_b", b.color);
    }
    return ::testing::AssertionFailure() << name << ": " << what << " differ";
}

TEST(TraceDeterminism, ThreadCountsAndTilesGiveIdenticalBytes) {
    const TraceScene ts(busyScene());
    for (const int spp : {1, 4}) {
        const TraceOutput one = traceImage(ts, settings(160, 90, 1, spp));
        for (const int threads : {2, 3}) {
            EXPECT_TRUE(identical(one, traceImage(ts, settings(160, 90, threads, spp)),
                                  "spp" + std::to_string(spp) + "_threads" + std::to_string(threads)));
        }
        TraceSettings oddTiles = settings(160, 90, 2, spp);
        oddTiles.tileSize = 7;
        EXPECT_TRUE(identical(one, traceImage(ts, oddTiles), "spp" + std::to_string(spp) + "_tiles7"));
        // The image must show what the scene holds: every object id appears in the coverage buffer.
        for (uint32_t id = 0; id <= 5; ++id)
            EXPECT_NE(std::count(one.coverage.begin(), one.coverage.end(), id), 0) << "coverage id " << id;
    }
    // Negative control: a 1 % change of one light's colour, or one flipped float bit, is noticed.
    Scene dimmer = busyScene();
    dimmer.lights[1].color *= 0.99f;
    const TraceOutput base = traceImage(ts, settings(160, 90, 2));
    EXPECT_FALSE(identical(base, traceImage(dimmer, settings(160, 90, 2)), "control_light", false));
    TraceOutput flipped = base;
    uint32_t bits;
    std::memcpy(&bits, &flipped.color.rgba[4 * 1000], 4);
    bits ^= 1u;
    std::memcpy(&flipped.color.rgba[4 * 1000], &bits, 4);
    EXPECT_FALSE(identical(base, flipped, "control_bit", false));
}

// The 8-bit pixels converted tile by tile as they arrive (TraceEncoding) are toImage8 of the float image, byte
// for byte, with the same count of non-finite pixels, for odd tile sizes, supersampling, both encodings and an
// exposure with the filmic curve. Control: another exposure gives other bytes.
TEST(TraceDeterminism, PixelsEncodedPerTileEqualTheWholeImagesConversion) {
    const TraceScene ts(busyScene());
    DisplaySettings filmic;
    filmic.exposure = 0.7;
    filmic.transform = ViewTransform::Filmic;
    for (const auto& [encoding, display] :
         {std::pair{Encoding::Srgb, DisplaySettings{}}, std::pair{Encoding::Linear, DisplaySettings{}},
          std::pair{Encoding::Srgb, filmic}}) {
        for (const int spp : {1, 4}) {
            TraceSettings s = settings(161, 91, 2, spp);
            s.tileSize = 13;
            uint64_t nonFinite = 0;
            const Image8 whole = toImage8(traceImage(ts, s).color, encoding, display, &nonFinite);
            const TraceEncoding encode{encoding, display};
            const TraceOutput tiled = traceImage(ts, s, {}, &encode);
            EXPECT_TRUE(tiled.color.rgba.empty());
            EXPECT_EQ(tiled.pixels.width, 161);
            EXPECT_EQ(tiled.pixels.channels, 3);
            EXPECT_EQ(tiled.nonFinite, nonFinite);
            EXPECT_EQ(tiled.pixels.data, whole.data) << "encoding " << int(encoding) << ", spp " << spp;
            if (tiled.pixels.data != whole.data) {
                const std::filesystem::path dir(SHADELAB_TEST_OUTPUT_DIR);
                std::filesystem::create_directories(dir);
                writePng((dir / "encoded_per_tile.png").string(), tiled.pixels);
                writePng((dir / "encoded_whole.png").string(), whole);
                std::printf("evidence: %s\n", dir.string().c_str());
            }
        }
    }
    DisplaySettings brighter;
    brighter.exposure = 1.0;
    const TraceEncoding other{Encoding::Srgb, brighter};
    EXPECT_NE(traceImage(ts, settings(161, 91, 2), {}, &other).pixels.data,
              toImage8(traceImage(ts, settings(161, 91, 2)).color, Encoding::Srgb, DisplaySettings{}, nullptr).data);
}

TEST(TraceDeterminism, SupersamplingAveragesTheFixedGrid) {
    // spp = k²: pixel (i, j) is the mean of the k×k samples at (i + (a + 0.5)/k, j + (b + 0.5)/k), which are
    // the pixel centres of a k-times larger image (tile_renderer.h), summed b outer, a inner.
    const Scene sc = busyScene();
    const TraceScene ts(sc);
    const WhittedIntegrator wi(ts, sc.maxDepth);
    const int W = 40, H = 24, k = 2;
    const TraceOutput out = traceImage(ts, settings(W, H, 2, k * k));
    const ViewSetup v = makeViewSetup(sc, k * W, k * H);
    int checked = 0;
    for (int j = 0; j < H; j += 5)
        for (int i = 0; i < W; i += 3, ++checked) {
            glm::vec3 sum(0.0f);
            uint32_t centreId = 0;
            for (int b = 0; b < k; ++b)
                for (int a = 0; a < k; ++a) {
                    const PrimarySample ps =
                        wi.primary(Ray{v.eye, shading::cameraRayDirection(
                                                  v.forward, v.right, v.up, v.tanHalfFovY, float(k * W), float(k * H),
                                                  float(k * i + a) + 0.5f, float(k * j + b) + 0.5f)});
                    sum += ps.color;
                    if (a == k / 2 && b == k / 2) centreId = ps.coverage;
                }
            const glm::vec3 mean = sum / float(k * k);
            const float* p = out.color.pixel(i, j);
            EXPECT_TRUE(p[0] == mean.x && p[1] == mean.y && p[2] == mean.z && p[3] == 1.0f)
                << "pixel " << i << "," << j;
            EXPECT_EQ(out.coverage[size_t(j * W + i)], centreId) << "coverage comes from sample (k/2, k/2)";
        }
    EXPECT_GT(checked, 50);
    // Negative control: the plain pixel centre gives a different image.
    EXPECT_FALSE(sameBits(out.color.rgba, traceImage(ts, settings(W, H, 2, 1)).color.rgba));
}

TEST(TraceDeterminism, OneSampleImagesFromPacketsEqualEachPixelsOwnSample) {
    // At one sample per pixel the camera rays of eight neighbouring pixels find their first hits as one packet
    // (WhittedIntegrator::primary8); every pixel must be what primary() gives its ray alone, bit for bit (a
    // colour of -0 written as +0, as the k×k sum does), with meshes, spheres and a plane in view.
    const Scene sc = busyScene();
    const TraceScene ts(sc);
    const WhittedIntegrator wi(ts, sc.maxDepth);
    const int W = 61, H = 37;  // tiles whose width is not a multiple of eight
    const TraceOutput out = traceImage(ts, settings(W, H, 2));
    const ViewSetup v = makeViewSetup(sc, W, H);
    size_t bad = 0, hitMesh = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const PrimarySample ps = wi.primary(sampleRay(v, 1, i, j, 0, 0));
            const glm::vec3 c = glm::vec3(0.0f) + ps.color;
            const float* p = out.color.pixel(i, j);
            bad += !(std::memcmp(p, &c.x, 4) == 0 && std::memcmp(p + 1, &c.y, 4) == 0 &&
                     std::memcmp(p + 2, &c.z, 4) == 0 && out.coverage[size_t(j * W + i)] == ps.coverage);
            hitMesh += ps.coverage > sc.spheres.size() + sc.planes.size();
        }
    EXPECT_EQ(bad, 0u);
    EXPECT_GT(hitMesh, 50u) << "the meshes must be in view";
    // Negative control: the comparison sees a pixel shifted by one (its neighbour's sample).
    size_t moved = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i + 1 < W; ++i) {
            const glm::vec3 c = wi.primary(sampleRay(v, 1, i + 1, j, 0, 0)).color;
            moved += std::memcmp(out.color.pixel(i, j), &c.x, 4) != 0;
        }
    EXPECT_GT(moved, 100u);
}

// Runs `pt` to completion, checking delivery and progress on the way; returns the assembled image.
TraceOutput collect(ProgressiveTrace& pt, const TraceSettings& s) {
    TraceOutput out;
    out.color = ImageF(s.width, s.height);
    out.coverage.assign(size_t(s.width) * size_t(s.height), 0u);
    const std::vector<Tile> tiles = makeTiles(s.width, s.height, s.tileSize);
    EXPECT_EQ(pt.tileCount(), int(tiles.size()));
    std::vector<int> seen(tiles.size(), 0);
    float last = 0.0f;
    const Clock::time_point deadline = Clock::now() + std::chrono::seconds(60);
    while (!pt.done() && Clock::now() < deadline) {
        std::vector<TileResult> got;
        pt.wait(got, std::chrono::milliseconds(20));
        const float p = pt.progress();
        EXPECT_GE(p, last) << "progress went backwards";
        EXPECT_LE(p, 1.0f);
        last = p;
        for (const TileResult& r : got) {
            if (r.index < 0 || r.index >= int(tiles.size())) {
                ADD_FAILURE() << "tile index " << r.index << " out of range";
                continue;
            }
            ++seen[size_t(r.index)];
            const Tile& t = tiles[size_t(r.index)];
            EXPECT_TRUE(r.tile.x0 == t.x0 && r.tile.y0 == t.y0 && r.tile.width == t.width && r.tile.height == t.height);
            for (int y = 0; y < t.height; ++y)
                for (int x = 0; x < t.width; ++x) {
                    const size_t src = size_t(y) * size_t(t.width) + size_t(x);
                    std::memcpy(out.color.pixel(t.x0 + x, t.y0 + y), &r.rgba[4 * src], 4 * sizeof(float));
                    out.coverage[size_t(t.y0 + y) * size_t(s.width) + size_t(t.x0 + x)] = r.coverage[src];
                }
        }
    }
    EXPECT_TRUE(pt.done()) << "not done after 60 s";
    EXPECT_EQ(pt.progress(), 1.0f);
    for (size_t i = 0; i < seen.size(); ++i)
        EXPECT_EQ(seen[i], 1) << "tile " << i << " delivered " << seen[i] << " times";
    std::vector<TileResult> more;
    EXPECT_EQ(pt.poll(more), 0u) << "tiles delivered after done()";
    return out;
}

TEST(ProgressiveTraceApi, EveryTileOnceAndTheSameImageAsTraceImage) {
    const auto ts = std::make_shared<const TraceScene>(busyScene());
    TraceSettings s = settings(150, 85, 2);
    s.tileSize = 16;  // ragged last row and column
    ProgressiveTrace pt;
    EXPECT_FALSE(pt.done());
    EXPECT_EQ(pt.progress(), 0.0f) << "idle";
    pt.start(ts, s);
    const TraceOutput assembled = collect(pt, s);
    EXPECT_TRUE(identical(assembled, traceImage(*ts, s), "progressive_vs_traceImage"));

    // traceImage's progress callback is monotone and ends at exactly 1.
    std::vector<float> reported;
    traceImage(*ts, s, [&](float f) { reported.push_back(f); });
    ASSERT_FALSE(reported.empty());
    EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
    EXPECT_EQ(reported.back(), 1.0f);
}

TEST(ProgressiveTraceApi, CancelReturnsPromptlyAndRestartWorks) {
    const auto ts = std::make_shared<const TraceScene>(busyScene());
    TraceSettings heavy = settings(640, 360, 2, 16);  // seconds of work: cancel must cut it short
    ProgressiveTrace pt;
    pt.start(ts, heavy);
    std::vector<TileResult> first;
    pt.wait(first, std::chrono::seconds(10));
    EXPECT_FALSE(first.empty()) << "no tile within 10 s";
    EXPECT_LT(pt.progress(), 0.5f) << "the heavy trace should still be running";
    const Clock::time_point t0 = Clock::now();
    pt.cancel();
    const double cancelSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    std::printf("cancel() returned after %.1f ms\n", cancelSeconds * 1e3);
    EXPECT_LT(cancelSeconds, 5.0) << "cancel must stop the workers within about one row of a tile";
    EXPECT_FALSE(pt.done());
    EXPECT_EQ(pt.tileCount(), 0);
    std::vector<TileResult> after;
    EXPECT_EQ(pt.poll(after), 0u) << "tiles delivered after cancel()";
    pt.cancel();  // idle: harmless

    // Restart on the same object, cancel straight after start, start over a running trace, then finish.
    const TraceSettings small = settings(96, 64, 2);
    pt.start(ts, heavy);
    pt.cancel();
    pt.start(ts, heavy);
    pt.start(ts, small);  // replaces the running heavy trace
    EXPECT_TRUE(identical(collect(pt, small), traceImage(*ts, small), "restart"));

    // Destroying a running trace cancels it.
    const Clock::time_point t1 = Clock::now();
    {
        ProgressiveTrace doomed;
        doomed.start(ts, heavy);
    }
    EXPECT_LT(std::chrono::duration<double>(Clock::now() - t1).count(), 5.0);
}

TEST(TraceDeterminism, ReusedMeshBvhGivesTheSameImage) {
    // The viewer's cheap path: only materials and lights change, the mesh BVH is shared (trace_scene.h).
    const Scene sc = busyScene();
    const TraceScene first(sc);
    Scene edited = sc;
    edited.meshes[0].parts[0].material.md = {0.2f, 0.7f, 0.3f};
    edited.lights[0].color = {1.0f, 0.8f, 0.6f};
    const TraceSettings s = settings(64, 36, 2);
    EXPECT_TRUE(
        identical(traceImage(TraceScene(edited, first.meshBvh()), s), traceImage(TraceScene(edited), s), "reuse"));
    EXPECT_FALSE(identical(traceImage(first, s), traceImage(TraceScene(edited), s), "reuse_control", false));
}

// The tracer names the field of a bad value (a SettingError), never a command-line flag: each front end words
// the field its own way (render/render_request.h).
TEST(TraceSettingsValidation, RejectsBadValuesNamingTheField) {
    auto field = [](const TraceSettings& s) -> std::string {
        try {
            validate(s);
        } catch (const SettingError& e) {
            EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
            return e.field();
        }
        return "";
    };
    TraceSettings s;
    for (const int spp : {0, 2, 3, 5, 8, 65, 4096}) {
        s.spp = spp;
        EXPECT_EQ(field(s), "spp") << "spp " << spp;
    }
    s = TraceSettings{};
    s.threads = -1;
    EXPECT_EQ(field(s), "threads");
    s = TraceSettings{};
    for (const int depth : {65, 1000, -2}) {
        s.maxDepth = depth;
        EXPECT_EQ(field(s), "depth") << "depth " << depth;
    }
    s = TraceSettings{};
    s.width = 0;
    EXPECT_EQ(field(s), "size");
    s = TraceSettings{};
    s.tileSize = 0;
    EXPECT_EQ(field(s), "tile_size");

    // Negative controls: the valid neighbours pass.
    for (const int spp : {1, 4, 9, 16, 64}) {
        s = TraceSettings{};
        s.spp = spp;
        EXPECT_EQ(field(s), "") << "spp " << spp;
        EXPECT_EQ(samplesPerAxis(s) * samplesPerAxis(s), spp);
    }
    for (const int depth : {-1, 0, 64}) {
        s = TraceSettings{};
        s.maxDepth = depth;
        EXPECT_EQ(field(s), "") << "depth " << depth;
    }
    s = TraceSettings{};
    s.threads = 0;
    EXPECT_EQ(field(s), "");
    EXPECT_GE(resolveThreads(s), 1);

    // Both entry points refuse before doing any work.
    s = settings(8, 8, 1, 2);
    EXPECT_THROW(traceImage(Scene{}, s), std::invalid_argument);
    ProgressiveTrace pt;
    EXPECT_THROW(pt.start(std::make_shared<const TraceScene>(Scene{}), s), std::invalid_argument);
    EXPECT_EQ(pt.tileCount(), 0);
}

}  // namespace
