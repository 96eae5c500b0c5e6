// PathBsdf: a surface's scattering as the path tracer samples it (design.md §8). The non-delta part is the
// lecture's local model read as a BRDF: f·N·L = shadeLight(Il = 1)/π, the very lighting.glsl code both other
// renderers run, so a light's direct contribution π·f·Il·N·L is the Whitted tracer's term for term. Phong's
// and Blinn-Phong's specular lobes are sampled by their cos^s lobes (Lafortune & Willems 1994), pbr's GGX
// lobe by its visible normals (Heitz 2018), the diffuse lobe by the cosine. disney's anisotropic GGX lobe is
// sampled by its visible normals in the tangent frame of anisotropyTangent, its clearcoat by GTR1's normals
// (Burley 2012, Appendix B), its diffuse, subsurface and sheen by the cosine; pbr's clear coat (glTF's
// KHR_materials_clearcoat) by its own GGX's visible normals around the coat's normal, pbr's sheen
// (KHR_materials_sheen) by the Charlie distribution's fibre normals; glTF's specular layer changes
// only pbr's evaluation and its lobes' picking. glTF's transmission through a thin wall is the GGX lobe mirrored
// through the surface, sampled by its visible normals as the specular lobe; into a volume it is a refraction about
// a sampled micro-normal, and out of one a refraction by the index, both delta-like (no light sampling through
// them; the integrator absorbs along the way inside). Mirrors (kr) and glass (kt,
// ior, refracted as the Whitted tracer refracts, total internal reflection going to the mirror) are delta
// lobes. One lobe is picked per sample with probabilities from estimated albedos; pdf() is the mixture's.
#pragma once

#include "shading/local_illumination.h"
#include "trace/integrator.h"
#include "trace/path/warp.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>

namespace shadelab::trace {

struct BsdfSample {
    glm::vec3 wi{0.0f};      // unit direction the light arrives from (the continuing ray's direction)
    glm::vec3 weight{0.0f};  // f·|N·wi| / pdf for the non-delta part; the lobe's factor / its probability for deltas
    float pdf = 0.0f;        // solid-angle density of the whole mixture at wi (non-delta), 0 for delta lobes
    bool delta = false;      // a mirror or refraction: no light sampling can reach this direction
    bool transmitted = false;
};

// Which lobes a path may scatter into (the terms a student switches on and off apply here as well).
struct BsdfTerms {
    bool diffuse = true, specular = true, reflections = true;
};

class PathBsdf {
public:
    // `s` from SurfaceSetup::at (trace/surface.h), `V` the unit direction back along the arriving ray.
    // `params` from WhittedIntegrator::shadingParams (textures and energy compensation applied).
    PathBsdf(const Surface& s, const shading::SurfaceParams& params, const glm::vec3& V, int model,
             const BsdfTerms& terms);

    // f(wi, V)·max(N·wi, 0) of the non-delta part (0 below the surface), linear RGB.
    glm::vec3 evalCos(const glm::vec3& wi) const;
    // The density with which sample() returns wi through a non-delta lobe (including the lobe's pick).
    float pdf(const glm::vec3& wi) const;
    // One scattering direction from u (three uniform numbers; u.x picks the lobe). nullopt: absorbed, or a
    // direction under the geometric surface.
    std::optional<BsdfSample> sample(const glm::vec3& u) const;

    // Whether the non-delta part can scatter at all (light sampling is pointless without it).
    bool hasSmooth() const { return pDiffuse_ + pSpecular_ + pCoat_ + pSheen_ + pThin_ > 0.0f; }
    // Whether the non-delta part reaches below the surface (glTF's transmission through a thin wall): light behind
    // it is sampled, from its far side.
    bool transmits() const { return pThin_ > 0.0f; }

private:
    bool halfVector(const glm::vec3& wi, glm::vec3& H, float& VoH) const;
    float specularPdf(const glm::vec3& wi) const;
    // Out of line: the other models' pdf() and evalCos() stay as small, and as inlined, as they were without disney.
    [[gnu::noinline]] float coatPdf(const glm::vec3& wi) const;
    [[gnu::noinline]] float sheenPdf(const glm::vec3& wi) const;
    [[gnu::noinline]] glm::vec3 evalCosDisney(const glm::vec3& wi) const;
    [[gnu::noinline]] glm::vec3 evalCosLayered(const glm::vec3& wi) const;
    glm::vec3 sampleCoat(glm::vec2 u) const;
    glm::vec3 toTangentFrame(const glm::vec3& v) const {
        return {glm::dot(v, stretched_->tangentX), glm::dot(v, stretched_->tangentY), glm::dot(v, N_)};
    }
    glm::vec3 sampleSpecular(glm::vec2 u) const;
    [[gnu::noinline]] float thinPdf(const glm::vec3& wi) const;
    std::optional<BsdfSample> sampleThrough(glm::vec2 u) const;
    void pickDisneyLobes(float NoV, float& diffuse, float& specular, float& coat) const;

    Frame frame_;           // around the unit shading normal
    glm::vec3 N_, Nf_, V_;  // unit shading normal, geometric normal and view direction (all on V's side)
    glm::vec3 md_, ms_;     // the coefficients shadeLight reads (surfaceParams, texture applied)
    float s_;               // exponent, or roughness under pbr
    float alpha_ = 0.0f;    // pbr: GGX α
    glm::vec3 specScale_{1.0f};
    // disney only (made by the constructor under that model): its inputs to shadeLightDisney and the clearcoat's GTR1
    // width. Absent under the other models, which then pay nothing for it.
    struct DisneyLobes {
        glm::vec3 baseColor;
        float metallic;
        glm::vec4 params0, params1;
        float coatAlpha;
    };
    std::optional<DisneyLobes> disney_;
    // An anisotropic GGX lobe (disney's, and pbr's under glTF's anisotropy): its tangents (X and N × X) and its widths
    // along them, sampled by their visible normals in that frame. Absent for an isotropic pbr lobe.
    struct Stretched {
        glm::vec3 tangentX, tangentY;
        float ax, ay;
    };
    std::optional<Stretched> stretched_;
    // pbr under glTF's clear coat only: its (factor, roughness), the frame around its unit normal and its GGX α.
    struct Clearcoat {
        glm::vec2 coat;
        Frame frame;
        float alpha;
    };
    std::optional<Clearcoat> clearcoat_;
    float sheenAlpha_ = 0.0f;  // pbr under glTF's sheen: its fibres' α (sheenAlpha)
    // pbr under glTF's transmission: the transmitted colour (md·t; through a thin wall times the volume's tint of 1)
    // and the transmitted lobe's GGX α; into a volume η = 1/ior, out of one (`leaving`) η = ior.
    struct Through {
        glm::vec3 color;
        float alpha;
        float eta;
        bool leaving;
        glm::vec4 layer;  // the specular layer (SpecularLayer::packed) whose Fresnel the light gives up
    };
    std::optional<Through> through_;
    // pbr with any of glTF's layers (the coat, the specular layer and ior, the sheen): the coefficients
    // shadeLightPbrLayers reads. Absent otherwise.
    std::optional<shading::SurfaceParams> layers_;
    int model_;
    bool diffuseOn_, specularOn_;
    glm::vec3 kr_{0.0f}, kt_{0.0f};
    float eta_ = 1.0f;            // n1 / n2 across the surface along the arriving ray
    bool totalInternal_ = false;  // kt goes to the mirror, as in the Whitted tracer
    glm::vec3 refracted_{0.0f};
    // Lobe picking probabilities (sum 1 unless everything is black).
    float pDiffuse_ = 0.0f, pSpecular_ = 0.0f, pCoat_ = 0.0f, pSheen_ = 0.0f, pMirror_ = 0.0f, pGlass_ = 0.0f;
    float pThin_ = 0.0f, pVolume_ = 0.0f;  // glTF's transmission: the thin wall's lobe, the volume's refraction
};

}  // namespace shadelab::trace
