// The path render around the integrator: bit-identical images for any thread count, tile size, split into
// passes or share of rows between workers; a cancelled pass keeps whole pixels; settings are refused with the
// field named; a time limit stops at a whole sample count.
#include "trace/path/path_render.h"
#include "trace/path/path_test_util.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <memory>

namespace shadelab::trace {
namespace {

using test::areaLightScene;
using test::pathRun;
using test::sameBytes;
using test::small;

TEST(PathDeterminism, AnyThreadCountTileSizeOrPassSplitGivesTheSameBytes) {
    Scene scene = areaLightScene();
    scene.spheres[0].material.kt = glm::vec3(0.5f);  // glass and roulette paths too
    PathSettings s = small(40, 30, 12, 5);
    s.threads = 1;
    const ImageF one = pathRun(scene, s).render->image();
    for (int threads : {2, 3}) {
        s.threads = threads;
        s.tileSize = threads == 2 ? 16 : 7;
        EXPECT_TRUE(sameBytes(one, pathRun(scene, s).render->image())) << threads << " threads";
    }
    // Progressive: 5 + 7 samples equal 12 at once.
    PathRender progressive(std::make_shared<const TraceScene>(scene), s);
    progressive.addSamples(5);
    progressive.addSamples(7);
    EXPECT_EQ(progressive.samples(), 12);
    EXPECT_TRUE(sameBytes(one, progressive.image()));
    // Negative control: another seed is another image.
    s.seed = 1;
    EXPECT_FALSE(sameBytes(one, pathRun(scene, s).render->image()));
}

// The web page's workers share the rows by turns; put together, their pixels are one render's bytes.
TEST(PathDeterminism, RowSharesPutTogetherGiveTheSameBytes) {
    Scene scene = areaLightScene();
    PathSettings s = small(40, 30, 6, 5);
    s.threads = 1;
    const ImageF one = pathRun(scene, s).render->image();
    const auto traced = std::make_shared<const TraceScene>(scene);
    PathRender a(traced, s), b(traced, s);
    a.addSamplesToRows(2, 0, 2);
    a.addSamplesToRows(4, 0, 2);
    b.addSamplesToRows(6, 1, 2);
    ImageF joined(s.width, s.height);
    for (int y = 0; y < s.height; ++y) {
        const ImageF share = (y % 2 == 0 ? a : b).image();
        std::memcpy(joined.pixel(0, y), share.pixel(0, y), size_t(s.width) * 4 * sizeof(float));
    }
    EXPECT_TRUE(sameBytes(one, joined));
    EXPECT_EQ(b.pixelSamples(3, 1), 6u);
    EXPECT_EQ(b.pixelSamples(3, 0), 0u) << "a row of the other share";
    // Negative control: a share with a sample fewer is not the same image.
    PathRender c(traced, s);
    c.addSamplesToRows(5, 0, 1);
    EXPECT_FALSE(sameBytes(one, c.image()));
}

TEST(PathDeterminism, ACancelledPassKeepsWholePixels) {
    Scene scene = areaLightScene();
    PathSettings s = small(16, 16, 4, 2);
    PathRender render(std::make_shared<const TraceScene>(scene), s);
    std::atomic<bool> cancel{true};
    EXPECT_FALSE(render.addSamples(4, &cancel));
    EXPECT_EQ(render.samples(), 0);
    cancel = false;
    EXPECT_TRUE(render.addSamples(4, &cancel));
    EXPECT_EQ(render.samples(), 4);
}

TEST(PathSettingsValidation, BadValuesAreRefusedWithTheFieldNamed) {
    auto field = [](const PathSettings& s) -> std::string {
        try {
            validate(s);
        } catch (const SettingError& e) {
            return e.field();
        }
        return "";
    };
    PathSettings s;
    s.spp = 0;
    EXPECT_EQ(field(s), "spp");
    s = PathSettings{};
    s.timeLimit = -1.0;
    EXPECT_EQ(field(s), "time_limit");
    s = PathSettings{};
    s.maxDepth = 65;
    EXPECT_EQ(field(s), "depth");
    EXPECT_NO_THROW(validate(PathSettings{}));
}

TEST(PathTimeLimit, StopsAtAWholeSampleCount) {
    Scene scene = areaLightScene();
    PathSettings s = small(64, 48, 100000, 3);
    s.timeLimit = 0.3;
    const PathOutput out = pathTraceImage(std::make_shared<const TraceScene>(scene), s);
    EXPECT_GE(out.spp, 1);
    EXPECT_LT(out.spp, 100000);
    // The standard error needs two samples; a slow (sanitizer, loaded) machine may finish only one in time.
    if (out.spp >= 2) {
        EXPECT_GT(out.meanStandardError8, 0.0);
    }
}

}  // namespace
}  // namespace shadelab::trace
