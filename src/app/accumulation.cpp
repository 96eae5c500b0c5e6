#include "app/accumulation.h"

#include "raster/offscreen.h"

namespace shadelab::app {

Accumulation::Accumulation(const gl::ShaderLibrary& shaders, int samplesPerSide)
    : k_(samplesPerSide), program_(gl::Program::build(shaders, "fullscreen.vert", "accumulate.frag")) {
    vao_ = gl::VertexArray::create();
}

bool Accumulation::restart(uint64_t revision, int width, int height) {
    if (revision == revision_ && width == width_ && height == height_) return false;
    revision_ = revision;
    width_ = width;
    height_ = height;
    samples_ = 0;
    return true;
}

// Samples come in point-symmetric pairs (i, k²-1-i) about the pixel centre, so the average after every
// second sample is centred and the picture does not shift while it sharpens; for k = 4 the pairs are taken
// in an order that spreads them over the pixel.
glm::vec2 Accumulation::nextJitter() const {
    const int n = k_ * k_, s = samples_ % n;
    static constexpr int kPairs4[8] = {0, 3, 5, 6, 1, 2, 4, 7};
    const int pair = k_ == 4 ? kPairs4[s / 2] : s / 2;
    return raster::gridSampleOffset(k_, s % 2 == 0 ? pair : n - 1 - pair);
}

void Accumulation::add(GLuint sampleTexture) {
    target_.resize(width_, height_, false);
    target_.bind();
    ++samples_;
    // Running average: dst = src/n + dst·(1 − 1/n); the first sample replaces whatever was there.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / float(samples_));
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    glUseProgram(program_.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sampleTexture);
    glUniform1i(program_.uniform("t_sample"), 0);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::checkError("Accumulation::add");
}

}  // namespace shadelab::app
