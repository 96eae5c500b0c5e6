// Tile list and per-tile sampling loop. Every pixel depends only on its own samples, so the image is the
// same whatever the thread count or tile order.
#include "trace/tile_renderer.h"

#include "shading/lighting.h"

#include <algorithm>

namespace shadelab::trace {

std::vector<Tile> makeTiles(int width, int height, int tileSize) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += tileSize)
        for (int x = 0; x < width; x += tileSize)
            tiles.push_back(Tile{x, y, std::min(tileSize, width - x), std::min(tileSize, height - y)});
    return tiles;
}

PixelFootprint pixelFootprint(const ViewSetup& v) {
    const float step = 2.0f * v.tanHalfFovY / float(v.height);
    return {v.forward, step * v.right, -step * v.up};
}

Ray sampleRay(const ViewSetup& v, int k, int i, int j, int a, int b) {
    const float px = float(k * i + a) + 0.5f;
    const float py = float(k * j + b) + 0.5f;
    return Ray{v.eye, shading::cameraRayDirection(v.forward, v.right, v.up, v.tanHalfFovY, float(v.width),
                                                  float(v.height), px, py)};
}

namespace {

// One sample per pixel: the camera rays of eight neighbouring pixels of a row at a time, their first hits found as
// one packet (WhittedIntegrator::primary8), the same colours as one by one.
bool renderTileInPackets(const WhittedIntegrator& integrator, const ViewSetup& sampleView, bool coverage,
                         const Tile& tile, TileResult& out, const std::atomic<bool>* cancel) {
    for (int y = 0; y < tile.height; ++y)
        for (int x0 = 0; x0 < tile.width; x0 += 8) {
            if (cancel && cancel->load(std::memory_order_relaxed)) return false;
            Ray rays[8];
            unsigned valid = 0;
            for (int k = 0; k < 8 && x0 + k < tile.width; ++k) {
                rays[k] = sampleRay(sampleView, 1, tile.x0 + x0 + k, tile.y0 + y, 0, 0);
                valid |= 1u << k;
            }
            PrimarySample s[8];
            integrator.primary8(rays, valid, s, cancel);
            for (int k = 0; k < 8 && x0 + k < tile.width; ++k) {
                const size_t p = size_t(y) * size_t(tile.width) + size_t(x0 + k);
                const glm::vec3 c = glm::vec3(0.0f) + s[k].color;  // as the k×k sum from zero: -0 becomes +0
                out.rgba[4 * p + 0] = c.x;
                out.rgba[4 * p + 1] = c.y;
                out.rgba[4 * p + 2] = c.z;
                if (coverage) out.coverage[p] = s[k].coverage;
            }
        }
    return !(cancel && cancel->load(std::memory_order_relaxed));
}

}  // namespace

bool renderTile(const WhittedIntegrator& integrator, const ViewSetup& sampleView, int k, bool coverage,
                const Tile& tile, TileResult& out, const std::atomic<bool>* cancel) {
    const size_t n = size_t(tile.width) * size_t(tile.height);
    out.tile = tile;
    out.rgba.assign(4 * n, 1.0f);
    out.coverage.assign(coverage ? n : 0, 0u);
    if (k == 1) return renderTileInPackets(integrator, sampleView, coverage, tile, out, cancel);
    const float count = float(k * k);
    const int centre = k / 2;
    for (int y = 0; y < tile.height; ++y) {
        const int j = tile.y0 + y;
        for (int x = 0; x < tile.width; ++x) {
            const int i = tile.x0 + x;
            glm::vec3 sum(0.0f);
            uint32_t id = 0;
            for (int b = 0; b < k; ++b)
                for (int a = 0; a < k; ++a) {
                    // The integrator also reads `cancel` before each secondary ray, so a deep tree stops too.
                    if (cancel && cancel->load(std::memory_order_relaxed)) return false;
                    const PrimarySample s = integrator.primary(sampleRay(sampleView, k, i, j, a, b), cancel);
                    sum += s.color;
                    if (a == centre && b == centre) id = s.coverage;
                }
            const glm::vec3 c = k == 1 ? sum : sum / count;
            const size_t p = size_t(y) * size_t(tile.width) + size_t(x);
            out.rgba[4 * p + 0] = c.x;
            out.rgba[4 * p + 1] = c.y;
            out.rgba[4 * p + 2] = c.z;
            if (coverage) out.coverage[p] = id;
        }
    }
    // A tree the flag stopped returns a partial colour: the last sample may have been one.
    return !(cancel && cancel->load(std::memory_order_relaxed));
}

}  // namespace shadelab::trace
