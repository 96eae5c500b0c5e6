// EnvironmentSampler: importance sampling of the light that arrives from outside the scene, for the path
// tracer's next-event estimation (design.md §8). A uniform environment (`background`, times the
// environment's intensity when it has one) is sampled uniformly over the sphere. An .hdr environment is
// sampled over the texels of its unfiltered cube (level 0 of the prefiltered atlas, the radiance escaping
// rays read): a texel with probability ∝ 0.9·luminance·solid angle + 0.1·solid angle (the uniform part
// keeps every direction reachable where the bilinear lookup is brighter than the texel), then a uniform
// point in the texel's face square, whose density per solid angle is exact (r³ of the face point).
#pragma once

#include "scene/scene.h"
#include "trace/path/distribution.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shadelab::trace {

struct EnvironmentDirection {
    glm::vec3 dir{0.0f};  // unit world direction toward the environment
    float pdf = 0.0f;     // per solid angle
};

class EnvironmentSampler {
public:
    explicit EnvironmentSampler(const Scene& scene);

    // Whether any light arrives from outside the scene (an .hdr map, or a non-black background).
    bool emits() const { return emits_; }
    // Whether light sampling should draw from it: an .hdr map. A uniform environment is left to BSDF
    // sampling, which for it is the better strategy (the cosine lobe is a Lambertian surface's ideal
    // importance sampler of constant radiance, and a glossy lobe's own sampling is too).
    bool sampled() const { return emits_ && map_ != nullptr; }
    // u.x picks the texel, (u.y, u.z) the point in it (a uniform environment uses (u.y, u.z)).
    EnvironmentDirection sample(glm::vec3 u) const;
    float pdf(const glm::vec3& dir) const;

    // Map face f's point (x, y) ∈ [−1, 1]² as an unnormalised map direction: the inverse of
    // cubeFaceCoords (shaders/cube_face.glsl).
    static glm::vec3 faceDirection(int face, float x, float y);

private:
    bool emits_ = false;
    const shading::PrefilteredEnvironment* map_ = nullptr;
    int n_ = 0;  // texels per face side at level 0
    float cosRot_ = 1.0f, sinRot_ = 0.0f;
    Distribution1D texels_;  // 6·n² texels, face-major then row-major
};

}  // namespace shadelab::trace
