// BackgroundController: the one controller thread behind each of the viewer's background renderers (the Whitted
// reference, the path tracer of the Global modes). The UI thread posts a job (the scene and the render request)
// or asks for a pause; the controller, at idle priority, hands it to its BackgroundWork and then steps that work
// until it has nothing more to do, waiting for the next job without spinning. What the work hands back (tiles,
// passes) it guards itself. GL-free: the renderers put textures on top (reference_renderer.h, global_renderer.h).
#pragma once

#include "app/job_hand_off.h"
#include "render/render_request.h"
#include "scene/scene.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>

namespace shadelab::app {

// One request for a background renderer: `id` tells its results from those of older, cancelled jobs.
struct BackgroundJob {
    uint64_t id = 0;
    Scene scene;
    render::RenderRequest request;
};

// What a controller runs, called on its thread only.
class BackgroundWork {
public:
    virtual ~BackgroundWork() = default;
    // Starts `job`, dropping whatever ran before. Throws (std::exception) when it cannot start: the message is
    // what BackgroundController::error() then says.
    virtual void start(const BackgroundJob& job) = 0;
    // Whether the job started last has more to do.
    virtual bool busy() const = 0;
    // One step of it (a batch of tiles, one pass), returning early once `cancel` is true.
    virtual void step(const std::atomic<bool>& cancel) = 0;
    // Drops the job (a pause, a failed start, the end).
    virtual void stop() = 0;
};

class BackgroundController {
public:
    // Starts the thread, which drops to idle priority (idle_priority.h) before the work starts any worker
    // threads, so they inherit it. `work` outlives the controller.
    explicit BackgroundController(BackgroundWork& work);
    ~BackgroundController();  // cancels the step under way and joins the thread
    BackgroundController(const BackgroundController&) = delete;
    BackgroundController& operator=(const BackgroundController&) = delete;

    // UI thread: replaces the job (one not yet taken is dropped unseen) and cancels the step under way. Returns
    // the new job's id, which is what job() says from now on.
    uint64_t post(const Scene& scene, const render::RenderRequest& request);
    // UI thread: stops the work; job() is 0 until the next post.
    void pause();

    uint64_t job() const { return job_; }  // the job posted last, 0 when paused
    bool active() const { return job_ != 0; }
    double seconds() const;  // since the job was posted (0 when paused)
    // Why the job posted last could not start (empty when it did).
    std::string error() const { return jobs_.error(); }
    // The worker threads a job should use: every core but one, at least one.
    int threads() const { return threads_; }

private:
    void loop();

    BackgroundWork& work_;
    JobHandOff<BackgroundJob> jobs_;
    std::atomic<bool> cancel_{false};  // set by post, pause and quit; cleared when the controller takes a job
    const int threads_;
    uint64_t nextJob_ = 1, job_ = 0;  // UI thread only
    std::chrono::steady_clock::time_point posted_;
    std::thread thread_;  // last: it starts once every member exists
};

}  // namespace shadelab::app
