// The render request: its limits by field (every front end's table-driven test builds on these), the sample
// grid's rule, and the conversions to each renderer's settings.
#include "render/render_request.h"

#include "compare/comparison.h"
#include "image/image.h"
#include "scene/sample_grid.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

using namespace shadelab;
using render::Engine;
using render::RenderRequest;

namespace {

std::string fieldOf(const RenderRequest& r) {
    const std::optional<render::RequestProblem> p = render::check(r);
    return p ? p->field : "";
}

}  // namespace

TEST(RenderRequest, DefaultsAreValid) {
    for (Engine e : {Engine::Raster, Engine::Trace, Engine::Both, Engine::Path}) {
        RenderRequest r;
        r.engine = e;
        EXPECT_FALSE(render::check(r)) << toString(e);
    }
    RenderRequest r;
    EXPECT_EQ(r.samples(), 1);
    r.engine = Engine::Path;
    EXPECT_EQ(r.samples(), 16);
}

TEST(RenderRequest, EachLimitIsNamedByItsField) {
    struct Case {
        const char* what;
        void (*edit)(RenderRequest&);
        const char* field;  // "" = valid
    };
    const Case cases[] = {
        {"zero width", [](RenderRequest& r) { r.width = 0; }, "size"},
        {"side over the limit", [](RenderRequest& r) { r.height = kMaxImageSide + 1; }, "size"},
        {"side at the limit", [](RenderRequest& r) { r.width = kMaxImageSide; }, ""},
        {"spp off the grid", [](RenderRequest& r) { r.spp = 2; }, "spp"},
        {"spp 0", [](RenderRequest& r) { r.spp = 0; }, "spp"},
        {"spp over the grid", [](RenderRequest& r) { r.spp = 81; }, "spp"},
        {"spp 64 on the grid", [](RenderRequest& r) { r.spp = 64; }, ""},
        {"path spp 3", [](RenderRequest& r) { r.engine = Engine::Path, r.spp = 3; }, ""},
        {"path spp 0", [](RenderRequest& r) { r.engine = Engine::Path, r.spp = 0; }, "spp"},
        {"path spp over", [](RenderRequest& r) { r.engine = Engine::Path, r.spp = trace::kMaxPathSamples + 1; }, "spp"},
        {"depth -1", [](RenderRequest& r) { r.depth = -1; }, "depth"},
        {"depth 65", [](RenderRequest& r) { r.depth = 65; }, "depth"},
        {"depth 0", [](RenderRequest& r) { r.depth = 0; }, ""},
        {"threads -1", [](RenderRequest& r) { r.threads = -1; }, "threads"},
        {"threads over", [](RenderRequest& r) { r.threads = render::kMaxThreads + 1; }, "threads"},
        {"time limit off path", [](RenderRequest& r) { r.path.timeLimit = 1.0; }, "time_limit"},
        {"estimator off path", [](RenderRequest& r) { r.path.estimator = trace::PathEstimator::Bsdf; }, "estimator"},
        {"light paths off path", [](RenderRequest& r) { r.path.part = trace::PathPart::Direct; }, "light_paths"},
        {"sampler off path", [](RenderRequest& r) { r.path.sampler = trace::PathSampler::Independent; }, "sampler"},
        {"denoise off path", [](RenderRequest& r) { r.path.denoise = true; }, "denoise"},
        {"seed off path", [](RenderRequest& r) { r.path.seed = 7; }, "seed"},
        {"seed -1", [](RenderRequest& r) { r.engine = Engine::Path, r.path.seed = -1; }, "seed"},
        {"seed over", [](RenderRequest& r) { r.engine = Engine::Path, r.path.seed = render::kMaxSeed + 1; }, "seed"},
        {"seed 0 and the largest", [](RenderRequest& r) { r.engine = Engine::Path, r.path.seed = render::kMaxSeed; },
         ""},
        {"negative time limit", [](RenderRequest& r) { r.engine = Engine::Path, r.path.timeLimit = -1.0; },
         "time_limit"},
        {"NaN time limit", [](RenderRequest& r) { r.engine = Engine::Path, r.path.timeLimit = 0.0 / 0.0; },
         "time_limit"},
        {"path options on path",
         [](RenderRequest& r) {
             r.engine = Engine::Path, r.path.timeLimit = 2.0, r.path.part = trace::PathPart::Indirect,
             r.path.sampler = trace::PathSampler::Independent;
         },
         ""},
    };
    for (const Case& c : cases) {
        RenderRequest r;
        c.edit(r);
        EXPECT_EQ(fieldOf(r), c.field) << c.what;
        if (*c.field) {
            try {
                render::require(r);
                ADD_FAILURE() << c.what << ": require() accepted it";
            } catch (const SettingError& e) {
                EXPECT_EQ(e.field(), c.field) << c.what;
                EXPECT_EQ(std::string(e.what()), std::string(c.field) + ": " + e.reason()) << c.what;
            }
        } else {
            EXPECT_NO_THROW(render::require(r)) << c.what;
        }
    }
}

TEST(SampleGrid, PerfectSquaresUpTo64) {
    EXPECT_EQ(gridSamplesPerSide(1), 1);
    EXPECT_EQ(gridSamplesPerSide(16), 4);
    EXPECT_EQ(gridSamplesPerSide(64), 8);
    for (int spp : {-4, 0, 2, 3, 15, 65, 81, 4096}) EXPECT_THROW(gridSamplesPerSide(spp), SettingError) << spp;
    try {
        gridSamplesPerSide(10);
    } catch (const SettingError& e) {
        EXPECT_NE(e.reason().find("nearest: 9 or 16"), std::string::npos) << e.what();
    }
}

TEST(RenderRequest, ConversionsCarryEveryField) {
    Scene scene;
    scene.maxDepth = 5;
    RenderRequest r;
    r.width = 320;
    r.height = 200;
    r.spp = 9;
    r.threads = 3;
    r.encoding = Encoding::Linear;
    const raster::OffscreenOptions o = render::toOffscreen(r, Scene{});
    EXPECT_EQ(o.width, 320);
    EXPECT_EQ(o.height, 200);
    EXPECT_EQ(o.spp, 9);
    EXPECT_EQ(o.encoding, Encoding::Linear);
    EXPECT_FALSE(o.coverage);
    const trace::TraceSettings t = render::toTrace(r, scene);
    EXPECT_EQ(t.width, 320);
    EXPECT_EQ(t.spp, 9);
    EXPECT_EQ(t.threads, 3);
    EXPECT_EQ(t.maxDepth, 5);  // the scene's
    EXPECT_FALSE(t.coverage);
    r.depth = 2;
    EXPECT_EQ(render::toTrace(r, scene).maxDepth, 2);

    r.engine = Engine::Path;
    r.spp.reset();
    r.path.timeLimit = 4.0;
    r.path.estimator = trace::PathEstimator::Light;
    r.path.part = trace::PathPart::Indirect;
    r.path.sampler = trace::PathSampler::Independent;
    r.path.denoise = true;
    r.path.seed = render::kMaxSeed;
    const trace::PathSettings p = render::toPath(r, scene);
    EXPECT_EQ(p.spp, 16);
    EXPECT_EQ(p.maxDepth, 2);
    EXPECT_EQ(p.timeLimit, 4.0);
    EXPECT_EQ(p.estimator, trace::PathEstimator::Light);
    EXPECT_EQ(p.part, trace::PathPart::Indirect);
    EXPECT_EQ(p.sampler, trace::PathSampler::Independent);
    EXPECT_TRUE(p.denoise);
    EXPECT_EQ(p.seed, 4294967295u);
    EXPECT_EQ(render::toPath(RenderRequest{}, scene).seed, 0u);  // unset: today's image
    EXPECT_FALSE(render::toPath(RenderRequest{}, scene).denoise);
    EXPECT_EQ(render::toPath(RenderRequest{}, scene).estimator, trace::PathEstimator::Mis);
    EXPECT_EQ(render::toPath(RenderRequest{}, scene).sampler, trace::PathSampler::Sobol);
}

// Compared with the rasterizer, the reference is traced at the comparison's depth and both keep coverage.
TEST(RenderRequest, BothTracesAtTheComparisonsDepth) {
    Scene scene;
    scene.maxDepth = 5;
    RenderRequest r;
    r.engine = Engine::Both;
    EXPECT_EQ(render::traceDepth(r, scene), comparisonDepth(scene));
    EXPECT_EQ(render::toTrace(r, scene).maxDepth, 1);
    EXPECT_TRUE(render::toTrace(r, scene).coverage);
    EXPECT_TRUE(render::toOffscreen(r, Scene{}).coverage);
    r.depth = 3;  // asked for: as asked
    EXPECT_EQ(render::toTrace(r, scene).maxDepth, 3);
    r.engine = Engine::Trace;  // control: alone, the scene's depth
    r.depth.reset();
    EXPECT_EQ(render::toTrace(r, scene).maxDepth, 5);
}

// The display: an exposure outside [-16, 16] (or NaN) is refused by its field; each unset field is the scene's,
// and a set one overrides it; the raster conversion carries the result.
TEST(RenderRequest, DisplayFieldsOverrideTheScenesAndExposureIsBounded) {
    render::RenderRequest r;
    for (double bad : {40.0, -16.01, std::nan("")}) {
        r.exposure = bad;
        const std::optional<render::RequestProblem> p = render::check(r);
        ASSERT_TRUE(p) << bad;
        EXPECT_EQ(p->field, "exposure");
        EXPECT_EQ(p->reason.rfind("must be in [-16, 16] stops, got ", 0), 0u) << p->reason;
    }
    r.exposure = 16.0;
    EXPECT_FALSE(render::check(r));
    Scene scene;
    scene.display = {-2.0, ViewTransform::Filmic};
    r.exposure.reset();
    EXPECT_EQ(render::displayOf(r, scene), scene.display);
    r.exposure = 1.0;
    EXPECT_EQ(render::displayOf(r, scene), (DisplaySettings{1.0, ViewTransform::Filmic}));
    r.viewTransform = ViewTransform::Standard;
    EXPECT_EQ(render::displayOf(r, scene), (DisplaySettings{1.0, ViewTransform::Standard}));
    EXPECT_EQ(render::toOffscreen(r, scene).display, (DisplaySettings{1.0, ViewTransform::Standard}));
    EXPECT_EQ(render::displayOf(render::RenderRequest{}, Scene{}), DisplaySettings{});
}
