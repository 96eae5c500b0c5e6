// What a ray's hit looks like to shading, and SurfaceSetup, the one place that works it out for every
// integrator (the Whitted tracer, the path tracer and the probe): the normal flipped to the viewer, the
// plane's checker, and the glTF material maps sampled with the rasterizer's filtering, exactly as the
// rasterizer's shaders do (shaders/sphere.frag, plane.frag, mesh.frag, material_maps.glsl).
#pragma once

#include "trace/ray.h"
#include "trace/trace_scene.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>

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
    int model = 0;  // shading::SL_MODEL_* the material is shaded with: its own, else the scene's
    // The other glTF maps (shaders/material_maps.glsl, as mesh.frag): a metallic-roughness texel re-derives
    // ma, md, ms and s (mapped); occlusion scales indirect light by ao; alpha is the base colour's.
    bool mapped = false;
    glm::vec3 ma{0.0f}, ms{0.0f};
    float s = 0.0f;
    float roughness = 0.0f;  // pbr roughness here: the material's, or the texel's when mapped
    float metallic = 0.0f;   // metallic here: the material's, or the texel's when mapped (disney reads it)
    float ao = 1.0f;
    float alpha = 1.0f;
    glm::vec3 emissive{1.0f};  // the emissive texture's linear RGB here (1 without one): scales emission
    // pbr's clear coat here: (factor, roughness) times its textures' texels, and its normal on the viewer's side:
    // the geometry's (the interpolated one, not the base's normal map), or its own normal map's.
    glm::vec2 coat{0.0f};
    glm::vec3 coatN{0.0f};
    // A mesh's interpolated tangent here (xyz, w the bitangent's sign) for an anisotropic material; zero elsewhere
    // (anisotropyDirection then takes the tangent from the normal).
    glm::vec4 tangent{0.0f};
};

// The same surface seen from its other side: shadow rays toward a light behind a transmitting surface start there.
inline Surface underside(const Surface& s) {
    Surface other = s;
    other.Nf = -s.Nf;
    return other;
}

// How a primary ray's unnormalised direction D = forward + x·right + y·up changes per pixel step of the
// sampled image (shading::cameraRayDirection): dDdx = (2·tan(fovY/2)/height)·right, dDdy = −(…)·up. With it
// the tracer selects a texture's mip level from exact ray differentials (Igehy 1999), as the rasterizer does
// from screen-space derivatives (shaders/texture_sample.glsl).
struct PixelFootprint {
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 dDdx{0.0f}, dDdy{0.0f};  // zero: no footprint known (every texture sampled as magnified)
};

class SurfaceSetup {
public:
    explicit SurfaceSetup(const TraceScene& scene);

    // The surface at `hit` along `ray`. `depth` 0 is a camera ray: its texture footprint comes from the pixel
    // footprint. Deeper rays sample textures at level 0 with the magnification filter
    // (docs/textures-status.md).
    Surface at(const Ray& ray, const Hit& hit, int depth = 0) const;
    // The first hit along `ray` beyond t = `after` that an alpha mask does not cut away (Hit::t along `ray`).
    // Inline: a scene with no alpha-masked part (decided once, in the constructor) asks the scene directly.
    std::optional<Hit> visibleHit(const Ray& ray, float after, int depth) const {
        if (!masks_ && !(after > 0.0f)) return scene_.intersect(ray);
        return visibleHitMasked(ray, after, depth);
    }
    // visibleHit(rays[k], 0, 0) for up to eight camera rays (bit k of `valid`), into out[k]: as one packet
    // (TraceScene::intersect8) where no part is alpha-masked, one by one otherwise.
    void visibleHits8(const Ray* rays, unsigned valid, std::optional<Hit>* out) const {
        if (!masks_) return scene_.intersect8(rays, valid, out);
        for (unsigned v = valid & 0xFFu; v; v &= v - 1) {
            const int k = __builtin_ctz(v);
            out[k] = visibleHitMasked(rays[k], 0.0f, 0);
        }
    }
    void setPixelFootprint(const PixelFootprint& f) { footprint_ = f; }

private:
    // A material map's filtered linear texel at a triangle hit, as mesh.frag's sampleMap.
    std::optional<Hit> visibleHitMasked(const Ray& ray, float after, int depth) const;
    glm::vec4 mapTexel(const Ray& ray, const Hit& hit, int depth, const TextureBinding& b) const;

    const TraceScene& scene_;
    int model_;
    bool masks_ = false;  // some mesh part has alphaMode MASK
    PixelFootprint footprint_;
};

}  // namespace shadelab::trace
