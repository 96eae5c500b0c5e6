// EnvironmentLight: the tracer's view of Scene::environment: what an escaping ray sees, and the split-sum
// lookups (prefiltered radiance, SH9 irradiance, DFG) that light pbr surfaces, through the same
// shaders/ibl.glsl text the rasterizer runs (shading/ibl_lookup.h). Without an environment, escaping rays
// see `background` and nothing else changes.
#pragma once

#include "scene/scene.h"
#include "shading/ibl_lookup.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shadelab::trace {

class EnvironmentLight {
public:
    explicit EnvironmentLight(const Scene& scene);

    // Whether pbr surfaces are lit by the environment (the scene has one, and pbr surfaces: its model is pbr, or
    // some material's own is). Other surfaces keep the constant ambient.
    bool lightsPbr() const { return lightsPbr_; }
    // Radiance arriving along a ray of direction `dir` that leaves the scene.
    glm::vec3 escaping(glm::vec3 dir) const;
    // Prefiltered radiance around world direction R at `roughness` (the specular lookup).
    glm::vec3 prefiltered(glm::vec3 R, float roughness) const;
    // The weight of level 0 (the unfiltered environment, what a mirror sees) in prefiltered(R, roughness):
    // 1 − roughness·(levels − 1) while positive (a uniform environment counts as the default 6 levels).
    float mirrorWeight(float roughness) const;
    // prefiltered(R, roughness) with its level-0 sample replaced by `mirror`, the radiance the reflected ray
    // brought back from an object (docs/lighting.md: what the tracer's reflected ray does).
    glm::vec3 prefilteredWithMirror(glm::vec3 R, float roughness, glm::vec3 mirror) const;
    // E(N)/π: the radiance a white Lambertian surface of normal N reflects.
    glm::vec3 irradiance(glm::vec3 N) const;
    // The DFG table (A, B) at (N·V, roughness); pbr scenes with an environment or energy compensation only.
    glm::vec2 dfg(float NoV, float roughness) const;

private:
    glm::vec3 uniform_;  // background·intensity (uniform environment, or none: background)
    float intensity_ = 1.0f, cosRot_ = 1.0f, sinRot_ = 0.0f;
    bool lightsPbr_ = false;
    shading::IblLookup lookup_;  // env null for a uniform environment
};

}  // namespace shadelab::trace
