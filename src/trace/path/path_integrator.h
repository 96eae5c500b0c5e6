// PathIntegrator: the path tracer of design.md §8, an estimate of the rendering equation beside the Whitted
// tracer. It shares the Whitted tracer's scene, intersections, surface set-up and shadow rays (it holds a
// WhittedIntegrator for them) and lighting.glsl's BRDFs (PathBsdf). At each vertex: the emission of what
// the path hit (multiple importance sampling against light sampling, power heuristic, Veach 1997), the
// point and directional lights (next-event estimation only: they are deltas), one emitter sample
// (Emitters: emissive objects and the environment), then one BSDF sample to continue. Russian roulette
// from `rouletteDepth` on; `maxDepth` bounces at most. The ambient term is off: light transport replaces
// it. No threads here: path_render.h runs it per pixel and sample.
#pragma once

#include "trace/integrator.h"
#include "trace/path/emitters.h"
#include "trace/path/environment_sampler.h"
#include "trace/path/path_settings.h"
#include "trace/path/sample_rng.h"
#include "trace/surface.h"

#include <cstdint>
#include <glm/vec3.hpp>

namespace shadelab::trace {

struct PathSample {
    glm::vec3 color{0.0f};  // the estimate of the pixel's radiance, linear RGB (PathPart applied)
    uint32_t coverage = 0;  // coverage id of the first hit (scene/coverage.h), 0 for the background
};

class PathIntegrator {
public:
    // `settings.maxDepth` must be resolved (>= 0); PathRender does that.
    PathIntegrator(const TraceScene& scene, const PathSettings& settings);

    // One path through `ray` with the numbers of `rng`.
    PathSample trace(const Ray& ray, const SampleRng& rng) const;

    // Texture footprint of camera rays (SurfaceSetup::setPixelFootprint).
    void setPixelFootprint(const PixelFootprint& f) { surfaces_.setPixelFootprint(f); }

private:
    // Multiple importance sampling weight of a sample drawn by the strategy with density `own` against the
    // other with density `other`, under the chosen estimator.
    float weightBsdf(float own, float other) const;
    float weightLight(float own, float other) const;

    const TraceScene& scene_;
    PathSettings settings_;
    SurfaceSetup surfaces_;      // what each hit looks like to shading, as the Whitted tracer sees it
    WhittedIntegrator whitted_;  // shadow rays, shading parameters, the environment
    EnvironmentSampler environment_;
    Emitters emitters_;
};

}  // namespace shadelab::trace
