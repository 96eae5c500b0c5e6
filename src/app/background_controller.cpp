// BackgroundController: the loop every background renderer's controller thread runs.
#include "app/background_controller.h"

#include "app/idle_priority.h"

#include <exception>
#include <optional>

namespace shadelab::app {

BackgroundController::BackgroundController(BackgroundWork& work)
    : work_(work), threads_(backgroundWorkerCount()), thread_([this] { loop(); }) {}

BackgroundController::~BackgroundController() {
    jobs_.quit();
    cancel_ = true;
    thread_.join();
}

uint64_t BackgroundController::post(const Scene& scene, const render::RenderRequest& request) {
    job_ = nextJob_++;
    posted_ = std::chrono::steady_clock::now();
    cancel_ = true;  // before the job is posted: the controller clears it when it takes the job
    jobs_.post(BackgroundJob{job_, scene, request});
    return job_;
}

void BackgroundController::pause() {
    if (job_ == 0) return;
    job_ = 0;
    cancel_ = true;
    jobs_.pause();
}

double BackgroundController::seconds() const {
    if (job_ == 0) return 0.0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - posted_).count();
}

void BackgroundController::loop() {
    lowerToIdlePriority();  // inherited by the work's threads, started below
    for (;;) {
        std::optional<BackgroundJob> job;
        // Taking a job clears the cancel flag under the hand-off's lock, so a job posted after it cancels again.
        const auto event = jobs_.take(!work_.busy(), job, [&](bool gotJob) {
            if (gotJob) cancel_ = false;
        });
        if (event == JobHandOff<BackgroundJob>::Event::Quit) break;
        if (event == JobHandOff<BackgroundJob>::Event::Pause) {
            work_.stop();
            continue;
        }
        if (job) {
            try {
                work_.start(*job);
            } catch (const std::exception& e) {
                jobs_.fail(e.what());
                work_.stop();
                continue;
            }
        }
        if (work_.busy()) work_.step(cancel_);
    }
    work_.stop();
}

}  // namespace shadelab::app
