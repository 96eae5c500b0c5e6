// Emitters: the light sources the path tracer samples by next-event estimation besides the point and
// directional lights (design.md §8): emissive spheres and mesh triangles (material `emission`, both sides)
// and an .hdr environment (a uniform one is left to BSDF sampling: EnvironmentSampler::sampled). One is picked per
// sample: the environment with probability 1/2 when there are also emissive objects (else 1), an object with
// probability ∝ its power (luminance(emission) × area), so a triangle's pick does not need its index. A sphere seen
// from outside is sampled by the cone it subtends, from inside by area; a triangle by area. Emissive planes are
// infinite: they are found by BSDF sampling only (pdf 0 here, so multiple importance sampling gives their hits full
// weight).
#pragma once

#include "trace/path/distribution.h"
#include "trace/path/environment_sampler.h"
#include "trace/trace_scene.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <vector>

namespace shadelab::trace {

struct EmitterSample {
    glm::vec3 wi{0.0f};     // unit direction from the shading point toward the sampled point
    float distance = 0.0f;  // to the sampled point; infinity for the environment
    float pdf = 0.0f;       // per solid angle, the emitter's pick included
    bool environment = false;
    glm::vec3 Le{0.0f};  // emitted radiance toward the shading point (objects; the caller looks up the environment)
};

class Emitters {
public:
    Emitters(const TraceScene& scene, const EnvironmentSampler& environment);

    bool empty() const { return pick_.empty() && !environment_->sampled(); }
    // A sample toward a light from point P; u.x picks the emitter, (u.y, u.z, u.w) the point on it.
    std::optional<EmitterSample> sample(const glm::vec3& P, const glm::vec4& u) const;
    // The density with which sample(P, ·) yields the direction of `ray` (origin P) that hit `hit`, an
    // emissive object: 0 for planes and non-emitters.
    float pdfHit(const Ray& ray, const Hit& hit) const;
    // The density with which sample() yields the escaping direction `dir`.
    float pdfEnvironment(const glm::vec3& dir) const;

private:
    // One sampled emitter: a sphere, or one triangle of an emissive mesh part.
    struct Entry {
        bool sphere = false;
        uint32_t sphereIndex = 0;
        glm::vec3 p0{0.0f}, e1{0.0f}, e2{0.0f};  // triangle corner 0 and the edges to 1 and 2, world units
        glm::vec3 Le{0.0f};
    };
    float objectShare() const { return environment_->sampled() ? 0.5f : 1.0f; }
    // Solid-angle density of the sphere's sampling from P toward the point q on it, before the pick.
    static float sphereDensity(const Sphere& s, const glm::vec3& P, const glm::vec3& q);

    const TraceScene* scene_;
    const EnvironmentSampler* environment_;
    std::vector<Entry> entries_;
    Distribution1D pick_;  // over entries_, by power
};

}  // namespace shadelab::trace
