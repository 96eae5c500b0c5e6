// renderOffline: the viewer's state rendered as `shadelab render` renders a scene file: the same request
// (render/render_request.h), the same library calls and the same bytes, at any size and sample count, whatever
// the window shows. The rasterizer is the window's own (its programs and meshes stay warm); the tracers run
// on the calling thread. For the script action `render`.
#pragma once

#include "image/image.h"
#include "raster/raster_renderer.h"
#include "render/render_request.h"
#include "scene/scene.h"

#include <cstdint>

namespace shadelab::app {

// `request` must pass render::check() and not be Engine::Both; `raster` must hold the scene's meshes and its
// context must be current. Leaves `raster` to redraw its next frame whole. Throws SettingError for a limit
// only the GL knows (its widest target). The pixels with no finite value are added to *nonFinite.
Image8 renderOffline(raster::RasterRenderer& raster, const Scene& scene, const render::RenderRequest& request,
                     uint64_t* nonFinite);

}  // namespace shadelab::app
