// WorkerTracer: what one of the page's Web Workers traces. The page has no threads (they would need
// SharedArrayBuffer, and so COOP/COEP headers a plain static server does not send), so the tracers run in
// workers, each with its own copy of the module: a worker rebuilds the page's scene from its saved JSON (parse
// of save is the same scene, field by field) and renders the tiles it is handed. Every worker builds the same
// TraceJob from the same request, so the assembled image is the bytes `shadelab render --renderer trace`
// writes. The Global view's path tracer runs here too, a pass of samples at a time.
#pragma once

#include "image/encode.h"
#include "trace/path/path_render.h"
#include "trace/tile_renderer.h"
#include "trace/trace_job.h"
#include "trace/trace_scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::web {

class WorkerTracer {
public:
    // `sceneJson` as PageLab::sceneJson() writes it; `baseDir` the folder its models' relative paths start
    // from. Throws InputError naming the scene and the problem.
    WorkerTracer(const std::string& sceneJson, const std::string& baseDir);

    // The Whitted reference of a width x height request (render::RenderRequest, Engine::Trace, with coverage):
    // sets up the job and returns how many tiles it has.
    int startReference(int width, int height);
    // The tiles traced since the last clearBatch() (or startReference), packed one after another in the order they
    // were traced: (index, x0, y0, width, height) for each in `tiles`, their pixels in `rgb` (8-bit, encoded as
    // `shadelab render --renderer trace` encodes its tiles for the PNG, rows from the top) and their ids in
    // `coverage`. The worker sends a batch to the page in one message: per tile, the calls and the objects a tile
    // of its own took were a quarter of a worker's time.
    struct TileBatch {
        std::vector<int32_t> tiles;
        std::vector<uint8_t> rgb;
        std::vector<uint32_t> coverage;
    };
    // Renders tile `index` of the job and appends it to the batch; returns how many tiles the batch holds.
    int traceTile(int index);
    const TileBatch& batch() const { return batch_; }
    void clearBatch();

    // The path tracer's progressive image at width x height (the scene's depth, the request's defaults);
    // addSamples adds `count` samples to every pixel, image() is the running mean, linear RGBA.
    void startGlobal(int width, int height);
    void addGlobalSamples(int count);
    int globalSamples() const { return path_ ? path_->samples() : 0; }
    ImageF globalImage() const;
    // This worker's share of the Global image when several share it: `count` more samples in rows first,
    // first + step, ... (trace::PathRender::addSamplesToRows), and the running mean of just those rows, packed
    // one after the other (linear RGBA).
    void addGlobalRowSamples(int count, int first, int step);
    std::vector<float> globalRows(int first, int step) const;

private:
    std::shared_ptr<const trace::TraceScene> scene_;
    std::unique_ptr<trace::TraceJob> job_;
    trace::TileResult tile_;  // the tile being traced, its buffers reused
    TileBatch batch_;
    Encoding encoding_ = Encoding::Srgb;  // the reference's, as the native render's request has them
    DisplaySettings display_;
    std::unique_ptr<trace::PathRender> path_;
};

}  // namespace shadelab::web
