// The memory budget of one render: an estimate of what `shadelab render` will allocate, checked
// against --max-memory before any pixel is drawn, so a 16384² trace under a 2 GB limit is one clear line
// instead of std::bad_alloc. An estimate for refusing, not an allocator: it errs on the generous side.
#pragma once

#include "cli/render_options.h"
#include "scene/scene.h"

#include <cstdint>
#include <string>

namespace shadelab::cli {

// Half of physical memory, and at most three quarters of the address-space limit (ulimit -v) if one is set.
uint64_t defaultMaxMemory();

// Bytes the render will allocate beyond the loaded scene: images (float, coverage, 8-bit, the side-by-side
// and heatmap of --renderer both), the tracer's BVH and the rasterizer's mesh buffers.
uint64_t estimateRenderBytes(const Scene& scene, const RenderOptions& options);

// Throws InputError naming `options.input`, the estimate and the limit when the estimate exceeds it.
void checkMemoryBudget(const Scene& scene, const RenderOptions& options);

// "2G", "512M", "1.5G", "4096" (MiB) → bytes. Throws UsageError naming --max-memory.
uint64_t parseMemorySize(const std::string& text);

}  // namespace shadelab::cli
