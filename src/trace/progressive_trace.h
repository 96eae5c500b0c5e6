// ProgressiveTrace: renders a TraceScene on worker threads and hands finished tiles out as they come,
// for the viewer (show the reference while it renders; cancel and restart when a slider moves) and for
// traceImage(). Threads pull tiles from an atomic counter; delivery is a mutex-guarded queue.
#pragma once

#include "trace/tile_renderer.h"
#include "trace/trace_scene.h"
#include "trace/trace_settings.h"

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

namespace shadelab::trace {

class ProgressiveTrace {
public:
    ProgressiveTrace() = default;
    ~ProgressiveTrace() { cancel(); }
    ProgressiveTrace(const ProgressiveTrace&) = delete;
    ProgressiveTrace& operator=(const ProgressiveTrace&) = delete;

    // Cancels any trace in progress, then starts tracing `scene` with resolveThreads(settings) workers.
    // Throws std::invalid_argument (validate()) before any work when the settings are bad. The scene is
    // shared with the workers, so the caller may drop its pointer or build the next one meanwhile.
    void start(std::shared_ptr<const TraceScene> scene, const TraceSettings& settings);

    // Moves the tiles finished since the last call to the end of `out` and returns how many. Never blocks.
    // Every tile is delivered exactly once.
    size_t poll(std::vector<TileResult>& out);
    // As poll(), but first waits up to `timeout` for a tile to finish (returns early when all are done).
    size_t wait(std::vector<TileResult>& out, std::chrono::milliseconds timeout);

    // Stops the workers and joins them. Each checks before every sample and before every secondary ray, so
    // this takes about one shade() of the slowest worker (well under 100 ms on any scene the limits admit;
    // trace_test's cancel test prints the figure). Tiles not yet delivered are dropped. Safe to call when idle.
    void cancel();

    // True once every tile has been rendered and delivered by poll() or wait(). False while idle.
    bool done() const;
    // Rendered tiles / all tiles, in [0, 1]; cheap (two atomic loads).
    float progress() const;
    int tileCount() const;

private:
    struct Job;
    static void work(const std::shared_ptr<Job>& job);

    std::shared_ptr<Job> job_;
    std::vector<std::thread> workers_;
};

}  // namespace shadelab::trace
