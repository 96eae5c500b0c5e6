// traceImage: the one-shot CPU reference render, Scene → linear float image + coverage ids, built on
// ProgressiveTrace. For the CLI and tests; the viewer drives ProgressiveTrace itself.
#pragma once

#include "image/image.h"
#include "scene/scene.h"
#include "trace/trace_scene.h"
#include "trace/trace_settings.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace shadelab::trace {

struct TraceOutput {
    ImageF color;                    // linear RGB, alpha 1, row 0 at the top
    std::vector<uint32_t> coverage;  // width × height ids (scene/coverage.h); empty unless settings.coverage
};

// Renders with resolveThreads(settings) workers. `progress`, when set, is called on the calling thread
// with the finished fraction in [0, 1] each time tiles arrive (at most every ~50 ms while waiting), and
// once with 1 at the end. Throws std::invalid_argument for bad settings, before any work.
TraceOutput traceImage(const TraceScene& scene, const TraceSettings& settings,
                       const std::function<void(float)>& progress = {});
// Builds the TraceScene (mesh BVH included) and renders it.
TraceOutput traceImage(const Scene& scene, const TraceSettings& settings,
                       const std::function<void(float)>& progress = {});

}  // namespace shadelab::trace
