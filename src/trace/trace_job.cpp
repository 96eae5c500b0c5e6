// TraceJob: the sample view at k times the image size, the integrator with the view's texture footprint, tiles.
#include "trace/trace_job.h"

namespace shadelab::trace {

TraceJob::TraceJob(const TraceScene& scene, const TraceSettings& st)
    : settings(st),
      k(samplesPerAxis(st)),
      sampleView(makeViewSetup(scene.scene(), k * st.width, k * st.height)),
      integrator(scene, st.maxDepth >= 0 ? st.maxDepth : scene.scene().maxDepth, st.rayTree),
      tiles(makeTiles(st.width, st.height, st.tileSize)) {
    integrator.setPixelFootprint(pixelFootprint(sampleView));
}

bool TraceJob::render(int index, TileResult& out, const std::atomic<bool>* cancel) const {
    out.index = index;
    return renderTile(integrator, sampleView, k, settings.coverage, tiles[size_t(index)], out, cancel);
}

}  // namespace shadelab::trace
