// Accumulation: the viewer's smooth still frame (docs/viewer.md, "Smooth edges"). While nothing changes, the rasterizer
// draws the k×k grid samples of `shadelab render --spp k²` one per frame (RasterRenderer::draw's jitter), and this
// keeps their running average in an RGBA32F texture; after k² frames it is that supersampled image. Any
// change starts it again from the centre sample, so a moving view shows 1 spp.
#pragma once

#include "gl/objects.h"
#include "gl/program.h"
#include "raster/render_target.h"

#include <cstdint>
#include <glm/vec2.hpp>

namespace shadelab::app {

class Accumulation {
public:
    explicit Accumulation(const gl::ShaderLibrary& shaders, int samplesPerSide = 4);

    // Forgets the samples when the image changed (its revision or size); true when it did.
    bool restart(uint64_t revision, int width, int height);
    bool converged() const { return samples_ >= k_ * k_; }
    int samples() const { return samples_; }
    int targetSamples() const { return k_ * k_; }
    // The jitter of the next sample to draw (pixels from the centre, x right, y down). Draw them two by two:
    // after an even count the average is centred.
    glm::vec2 nextJitter() const;
    // Folds the sample just drawn (an RGBA32F texture of the accumulation's size) into the average.
    void add(GLuint sampleTexture);
    // The average so far; 0 before the first sample.
    GLuint texture() const { return samples_ > 0 ? target_.colorTexture() : 0; }
    const raster::RenderTarget& target() const { return target_; }

private:
    int k_;
    int samples_ = 0;
    uint64_t revision_ = 0;
    int width_ = 0, height_ = 0;
    gl::Program program_;
    gl::VertexArray vao_;
    raster::RenderTarget target_;  // colour only
};

}  // namespace shadelab::app
