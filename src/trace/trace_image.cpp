// traceImage: the calling thread and resolveThreads() - 1 more pull tiles from one counter, render them and put
// each in place themselves (converted to 8-bit when asked). No queue and no hand-over: a one-shot render has
// nothing to show before the end, and on a machine with as many workers as cores a thread that only collected
// tiles competed with them for the cores and woke for every tile.
#include "trace/trace_image.h"

#include "trace/trace_job.h"
#include "util/fresh_buffer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

namespace shadelab::trace {

namespace {

// Joins the helpers however the calling thread leaves (a tile it renders may throw std::bad_alloc).
struct JoinAll {
    std::vector<std::thread>& threads;
    ~JoinAll() {
        for (std::thread& t : threads)
            if (t.joinable()) t.join();
    }
};

}  // namespace

TraceOutput traceImage(const TraceScene& scene, const TraceSettings& settings,
                       const std::function<void(float)>& progress, const TraceEncoding* encode) {
    validate(settings);
    TraceOutput out;
    const size_t width = size_t(settings.width), pixelCount = width * size_t(settings.height);
    if (encode) {
        out.pixels.width = settings.width;
        out.pixels.height = settings.height;
        out.pixels.channels = 3;
        resizeFresh(out.pixels.data, pixelCount * 3);
    } else {
        out.color = ImageF(settings.width, settings.height);
    }
    if (settings.coverage) out.coverage.assign(pixelCount, 0u);

    const TraceJob job(scene, settings);
    const int tileCount = int(job.tiles.size());
    const int workers = std::max(1, std::min(resolveThreads(settings), tileCount));
    std::atomic<int> next{0}, finished{0};
    std::vector<uint64_t> nonFinite(size_t(workers), 0);

    // Worker `w` renders tiles until none are left; worker 0 is the calling thread and reports progress.
    auto work = [&](int w) {
        using Clock = std::chrono::steady_clock;
        TileResult r;  // reused: its buffers keep their capacity from tile to tile
        uint64_t bad = 0;
        Clock::time_point reported = Clock::now();
        for (int index; (index = next.fetch_add(1, std::memory_order_relaxed)) < tileCount;) {
            job.render(index, r);
            const Tile& t = r.tile;
            if (encode) {
                encodeRgbaRows(r.rgba.data(), size_t(t.width) * 4,
                               &out.pixels.data[(size_t(t.y0) * width + size_t(t.x0)) * 3], width * 3, t.width,
                               t.height, encode->encoding, encode->display, &bad);
            } else {
                for (int y = 0; y < t.height; ++y) {
                    const float* src = &r.rgba[size_t(y) * size_t(t.width) * 4];
                    std::copy(src, src + size_t(t.width) * 4, out.color.pixel(t.x0, t.y0 + y));
                }
            }
            if (settings.coverage)
                for (int y = 0; y < t.height; ++y) {
                    const uint32_t* c = &r.coverage[size_t(y) * size_t(t.width)];
                    std::copy(c, c + t.width, &out.coverage[size_t(t.y0 + y) * width + size_t(t.x0)]);
                }
            const int done = finished.fetch_add(1, std::memory_order_relaxed) + 1;
            if (w == 0 && progress && Clock::now() - reported >= std::chrono::milliseconds(50)) {
                progress(float(done) / float(tileCount));
                reported = Clock::now();
            }
        }
        nonFinite[size_t(w)] = bad;
    };
    {
        std::vector<std::thread> helpers;
        JoinAll joinAll{helpers};
        for (int w = 1; w < workers; ++w) helpers.emplace_back(work, w);
        work(0);
    }
    for (uint64_t b : nonFinite) out.nonFinite += b;
    if (progress) progress(1.0f);
    return out;
}

TraceOutput traceImage(const Scene& scene, const TraceSettings& settings, const std::function<void(float)>& progress,
                       const TraceEncoding* encode) {
    validate(settings);
    const TraceScene prepared(scene);
    return traceImage(prepared, settings, progress, encode);
}

}  // namespace shadelab::trace
