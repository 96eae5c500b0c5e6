// RasterRenderer: Scene → linear float image through OpenGL (design.md §1, §2). Meshes are rasterized;
// spheres and planes are ray-cast impostors using the tracer's own intersection code, so silhouettes
// and normals are exact. Local illumination only (shadows and reflections arrive with issue 5).
#pragma once

#include "gl/program.h"
#include "image/image.h"
#include "raster/render_target.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace shadelab::raster {

class RasterRenderer {
public:
    // Compiles the programs; needs a current GL 3.3 core context. Throws InputError on shader errors.
    explicit RasterRenderer(const gl::ShaderLibrary& shaders = gl::ShaderLibrary());

    // Uploads every mesh part. Call again when geometry changes; materials are read at draw time.
    void uploadMeshes(const Scene& scene);

    // Draws the scene into the internal target at width x height, with coverage ids when asked.
    // uploadMeshes must have seen the scene's current geometry.
    void draw(const Scene& scene, int width, int height, bool withCoverage = false);

    const RenderTarget& target() const { return target_; }

private:
    struct DrawRange {
        size_t mesh, part;
        size_t firstIndex, indexCount;
    };

    void setMaterial(const gl::Program& p, const Material& m, uint32_t objectId) const;

    gl::Program meshProgram_, sphereProgram_, planeProgram_;
    gl::Buffer frameUbo_;
    gl::VertexArray meshVao_, cubeVao_, emptyVao_;
    gl::Buffer meshVbo_, meshIbo_, cubeVbo_;
    std::vector<DrawRange> ranges_;
    RenderTarget target_;
};

// Convenience for one-shot renders: draw, then read colour (and coverage when asked).
struct RasterOutput {
    ImageF color;
    std::vector<uint32_t> coverage;     // empty unless requested
};
RasterOutput renderRaster(RasterRenderer& r, const Scene& scene, int width, int height, bool withCoverage);

}  // namespace shadelab::raster
