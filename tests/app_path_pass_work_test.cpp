// PathPassWork (app/path_pass_work.h), without a window: a pass the window has not taken yet is replaced by the
// newer one, but the newest denoised preview is not lost with it.
#include "app/path_pass_work.h"
#include "render/render_request.h"
#include "scene/scene_load.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <atomic>

using namespace shadelab;

namespace {

app::BackgroundJob smallJob(uint64_t id) {
    app::BackgroundJob job;
    job.id = id;
    job.scene = loadScene(test::sourcePath("assets/scenes/default.json"));
    job.request.engine = render::Engine::Path;
    job.request.width = 48;
    job.request.height = 27;
    job.request.threads = 1;
    return job;
}

}  // namespace

// The first pass always carries the denoised preview; the passes after it carry one only now and then. On a busy
// machine the window may take the passes late: whichever pass it takes must bring the newest preview, with the
// sample count it was made from.
TEST(PathPassWork, APassNotYetTakenHandsItsDenoisedPreviewToTheNextOne) {
    trace::MeshBvhCache meshes;
    app::PathPassWork work(meshes);
    work.start(smallJob(1));
    const std::atomic<bool> cancel{false};
    work.step(cancel);  // the first pass: denoised
    for (int pass = 2; pass <= 4; ++pass) work.step(cancel);
    std::optional<app::PathPassWork::Pass> taken = work.takeArrived();
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->samples, 4);
    EXPECT_EQ(taken->denoised.width, 48);
    EXPECT_EQ(taken->denoised.height, 27);
    EXPECT_GE(taken->denoisedSamples, 1);
    EXPECT_LE(taken->denoisedSamples, 4);
    // Taken, it is gone; the next pass brings only what it has.
    EXPECT_FALSE(work.takeArrived().has_value());
    // A new job starts afresh: nothing of the old job's preview is handed to its passes.
    work.start(smallJob(2));
    work.step(cancel);
    taken = work.takeArrived();
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->job, 2u);
    EXPECT_EQ(taken->samples, 1);
    EXPECT_EQ(taken->denoisedSamples, 1);  // its own first pass's
}
