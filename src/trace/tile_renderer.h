// Tiles and the per-tile render loop: each pixel of a tile from its fixed k×k sample grid, box-filtered
// in linear float, plus its coverage id. One thread per call; threads and delivery are progressive_trace.h.
#pragma once

#include "scene/view.h"
#include "trace/integrator.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace shadelab::trace {

struct Tile {
    int x0 = 0, y0 = 0;         // top-left pixel, row 0 at the top
    int width = 0, height = 0;  // pixels
};

struct TileResult {
    int index = 0;  // position in makeTiles()' list
    Tile tile;
    std::vector<float> rgba;         // tile.width × tile.height × 4, linear, alpha 1, row 0 at the top
    std::vector<uint32_t> coverage;  // tile.width × tile.height ids; empty unless coverage was asked for
};

// Row-major tiles of at most tileSize × tileSize covering width × height.
std::vector<Tile> makeTiles(int width, int height, int tileSize);

// Where the tracer samples: pixel (i, j)'s sample (a, b) of a k×k grid is at (i + (a+0.5)/k, j + (b+0.5)/k).
// It is computed as pixel centre (k·i + a + 0.5, k·j + b + 0.5) of a (k·W)×(k·H) image, which is exactly
// what the rasterizer evaluates when it renders k times larger and box-filters, so the two agree to the bit.
// sampleView must be makeViewSetup(scene, k·W, k·H).
Ray sampleRay(const ViewSetup& sampleView, int k, int i, int j, int a, int b);

// shading::cameraRayDirection's D = forward + x·right + y·up per pixel step of `v`: the texture footprint
// of `v`'s camera rays (WhittedIntegrator::setPixelFootprint).
PixelFootprint pixelFootprint(const ViewSetup& v);

// Renders one tile. Colour: the k² samples summed in row order (b outer, a inner) from 0, then divided by
// k². Coverage: the id seen by the centre-most sample (a, b) = (k/2, k/2), which for odd k is the pixel
// centre and for even k the sample just below and right of it. Returns false, with `out` incomplete, when
// `cancel` became true (checked before each sample, and by the integrator before each secondary ray).
bool renderTile(const WhittedIntegrator& integrator, const ViewSetup& sampleView, int k, bool coverage,
                const Tile& tile, TileResult& out, const std::atomic<bool>* cancel = nullptr);

}  // namespace shadelab::trace
