// ProgressiveTrace: the job shared by the workers, the worker loop, and tile delivery.
#include "trace/progressive_trace.h"

#include "trace/trace_job.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>

namespace shadelab::trace {
struct ProgressiveTrace::Job {
    Job(std::shared_ptr<const TraceScene> s, const TraceSettings& st) : scene(std::move(s)), trace(*scene, st) {}

    std::shared_ptr<const TraceScene> scene;
    TraceJob trace;

    std::atomic<int> next{0};       // next tile to hand to a worker
    std::atomic<int> rendered{0};   // tiles finished
    std::atomic<int> delivered{0};  // tiles handed out by poll/wait
    std::atomic<bool> cancelled{false};
    std::mutex mutex;
    std::condition_variable ready;
    std::deque<TileResult> queue;  // finished, not yet delivered
};

void ProgressiveTrace::start(std::shared_ptr<const TraceScene> scene, const TraceSettings& settings) {
    validate(settings);
    cancel();
    job_ = std::make_shared<Job>(std::move(scene), settings);
    const int n = std::min(resolveThreads(settings), int(job_->trace.tiles.size()));
    for (int t = 0; t < n; ++t) workers_.emplace_back([job = job_] { work(job); });
}

void ProgressiveTrace::work(const std::shared_ptr<Job>& job) {
    for (;;) {
        if (job->cancelled.load(std::memory_order_relaxed)) return;
        const int index = job->next.fetch_add(1, std::memory_order_relaxed);
        if (index >= int(job->trace.tiles.size())) return;
        TileResult result;
        if (!job->trace.render(index, result, &job->cancelled)) return;
        {
            std::lock_guard<std::mutex> lock(job->mutex);
            job->queue.push_back(std::move(result));
            job->rendered.fetch_add(1, std::memory_order_release);
        }
        job->ready.notify_all();
    }
}

size_t ProgressiveTrace::poll(std::vector<TileResult>& out) {
    if (!job_) return 0;
    std::lock_guard<std::mutex> lock(job_->mutex);
    const size_t n = job_->queue.size();
    for (TileResult& r : job_->queue) out.push_back(std::move(r));
    job_->queue.clear();
    job_->delivered.fetch_add(int(n), std::memory_order_relaxed);
    return n;
}

size_t ProgressiveTrace::wait(std::vector<TileResult>& out, std::chrono::milliseconds timeout) {
    if (!job_) return 0;
    {
        std::unique_lock<std::mutex> lock(job_->mutex);
        const int total = int(job_->trace.tiles.size());
        job_->ready.wait_for(lock, timeout, [&] {
            return !job_->queue.empty() || job_->cancelled.load() ||
                   job_->delivered.load(std::memory_order_relaxed) >= total;
        });
    }
    return poll(out);
}

void ProgressiveTrace::cancel() {
    if (job_) job_->cancelled.store(true);
    for (std::thread& t : workers_) t.join();
    workers_.clear();
    job_.reset();
}

bool ProgressiveTrace::done() const {
    return job_ && job_->delivered.load(std::memory_order_relaxed) == int(job_->trace.tiles.size());
}

float ProgressiveTrace::progress() const {
    if (!job_ || job_->trace.tiles.empty()) return job_ ? 1.0f : 0.0f;
    return float(job_->rendered.load(std::memory_order_acquire)) / float(job_->trace.tiles.size());
}

int ProgressiveTrace::tileCount() const { return job_ ? int(job_->trace.tiles.size()) : 0; }

}  // namespace shadelab::trace
