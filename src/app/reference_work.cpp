// ReferenceWork: the reference's trace on the controller thread.
#include "app/reference_work.h"

#include "trace/trace_scene.h"

#include <chrono>
#include <memory>

namespace shadelab::app {

void ReferenceWork::start(const BackgroundJob& job) {
    stop();
    auto scene = std::make_shared<trace::TraceScene>(job.scene, meshes_.get(job.scene));
    trace::TraceSettings settings = render::toTrace(job.request, job.scene);
    settings.tileSize = tileSize_;
    trace_.start(scene, settings);
    running_ = job.id;
}

void ReferenceWork::step(const std::atomic<bool>&) {
    // ProgressiveTrace cancels itself when the next job starts; a step is at most 30 ms anyway.
    std::vector<trace::TileResult> tiles;
    trace_.wait(tiles, std::chrono::milliseconds(30));
    if (tiles.empty()) return;
    std::lock_guard<std::mutex> lock(arrivedMutex_);
    for (trace::TileResult& t : tiles) arrived_.emplace_back(running_, std::move(t));
}

void ReferenceWork::stop() {
    trace_.cancel();
    running_ = 0;
}

std::vector<ReferenceWork::Arrival> ReferenceWork::takeArrived() {
    std::vector<Arrival> tiles;
    std::lock_guard<std::mutex> lock(arrivedMutex_);
    tiles.swap(arrived_);
    return tiles;
}

}  // namespace shadelab::app
