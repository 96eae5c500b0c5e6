// firstHitPasses: the surface passes (image/surface_passes.h) of a scene's camera, one ray through each
// pixel's centre, the nearest surface an alpha mask does not cut away, set up as every integrator sees it
// (SurfaceSetup: textures, the checker, normal maps). Albedo is what the surface reflects in all: md + ms + kr
// under Phong and Blinn-Phong, the base colour under pbr (clamped to [0, 1]); an emitter's is 1 so that its
// light is not mistaken for a lit surface's. The same for every renderer (the rasterizer draws the same
// geometry): the denoiser's guides and `render --passes`.
#pragma once

#include "image/surface_passes.h"
#include "trace/trace_scene.h"

namespace shadelab::trace {

// `threads` 0: every core.
SurfacePasses firstHitPasses(const TraceScene& scene, int width, int height, int threads = 0);

}  // namespace shadelab::trace
