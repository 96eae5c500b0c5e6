// WhittedIntegrator: the recursive ray tracer of Whitted 1980 ("An Improved Illumination Model for Shaded
// Display") over a TraceScene, exactly as design.md §1 states it. No threads and no images here: the tile
// renderer (progressive_trace.h) calls it per sample.
#pragma once

#include "shading/local_illumination.h"
#include "trace/environment_light.h"
#include "trace/ray.h"
#include "trace/trace_scene.h"
#include "trace/trace_settings.h"

#include <atomic>
#include <cstdint>
#include <glm/vec3.hpp>

namespace shadelab::trace {

// What a hit looks like to shading.
struct Surface {
    glm::vec3 P{0.0f};          // hit point, origin + t·dir as the rasterizer computes it
    glm::vec3 N{0.0f};          // shading normal on the viewer's side, as handed to shadeLight (meshes: not unit)
    glm::vec3 Nf{0.0f};         // unit geometric normal on the viewer's side: secondary rays are offset along it
    bool entering = true;       // the ray arrives from the outward side (sphere outside, plane normal side,
                                // mesh counter-clockwise front), so refraction goes from 1 into ior
    glm::vec3 md{0.0f};         // diffuse coefficient, after the plane's checker
    glm::vec3 baseColor{0.0f};  // pbr base colour, after the plane's checker and the base-colour texture
    glm::vec3 tex{1.0f};        // the base-colour texture's linear RGB here (1 without one): scales md, ma, F0
    const Material* material = nullptr;
    // The other glTF maps (shaders/material_maps.glsl, as mesh.frag): a metallic-roughness texel re-derives
    // ma, md, ms and s (mapped); occlusion scales indirect light by ao; alpha is the base colour's.
    bool mapped = false;
    glm::vec3 ma{0.0f}, ms{0.0f};
    float s = 0.0f;
    float roughness = 0.0f;  // pbr roughness here: the material's, or the texel's when mapped
    float ao = 1.0f;
    float alpha = 1.0f;
    glm::vec3 emissive{1.0f};  // the emissive texture's linear RGB here (1 without one): scales emission
};

// How a primary ray's unnormalised direction D = forward + x·right + y·up changes per pixel step of the
// sampled image (shading::cameraRayDirection): dDdx = (2·tan(fovY/2)/height)·right, dDdy = −(…)·up. With it
// the tracer selects a texture's mip level from exact ray differentials (Igehy 1999), as the rasterizer does
// from screen-space derivatives (shaders/texture_sample.glsl).
struct PixelFootprint {
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 dDdx{0.0f}, dDdy{0.0f};  // zero: no footprint known (every texture sampled as magnified)
};

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
    // Radiance arriving along `ray`, which is `depth` bounces from the camera, as the root of a tree of
    // its own (weight 1, a fresh ray budget). Background on a miss.
    glm::vec3 radiance(const Ray& ray, int depth) const;

    // `depth` 0 is a camera ray: its texture footprint comes from the pixel footprint. Deeper rays sample
    // textures at level 0 with the magnification filter (docs/textures-status.md).
    Surface surfaceAt(const Ray& ray, const Hit& hit, int depth = 0) const;
    void setPixelFootprint(const PixelFootprint& f) { footprint_ = f; }
    // Local illumination (design.md §1) at a surface seen along `ray`: ambient plus every light, each
    // weighted by its shadow-ray visibility when the shadows term is on. A pbr surface in an environment
    // gets the split-sum environment light in place of Ia·ma; its specular part reads `reflected` (the
    // radiance the reflected ray brought back from an object) when given, else the prefiltered lookup.
    glm::vec3 local(const Ray& ray, const Surface& s, const glm::vec3* reflected = nullptr) const;

    // The coefficients shadeLight reads at `s` seen from unit direction V (shading::surfaceParams with the
    // base-colour texture and pbr's energy compensation applied); `dfg`, when given, receives pbr's DFG
    // table value when the scene reads it (else 0). The path tracer's BSDF reads the same.
    shading::SurfaceParams shadingParams(const Surface& s, glm::vec3 V, glm::vec2* dfg = nullptr) const;

    const EnvironmentLight& environment() const { return env_; }

    // vis_l: 1 when the shadow ray from s.P + ε·s.Nf toward the light reaches it, else 0.
    float visibility(const Surface& s, const Light& light) const;

    // The first hit along `ray` beyond t = `after` that an alpha mask does not cut away (Hit::t along `ray`).
    // The path tracer intersects through it too.
    std::optional<Hit> visibleHit(const Ray& ray, float after, int depth) const;

private:
    struct Tree;  // one sample's budget, cancel flag and stats
    glm::vec3 radiance(const Ray& ray, int depth, const glm::vec3& weight, Tree& tree) const;
    glm::vec3 shade(const Ray& ray, const Hit& hit, int depth, const glm::vec3& weight, Tree& tree) const;
    // Whether a child of weight `weight` is traced; counts it in the stats either way.
    bool admit(const glm::vec3& weight, Tree& tree) const;

    const TraceScene& scene_;
    int maxDepth_;
    int model_;
    RayTreeLimits limits_;
    EnvironmentLight env_;
    PixelFootprint footprint_;
    // A material map's filtered linear texel at a triangle hit (surfaceAt), as mesh.frag's sampleMap.
    glm::vec4 mapTexel(const Ray& ray, const Hit& hit, int depth, const TextureBinding& b) const;
    // The split-sum specular weight E = (F0·A + B)·compensation of a pbr surface (0 without IBL specular).
    glm::vec3 environmentSpecularWeight(const Surface& s, glm::vec3 V) const;
};

}  // namespace shadelab::trace
