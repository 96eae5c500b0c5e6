// TraceJob: the fixed part of one Whitted render, what every worker reads and none writes: the settings, the
// k×k grid's sample view, the integrator and the list of tiles. ProgressiveTrace's threads share one; the web
// page's Web Workers each build their own from the same scene and settings, so any worker renders any tile
// to the same bits.
#pragma once

#include "scene/view.h"
#include "trace/integrator.h"
#include "trace/tile_renderer.h"
#include "trace/trace_scene.h"
#include "trace/trace_settings.h"

#include <atomic>
#include <vector>

namespace shadelab::trace {

struct TraceJob {
    // `scene` must outlive the job (the integrator refers to it). The settings are validate()d by the caller.
    TraceJob(const TraceScene& scene, const TraceSettings& settings);

    // Renders tile `index` (0 .. tiles.size()-1) into `out`; false when `cancel` became true (renderTile).
    bool render(int index, TileResult& out, const std::atomic<bool>* cancel = nullptr) const;

    TraceSettings settings;
    int k;  // samples per axis of the pixel grid
    ViewSetup sampleView;
    WhittedIntegrator integrator;
    std::vector<Tile> tiles;
};

}  // namespace shadelab::trace
