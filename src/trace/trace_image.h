// traceImage: the one-shot CPU reference render, Scene → linear float image (or 8-bit pixels) + coverage ids, on
// the calling thread and helpers sharing one TraceJob. For the CLI and tests; the viewer drives
// ProgressiveTrace, which hands tiles out as they finish.
#pragma once

#include "image/encode.h"
#include "image/image.h"
#include "scene/scene.h"
#include "trace/trace_scene.h"
#include "trace/trace_settings.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace shadelab::trace {

struct TraceOutput {
    ImageF color;                    // linear RGB, alpha 1, row 0 at the top; empty when encoded (below)
    Image8 pixels;                   // when encoded: toImage8 of that image, RGB
    uint64_t nonFinite = 0;          // when encoded: pixels with no finite value (toImage8)
    std::vector<uint32_t> coverage;  // width × height ids (scene/coverage.h); empty unless settings.coverage
};

// Asks traceImage for 8-bit pixels instead of the float image: each tile is converted as it is finished,
// so no float copy of the whole image is made (at 1920x1080 that copy was 32 MiB of fresh pages, about 60 ms
// of page faults on the development VM). The bytes are toImage8's of the whole image: it converts pixel by pixel.
struct TraceEncoding {
    Encoding encoding = Encoding::Srgb;
    DisplaySettings display;
};

// Renders with resolveThreads(settings) workers, the calling thread one of them. `progress`, when set, is called
// on the calling thread with the finished fraction in [0, 1] after one of its tiles when 50 ms have passed since
// the last call, and once with 1 at the end. Throws std::invalid_argument for bad settings, before any work.
// With `encode`, fills pixels and nonFinite instead of color.
TraceOutput traceImage(const TraceScene& scene, const TraceSettings& settings,
                       const std::function<void(float)>& progress = {}, const TraceEncoding* encode = nullptr);
// Builds the TraceScene (mesh BVH included) and renders it.
TraceOutput traceImage(const Scene& scene, const TraceSettings& settings,
                       const std::function<void(float)>& progress = {}, const TraceEncoding* encode = nullptr);

}  // namespace shadelab::trace
