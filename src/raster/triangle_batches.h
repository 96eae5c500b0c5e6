// TriangleBatches: a pass's indexed triangle draws cut into batches, with a glFlush after each full batch.
//
// A software rasterizer (Mesa's llvmpipe, SwiftShader) bins every triangle it is given before its raster
// threads shade any of them, until something flushes: 2CylinderEngine's 121,496 triangles at 1920x1080 held
// llvmpipe's binned scene until glFinish while the raster threads waited for the one thread setting triangles
// up. Flushing every few hundred triangles hands each batch to the raster threads as soon as it is binned, so
// the binned scene stays the size of a batch and shading overlaps set-up: peak 184.3 → 162.0 MiB and 0.51 →
// 0.46 s for that render (bench/README.md, "Headless render"). GL keeps the order of draws across a flush, so
// the image is the same bit for bit. A hardware driver would pay one submission per batch and gain nothing, so
// there the ranges are drawn whole; so are a window's frames (RasterRenderer::setTriangleBatches).
#pragma once

#include <cstddef>

namespace shadelab::raster {

class TriangleBatches {
public:
    // Triangles per batch on a software rasterizer: the smallest that costs no time on that render (64 is
    // 16 % slower and saves 2 MiB more).
    static constexpr size_t kSoftwareBatch = 256;

    // The batch size for the current context: kSoftwareBatch when GL_RENDERER names llvmpipe, softpipe or
    // SwiftShader, else 0 (no batches).
    static size_t sizeForCurrentContext();

    // trianglesPerBatch 0: every draw whole, never flushed.
    explicit TriangleBatches(size_t trianglesPerBatch) : batch_(trianglesPerBatch) {}

    // Draws indexCount indices from firstIndex of the bound element buffer (GL_TRIANGLES, GL_UNSIGNED_INT),
    // cut where a batch fills.
    void draw(size_t firstIndex, size_t indexCount);

private:
    size_t batch_;
    size_t pending_ = 0;  // triangles drawn since the last flush
};

}  // namespace shadelab::raster
