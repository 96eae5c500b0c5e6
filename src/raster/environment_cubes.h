// EnvironmentCubes: the rasterizer's approximation for reflective spheres and mesh parts. Each
// gets a cube map of the scene rendered from its centre (the object itself left out) with local shading
// and shadows, one bounce; its fragments add kr ⊙ env(R), R the mirror direction of V. Known error
// (docs/lighting.md): the cube is seen from the centre, not from each surface point (parallax), so what
// lies near the object is misplaced; the object never reflects itself; the faces' resolution blurs.
// Planes keep their exact planar reflection (planar_reflection.h). Not the drawing: RasterRenderer runs
// its colour passes into each face.
#pragma once

#include "gl/objects.h"
#include "raster/frame_block.h"
#include "raster/raster_limits.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>
#include <vector>

namespace shadelab::raster {

// What a cube is rendered around: a sphere (index into scene.spheres) or a mesh part (into the renderer's
// draw ranges), its centre and the near plane that keeps the object's own inside out of view.
struct EnvironmentProbe {
    int sphere = -1;
    int range = -1;
    glm::vec3 centre{0.0f};
    float zNear = 0.01f;
};

// The frame for cube face `face` (+X −X +Y −Y +Z −Z) of `size` texels around `centre`: the GL cube-map
// orientation (window +y is the face's −t), 90° field of view, no planar mirrors inside (one bounce).
FrameBlock cubeFaceFrame(const FrameBlock& frame, const glm::vec3& centre, float zNear, int face, int size);

class EnvironmentCubes {
public:
    // Makes `count` RGBA16F cubes of size² texels per face (reallocating only on change), and checks that
    // what it made can be drawn into. Throws std::runtime_error when it cannot.
    void resize(int count, int size);
    // Attaches face `face` of cube `cube` (and the shared depth buffer) to the framebuffer and binds it.
    void bindFace(int cube, int face) const;
    GLuint texture(int cube) const { return cubes_[size_t(cube)].id(); }
    int size() const { return size_; }

private:
    void attachFace(int cube, int face) const;

    std::vector<gl::Texture> cubes_;
    gl::Framebuffer fbo_;
    gl::Renderbuffer depth_;
    int size_ = 0, depthSize_ = 0;
};

}  // namespace shadelab::raster
