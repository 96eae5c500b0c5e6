// WhittedIntegrator: the recursive ray tracer of Whitted 1980 ("An Improved Illumination Model for Shaded
// Display") over a TraceScene, exactly as design.md §1 states it. No threads and no images here: the tile
// renderer (progressive_trace.h) calls it per sample.
#pragma once

#include "shading/local_illumination.h"
#include "trace/environment_light.h"
#include "trace/ray.h"
#include "trace/ray_tree_record.h"
#include "trace/surface.h"
#include "trace/trace_scene.h"
#include "trace/trace_settings.h"

#include <atomic>
#include <cstdint>
#include <glm/vec3.hpp>

namespace shadelab::trace {

struct PrimarySample {
    glm::vec3 color{0.0f};  // linear RGB radiance
    uint32_t coverage = 0;  // coverage id of the first hit (scene/coverage.h), 0 for the background
};

// What one camera sample's ray tree did (RayTreeLimits). A skipped child contributes 0, as one past
// maxDepth does, so the sample's error is at most prunedWeight × (the largest radiance a ray can carry).
struct TreeStats {
    int secondaryRays = 0;      // reflected and refracted rays traced
    int pruned = 0;             // children not traced because their weight < minWeight
    float prunedWeight = 0.0f;  // sum of those children's weights (max channel each)
    int cut = 0;                // children not traced because the sample's maxRays were spent
    bool cancelled = false;     // the cancel flag was seen: the colour is incomplete, throw it away
};

class WhittedIntegrator {
public:
    // maxDepth: how many secondary bounces a path may take; 0 traces primary and shadow rays only.
    // limits: how the tree is pruned within that depth (trace_settings.h).
    WhittedIntegrator(const TraceScene& scene, int maxDepth, const RayTreeLimits& limits = {});

    // One camera sample. `cancel`, when set, is read before every secondary ray: once it is true no
    // further child is traced, so the call returns within about one shade() of it.
    PrimarySample primary(const Ray& ray, const std::atomic<bool>* cancel = nullptr, TreeStats* stats = nullptr) const;
    // primary(rays[k], cancel) for up to eight camera samples (bit k of `valid`) into out[k], the same colours:
    // their first hits are found as one packet (TraceScene::intersect8), which pays for neighbouring pixels.
    void primary8(const Ray* rays, unsigned valid, PrimarySample* out, const std::atomic<bool>* cancel = nullptr) const;
    // The same sample, returning the same colour, with every ray it traces written to `record` (cleared
    // first): the ray view's tree (ray_tree_record.h).
    PrimarySample recordPrimary(const Ray& ray, RayTreeRecord& record, TreeStats* stats = nullptr) const;
    // Radiance arriving along `ray`, which is `depth` bounces from the camera, as the root of a tree of
    // its own (weight 1, a fresh ray budget). Background on a miss.
    glm::vec3 radiance(const Ray& ray, int depth) const;

    // The surface at a hit (SurfaceSetup::at, trace/surface.h).
    Surface surfaceAt(const Ray& ray, const Hit& hit, int depth = 0) const { return surfaces_.at(ray, hit, depth); }
    void setPixelFootprint(const PixelFootprint& f) { surfaces_.setPixelFootprint(f); }
    // Local illumination (design.md §1) at a surface seen along `ray`: ambient plus every light, each
    // weighted by its shadow-ray visibility when the shadows term is on. A pbr surface in an environment
    // gets the split-sum environment light in place of Ia·ma; its specular part reads `reflected` (the
    // radiance the reflected ray brought back from an object) when given, else the prefiltered lookup.
    glm::vec3 local(const Ray& ray, const Surface& s, const glm::vec3* reflected = nullptr) const {
        return local(ray, s, reflected, nullptr);
    }

    // The coefficients shadeLight reads at `s` seen from unit direction V (shading::surfaceParams with the
    // base-colour texture and pbr's energy compensation applied); `dfg`, when given, receives pbr's DFG
    // table value when the scene reads it (else 0). The path tracer's BSDF reads the same.
    shading::SurfaceParams shadingParams(const Surface& s, glm::vec3 V, glm::vec2* dfg = nullptr) const;

    const EnvironmentLight& environment() const { return env_; }

    // vis_l: 1 when the shadow ray from s.P + ε·s.Nf toward the light reaches it, else 0.
    float visibility(const Surface& s, const Light& light) const;

    // The first hit that an alpha mask does not cut away (SurfaceSetup::visibleHit).
    std::optional<Hit> visibleHit(const Ray& ray, float after, int depth) const {
        return surfaces_.visibleHit(ray, after, depth);
    }

private:
    // visibility()'s shadow ray and the distance to the light along it (infinity for a directional light; 0
    // when the point is at the light). Defined inline in integrator.cpp, its only user.
    Ray shadowRay(const Surface& s, const Light& light, float& tMax) const;
    struct Tree;  // one sample's budget, cancel flag and stats, and the record when one is kept
    PrimarySample primary(const Ray& ray, Tree& tree) const;
    // The sample of a camera ray whose first visible hit is known.
    PrimarySample primaryAt(const Ray& ray, const std::optional<Hit>& hit, Tree& tree) const;
    glm::vec3 radiance(const Ray& ray, int depth, const glm::vec3& weight, Tree& tree, TreeRayKind kind) const;
    glm::vec3 shade(const Ray& ray, const Hit& hit, int depth, const glm::vec3& weight, Tree& tree) const;
    // `transmitted`, when given, is the radiance a ray traced through a transmitting pbr surface brought back
    // (glTF's transmission), read in place of the environment along the transmitted direction.
    glm::vec3 local(const Ray& ray, const Surface& s, const glm::vec3* reflected, Tree* tree,
                    const glm::vec3* transmitted = nullptr) const;
    // The light through a transmitting pbr surface (glTF's transmission) seen along V: `transmitted` (a traced ray's
    // radiance) or the environment along the transmitted direction times the volume's tint, weighed as the diffuse
    // lobe (transmissionEnvironment). Out of line: surfaces that do not transmit never call it.
    [[gnu::noinline]] glm::vec3 lightThrough(const Surface& s, const shading::SurfaceParams& params, const glm::vec3& V,
                                             const glm::vec2& dfg, const glm::vec3* transmitted) const;
    // vis_l toward a light behind a transmitting surface, sought from its far side (appended to `record`'s tree as
    // light `index` when given). Out of line, as lightThrough.
    [[gnu::noinline]] float visibilityBehind(const Surface& s, const Light& light, Tree* record, size_t index) const;
    // Radiance arriving along a ray through a transmitting surface, `depth` bounces from the camera: the object it
    // meets, shaded, or the environment along it.
    glm::vec3 transmittedRadiance(const Ray& ray, int depth, const glm::vec3& weight, Tree& tree) const;
    // Light leaving a transmitting volume at `hit`, seen from inside along `ray`: absorbed over the way in
    // (Beer–Lambert), then refracted out by the index (or reflected back in past the critical angle).
    glm::vec3 leaveVolume(const Ray& ray, const Hit& hit, const Surface& s, int depth, const glm::vec3& weight,
                          Tree& tree) const;
    // The environment's light `base` on a pbr surface under its clear coat (params.coat): the coat reflects the
    // prefiltered environment at its own normal and roughness, not the objects around it (docs/lighting.md).
    glm::vec3 coatedEnvironment(const glm::vec3& base, const shading::SurfaceParams& params, const glm::vec3& V) const;
    // Appends a ray to the tree's record, a child of the ray being shaded, and makes it the one being shaded.
    void note(Tree& tree, TreeRayKind kind, int depth, const Ray& ray, const std::optional<Hit>& hit,
              const glm::vec3& weight, float after = 0.0f) const;
    // Appends the shadow ray toward scene light `light` that visibility() traced from `s`, with its answer.
    void noteShadow(Tree& tree, const Surface& s, size_t light, float visibility) const;
    // Whether a child of weight `weight` is traced; counts it in the stats either way.
    bool admit(const glm::vec3& weight, Tree& tree) const;

    const TraceScene& scene_;
    int maxDepth_;
    RayTreeLimits limits_;
    EnvironmentLight env_;
    SurfaceSetup surfaces_;
    // The split-sum specular weight E = (F0·A + B)·compensation of a pbr surface (0 without IBL specular).
    glm::vec3 environmentSpecularWeight(const Surface& s, glm::vec3 V) const;
};

}  // namespace shadelab::trace
