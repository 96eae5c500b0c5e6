// The memory budget of one render, for every front end that renders whole images (`shadelab render`,
// `shadelab.render`): an estimate of what the render will allocate, compared with the request's maxMemory
// (render/render_request.h) before any pixel is drawn, so that a 16384² path render under a 2 GB limit is one
// clear line instead of minutes of paging and std::bad_alloc. An estimate for refusing, not an allocator: it
// errs on the generous side. GL-free: the GL context's share is a measured constant.
#pragma once

#include "render/render_request.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace shadelab::render {

// Half of physical memory, and at most three quarters of the address-space limit (ulimit -v) if one is set:
// the limit of a request that sets no maxMemory.
uint64_t defaultMaxMemory();

// The limit `request` renders under: its maxMemory, else defaultMaxMemory().
uint64_t memoryLimit(const RenderRequest& request);

// A size as the command line's --max-memory writes it: "2G", "512M", "1.5G", "4096" (a bare number is MiB),
// with G/g/GiB or M/m/MiB, positive, at most 1e18 bytes. Throws SettingError naming "max_memory".
uint64_t parseMemorySize(const std::string& text);

// What the render keeps of the image: the CLI encodes a PNG from the 8-bit pixels; Python keeps the linear
// floats beside them (shadelab.Image) and makes no PNG.
enum class RenderOutput { Png, Image };

// What any render of this request needs, whatever the scene: the process, the GL context with the rasterizer's
// programs (raster and both), the images and the rasterizer's band target. check() refuses a maxMemory below
// it; estimateRenderBytes is never less.
uint64_t minimumRenderBytes(const RenderRequest& request);

// Bytes the process will hold while it renders: minimumRenderBytes with the output's images, the loaded scene
// (geometry, textures, the prefiltered environment map), the tracer's BVH, the rasterizer's mesh buffers and
// textures, shadow maps, reflection cubes, mirror targets and environment atlas, and the path tracer's sums
// and environment sampler. The environment map's load, which peaks before the render, has its own
// estimate (environmentLoadBytes, scene/environment_load.h).
uint64_t estimateRenderBytes(const Scene& scene, const RenderRequest& request, RenderOutput output = RenderOutput::Png);

// When the estimate exceeds memoryLimit(request), why, for the front end to word: "a 16384x16384 path render of
// this scene needs about 20480 MiB, over the limit of 2048 MiB"; else none.
std::optional<std::string> memoryProblem(const Scene& scene, const RenderRequest& request,
                                         RenderOutput output = RenderOutput::Png);

// What a raster render of this request allocates from the rendering thread's heap on Mesa's software
// rasterizer, counting only blocks that a HeapWarmup lets glibc serve from the heap (util/heap_warmup.h): the context's
// own share and the band's RGB32F colour and depth targets and the 8-bit image. `shadelab render` makes that much ready
// while the context starts; 0 when the request draws nothing.
uint64_t softwareRasterHeapBytes(const RenderRequest& request);

// Bytes as the messages give them: whole MiB ("512 MiB", rounded up when `roundUp`), or bytes below 1 MiB.
std::string memoryText(uint64_t bytes, bool roundUp = false);

}  // namespace shadelab::render
