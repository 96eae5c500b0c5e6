// JobHandOff: how the viewer's UI thread hands work to a background renderer's controller thread (the Whitted
// reference, the path tracer of the Global modes). The UI posts the newest job (an older one not yet taken is
// dropped unseen), asks for a pause or for quit; the controller takes what is there, waiting for it when it has
// nothing to do, and reports a failure for the UI to show. One mutex guards exactly this; what the controller
// hands back (tiles, passes) each renderer guards itself. GL-free and header-only.
#pragma once

#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

namespace shadelab::app {

template <typename JobT>
class JobHandOff {
public:
    enum class Event { None, Job, Pause, Quit };

    // UI thread: replaces any job not yet taken, and clears the last failure.
    void post(JobT job) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            pending_ = std::move(job);
            error_.clear();
        }
        wake_.notify_all();
    }
    // UI thread: drops any job not yet taken; the controller stops what it runs.
    void pause() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            pending_.reset();
            pause_ = true;
        }
        wake_.notify_all();
    }
    // Any thread: the controller leaves its loop at its next take().
    void quit() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            quit_ = true;
        }
        wake_.notify_all();
    }
    std::string error() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return error_;
    }

    // Controller thread: a quit, else a pause, else the newest job (moved into `job`: Event::Job), else None.
    // With `wait`, blocks until one of the three arrives. `onTake(bool gotJob)`, when given, runs under the lock
    // when the result is Job or None, so that what it sets is ordered with post().
    template <typename OnTake>
    Event take(bool wait, std::optional<JobT>& job, OnTake&& onTake) {
        std::unique_lock<std::mutex> lock(mutex_);
        if (wait) wake_.wait(lock, [&] { return quit_ || pending_ || pause_; });
        if (quit_) return Event::Quit;
        if (pause_) {
            pause_ = false;
            return Event::Pause;
        }
        job = std::move(pending_);
        pending_.reset();
        onTake(job.has_value());
        return job ? Event::Job : Event::None;
    }
    Event take(bool wait, std::optional<JobT>& job) {
        return take(wait, job, [](bool) {});
    }
    // Controller thread: a job could not start; error() says why until the next post().
    void fail(std::string message) {
        std::lock_guard<std::mutex> lock(mutex_);
        error_ = std::move(message);
    }

private:
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<JobT> pending_;
    bool pause_ = false, quit_ = false;
    std::string error_;
};

}  // namespace shadelab::app
