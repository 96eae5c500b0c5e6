// BackgroundController (app/background_controller.h): the one controller thread the viewer's reference and path
// tracer share, driven here by a work that counts what it is asked to do.
#include "app/background_controller.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

using shadelab::Scene;
using shadelab::app::BackgroundController;
using shadelab::app::BackgroundJob;
using shadelab::app::BackgroundWork;
using shadelab::render::RenderRequest;

namespace {

// Steps each job `steps` times; a request of width 13 fails to start.
class CountingWork : public BackgroundWork {
public:
    explicit CountingWork(int steps) : steps_(steps) {}
    void start(const BackgroundJob& job) override {
        if (job.request.width == 13) throw std::runtime_error("width 13 is unlucky");
        std::lock_guard<std::mutex> lock(mutex_);
        started.push_back(job.id);
        left_ = steps_;
        changed_.notify_all();
    }
    bool busy() const override {
        std::lock_guard<std::mutex> lock(mutex_);
        return left_ > 0;
    }
    void step(const std::atomic<bool>&) override {
        std::lock_guard<std::mutex> lock(mutex_);
        --left_;
        ++steps;
        changed_.notify_all();
    }
    void stop() override {
        std::lock_guard<std::mutex> lock(mutex_);
        left_ = 0;
        ++stops;
        changed_.notify_all();
    }
    // Waits up to 5 s for `done` to hold (under the lock).
    template <typename F>
    bool waitFor(F done) {
        std::unique_lock<std::mutex> lock(mutex_);
        return changed_.wait_for(lock, std::chrono::seconds(5), done);
    }

    std::vector<uint64_t> started;
    int steps = 0, stops = 0;

private:
    const int steps_;
    int left_ = 0;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
};

RenderRequest requestOfWidth(int width) {
    RenderRequest r;
    r.width = width;
    r.height = 8;
    return r;
}

}  // namespace

TEST(BackgroundController, AJobIsStartedAndSteppedUntilItHasNothingMoreToDo) {
    CountingWork work(3);
    {
        BackgroundController controller(work);
        EXPECT_FALSE(controller.active());
        EXPECT_GE(controller.threads(), 1);
        const uint64_t id = controller.post(Scene(), requestOfWidth(8));
        EXPECT_TRUE(controller.active());
        EXPECT_EQ(controller.job(), id);
        ASSERT_TRUE(work.waitFor([&] { return work.steps == 3; }));
        // Nothing more to do: the controller waits instead of stepping on (control: a fourth step would show).
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        EXPECT_TRUE(work.waitFor([&] { return work.steps == 3; }));
        EXPECT_EQ(work.started, std::vector<uint64_t>{id});
        EXPECT_EQ(controller.error(), "");
    }
    EXPECT_GE(work.stops, 1);  // the end stops the work
}

TEST(BackgroundController, APauseStopsTheWorkAndTheNextPostStartsAfresh) {
    CountingWork work(1000000);
    BackgroundController controller(work);
    const uint64_t first = controller.post(Scene(), requestOfWidth(8));
    ASSERT_TRUE(work.waitFor([&] { return work.steps > 0; }));
    controller.pause();
    EXPECT_FALSE(controller.active());
    EXPECT_EQ(controller.job(), 0u);
    EXPECT_EQ(controller.seconds(), 0.0);
    ASSERT_TRUE(work.waitFor([&] { return work.stops >= 1; }));
    const uint64_t second = controller.post(Scene(), requestOfWidth(8));
    EXPECT_NE(second, first);
    ASSERT_TRUE(work.waitFor([&] { return work.started.size() == 2; }));
    EXPECT_EQ(work.started.back(), second);
}

TEST(BackgroundController, AJobThatCannotStartSaysWhyUntilTheNextPost) {
    CountingWork work(1);
    BackgroundController controller(work);
    controller.post(Scene(), requestOfWidth(13));
    for (int i = 0; i < 500 && controller.error().empty(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(controller.error(), "width 13 is unlucky");
    EXPECT_TRUE(work.started.empty());
    controller.post(Scene(), requestOfWidth(8));
    EXPECT_EQ(controller.error(), "");  // control: a good job clears it
    ASSERT_TRUE(work.waitFor([&] { return work.started.size() == 1; }));
}
