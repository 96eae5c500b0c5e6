// GeometryBuffers: the GL buffers RasterRenderer's passes draw from. Every mesh part's vertices and rebased
// indices in one vertex array (uploadMeshes, raster_uploads.cpp) with the ranges that say where each part is,
// the unit cube the impostors are drawn as, the planes' footprints, and an empty vertex array for full-screen
// passes.
#pragma once

#include "gl/objects.h"
#include "raster/draw_range.h"

#include <cstdint>
#include <vector>

namespace shadelab::raster {

struct GeometryBuffers {
    gl::VertexArray meshVao;  // null until the first mesh upload
    gl::Buffer meshVbo, meshIbo;
    std::vector<DrawRange> ranges;  // one per mesh part, in the scene's order
    uint64_t generation = 0;        // bumped by every mesh upload
    gl::VertexArray cubeVao;
    gl::Buffer cubeVbo;
    gl::VertexArray planeVao;  // a plane's footprint triangles (plane_footprint.h), rewritten for every plane drawn
    gl::Buffer planeVbo;
    gl::VertexArray emptyVao;
};

}  // namespace shadelab::raster
