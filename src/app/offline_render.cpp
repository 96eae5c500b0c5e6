// renderOffline: one request, through the renderer it names.
#include "app/offline_render.h"

#include "image/encode.h"
#include "raster/offscreen.h"
#include "trace/path/path_render.h"
#include "trace/trace_image.h"
#include "trace/trace_scene.h"

#include <memory>

namespace shadelab::app {

Image8 renderOffline(raster::RasterRenderer& raster, const Scene& scene, const render::RenderRequest& request,
                     uint64_t* nonFinite) {
    render::require(request);
    switch (request.engine) {
        case render::Engine::Raster: {
            raster::OffscreenResult r = raster::renderOffscreen(raster, scene, render::toOffscreen(request, scene));
            raster.invalidate();  // its target now holds the offline bands, not the window's image
            if (nonFinite) *nonFinite += r.nonFinite;
            return std::move(r.pixels);
        }
        case render::Engine::Path: {
            const trace::PathOutput out =
                trace::pathTraceImage(std::make_shared<const trace::TraceScene>(scene), render::toPath(request, scene));
            return toImage8(out.color, request.encoding, render::displayOf(request, scene), nonFinite);
        }
        case render::Engine::Trace:
        case render::Engine::Both: break;
    }
    // Converted tile by tile as the tracer delivers, as the command line's render does: no float image.
    const trace::TraceEncoding encoding{request.encoding, render::displayOf(request, scene)};
    trace::TraceOutput out = trace::traceImage(scene, render::toTrace(request, scene), {}, &encoding);
    if (nonFinite) *nonFinite += out.nonFinite;
    return std::move(out.pixels);
}

}  // namespace shadelab::app
