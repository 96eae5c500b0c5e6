// JobHandOff (app/job_hand_off.h): what the viewer's background renderers' controllers take from the UI thread.
#include "app/job_hand_off.h"

#include <gtest/gtest.h>

#include <thread>

using shadelab::app::JobHandOff;
using Event = JobHandOff<int>::Event;

TEST(JobHandOff, TheNewestJobIsTakenAndOlderOnesAreDropped) {
    JobHandOff<int> h;
    std::optional<int> job;
    EXPECT_EQ(h.take(false, job), Event::None);  // control: nothing posted
    h.post(1);
    h.post(2);
    EXPECT_EQ(h.take(false, job), Event::Job);
    EXPECT_EQ(job, 2);
    EXPECT_EQ(h.take(false, job), Event::None);
    EXPECT_FALSE(job);
}

TEST(JobHandOff, QuitComesBeforePauseAndPauseBeforeAJob) {
    JobHandOff<int> h;
    std::optional<int> job;
    h.post(1);
    h.pause();  // drops the job
    EXPECT_EQ(h.take(false, job), Event::Pause);
    EXPECT_EQ(h.take(false, job), Event::None);
    h.post(3);
    h.quit();
    EXPECT_EQ(h.take(false, job), Event::Quit);
}

TEST(JobHandOff, AFailureShowsUntilTheNextPost) {
    JobHandOff<int> h;
    h.fail("no memory");
    EXPECT_EQ(h.error(), "no memory");
    h.post(1);
    EXPECT_EQ(h.error(), "");
}

TEST(JobHandOff, AWaitingControllerWakesForAPostAndRunsItsCallbackUnderTheLock) {
    JobHandOff<int> h;
    bool took = false;
    std::optional<int> job;
    std::thread controller([&] { EXPECT_EQ(h.take(true, job, [&](bool got) { took = got; }), Event::Job); });
    h.post(7);
    controller.join();
    EXPECT_EQ(job, 7);
    EXPECT_TRUE(took);
}
