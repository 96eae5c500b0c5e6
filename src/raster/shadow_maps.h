// ShadowMaps: the depth maps behind the rasterizer's hard shadows (Williams 1978, "Casting curved shadows
// on curved surfaces"). One 2D-array depth texture holds every layer: an orthographic map per directional
// light, one perspective map per point light outside the casters' bounds, six cube faces otherwise.
// Not the shading: shaders/shadow.glsl does the lookups, with the biases of RasterSettings.
#pragma once

#include "gl/program.h"
#include "raster/draw_range.h"
#include "raster/raster_limits.h"
#include "raster/shadow_block.h"
#include "raster/triangle_batches.h"
#include "scene/scene.h"

#include <vector>

namespace shadelab::raster {

class ShadowMaps {
public:
    // Needs a current GL 3.3 core context. The depth-only programs are built now when `buildNow` (the viewer's
    // check at start: a shader error shows before anything draws), else by the first render that has layers
    // to draw (a one-shot render without shadows never compiles them). `shaders` must outlive this object.
    ShadowMaps(const gl::ShaderLibrary& shaders, bool buildNow);

    // Renders every layer fitShadows (shadow_fit.h) fits for the scene's first kMaxShadowedLights lights
    // (casters: meshes and spheres; planes occlude analytically in the shader) and uploads the block. Leaves the
    // framebuffer unbound. meshVao draws `ranges`; cubeVao holds the 36-vertex unit cube of the sphere impostors.
    // batchTriangles: the mesh draws' TriangleBatches size (0: whole).
    void render(const Scene& scene, const RasterSettings& settings, const std::vector<DrawRange>& ranges,
                GLuint meshVao, GLuint cubeVao, size_t batchTriangles);

    // The shadow-ray offset ε (scene/ray_epsilon.h) scales with the box of casters and eye, so it follows the
    // camera; the maps do not depend on it. Updates the block only (no depth pass) when it changed.
    void setEpsilon(float epsilon);

    // Binds the block and the array texture for the colour passes.
    void bind(GLuint blockBinding, GLuint textureUnit) const;

    int layers() const { return layerCount_; }
    int size() const { return size_; }
    const ShadowBlock& block() const { return block_; }

private:
    void buildPrograms();
    void allocate(int size, int layers);
    void drawLayer(const Scene& scene, const std::vector<DrawRange>& ranges, GLuint meshVao, GLuint cubeVao, int layer,
                   size_t batchTriangles) const;

    const gl::ShaderLibrary* shaders_;
    gl::Program meshDepth_, sphereDepth_;  // empty until buildPrograms
    gl::Buffer ubo_;
    gl::Texture maps_;
    gl::Framebuffer fbo_;
    int size_ = 0, allocatedLayers_ = 0, layerCount_ = 0;
    ShadowBlock block_{};
};

}  // namespace shadelab::raster
