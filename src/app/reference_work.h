// ReferenceWork: what the reference's controller thread runs (background_controller.h): the Whitted tracer's
// ProgressiveTrace over the job's scene, whose finished tiles it keeps, tagged with their job, until the UI
// thread takes them. The mesh BVHs come from a cache shared with the UI thread's probe.
#pragma once

#include "app/background_controller.h"
#include "trace/accel/mesh_bvh_cache.h"
#include "trace/progressive_trace.h"
#include "trace/tile_renderer.h"

#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace shadelab::app {

class ReferenceWork : public BackgroundWork {
public:
    using Arrival = std::pair<uint64_t, trace::TileResult>;  // (job id, tile)

    ReferenceWork(trace::MeshBvhCache& meshes, int tileSize) : meshes_(meshes), tileSize_(tileSize) {}

    void start(const BackgroundJob& job) override;
    bool busy() const override { return running_ != 0 && !trace_.done(); }
    void step(const std::atomic<bool>& cancel) override;  // waits up to 30 ms for tiles
    void stop() override;

    // Any thread: the tiles finished since the last call, oldest first.
    std::vector<Arrival> takeArrived();

private:
    trace::MeshBvhCache& meshes_;
    const int tileSize_;
    trace::ProgressiveTrace trace_;
    uint64_t running_ = 0;  // the job traced, 0 for none
    std::mutex arrivedMutex_;
    std::vector<Arrival> arrived_;  // under arrivedMutex_
};

}  // namespace shadelab::app
