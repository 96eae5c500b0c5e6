// traceImage: start a ProgressiveTrace, wait for its tiles on the calling thread, copy them into place.
#include "trace/trace_image.h"

#include "trace/progressive_trace.h"

#include <algorithm>
#include <chrono>

namespace shadelab::trace {

TraceOutput traceImage(const TraceScene& scene, const TraceSettings& settings,
                       const std::function<void(float)>& progress, const TraceEncoding* encode) {
    validate(settings);
    TraceOutput out;
    Image8& pixels = out.pixels;
    if (encode) {
        pixels.width = settings.width;
        pixels.height = settings.height;
        pixels.channels = 3;
        pixels.data.resize(size_t(settings.width) * size_t(settings.height) * 3);
    } else {
        out.color = ImageF(settings.width, settings.height);
    }
    if (settings.coverage) out.coverage.assign(size_t(settings.width) * size_t(settings.height), 0u);

    ProgressiveTrace trace;
    // The workers are joined before this function returns, so a non-owning pointer is safe.
    trace.start(std::shared_ptr<const TraceScene>(&scene, [](const TraceScene*) {}), settings);
    std::vector<TileResult> tiles;
    ImageF tile;
    while (!trace.done()) {
        tiles.clear();
        trace.wait(tiles, std::chrono::milliseconds(50));
        for (const TileResult& r : tiles) {
            const Tile& t = r.tile;
            if (encode) {
                if (tile.width != t.width || tile.height != t.height) tile = ImageF(t.width, t.height);
                std::copy(r.rgba.begin(), r.rgba.begin() + ptrdiff_t(tile.rgba.size()), tile.rgba.begin());
                const Image8 converted = toImage8(tile, encode->encoding, encode->display, &out.nonFinite);
                for (int y = 0; y < t.height; ++y)
                    std::copy_n(&converted.data[size_t(y) * size_t(t.width) * 3], size_t(t.width) * 3,
                                &pixels.data[(size_t(t.y0 + y) * size_t(settings.width) + size_t(t.x0)) * 3]);
            }
            for (int y = 0; y < t.height; ++y) {
                if (!encode) {
                    const float* src = &r.rgba[size_t(y) * size_t(t.width) * 4];
                    std::copy(src, src + size_t(t.width) * 4, out.color.pixel(t.x0, t.y0 + y));
                }
                if (settings.coverage) {
                    const uint32_t* c = &r.coverage[size_t(y) * size_t(t.width)];
                    std::copy(c, c + t.width, &out.coverage[size_t(t.y0 + y) * size_t(settings.width) + size_t(t.x0)]);
                }
            }
        }
        if (progress) progress(trace.progress());
    }
    return out;
}

TraceOutput traceImage(const Scene& scene, const TraceSettings& settings, const std::function<void(float)>& progress,
                       const TraceEncoding* encode) {
    validate(settings);
    const TraceScene prepared(scene);
    return traceImage(prepared, settings, progress, encode);
}

}  // namespace shadelab::trace
