// SurfaceSetup: normals and checker exactly as the rasterizer's shaders, the material maps through the
// shared texture lookup (shading/texture_sample.h) with ray differentials for camera rays, and alpha masks.
#include "trace/surface.h"

#include "shading/local_illumination.h"
#include "shading/material_maps.h"
#include "shading/texel_decode.h"
#include "shading/texture_sample.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace shadelab::trace {

SurfaceSetup::SurfaceSetup(const TraceScene& scene) : scene_(scene), model_(modelIndex(scene.scene().model)) {
    for (const Mesh& m : scene.scene().meshes)
        for (const MeshPart& p : m.parts) masks_ = masks_ || p.material.alphaMode == AlphaMode::Mask;
}

glm::vec4 SurfaceSetup::mapTexel(const Ray& ray, const Hit& hit, int depth, const TextureBinding& b) const {
    const Texture& tex = *b.texture;
    const MeshBvh& mb = *scene_.meshBvh();
    const MeshGeometry& g = *scene_.meshPart(hit).geometry;
    const uint32_t tri = scene_.triangleInPart(hit);
    glm::vec2 uv0(0.0f), uv1(0.0f), uv2(0.0f);
    const std::vector<glm::vec2>& uvs = b.texCoord == 1 ? g.texcoords1 : g.texcoords0;  // (0, 0) when absent
    if (uvs.size() == g.positions.size()) {
        uv0 = uvs[g.indices[3 * size_t(tri)]];
        uv1 = uvs[g.indices[3 * size_t(tri) + 1]];
        uv2 = uvs[g.indices[3 * size_t(tri) + 2]];
    }
    // KHR_texture_transform on the interpolated coordinate, as mesh.frag; its derivatives take the linear part.
    shading::TextureLookup transform{};  // the GLSL-shaped members are not const
    const glm::vec4 uvm = b.uvMatrix();
    const glm::vec2 uv = transform.texTransform(hit.b0 * uv0 + hit.b1 * uv1 + hit.b2 * uv2, uvm, b.offset);

    // Ray differentials (Igehy 1999) for a camera ray: dP/dx on the triangle's plane, then the barycentric
    // and (u, v) derivatives through the triangle's edges; texLod turns them into a level of detail.
    float lod = -1.0f;
    if (depth == 0 && footprint_.dDdx != glm::vec3(0.0f)) {
        const std::array<float, 9> v = mb.vertices(hit.index);
        const glm::vec3 p0(v[0], v[1], v[2]), e1 = glm::vec3(v[3], v[4], v[5]) - p0,
                                              e2 = glm::vec3(v[6], v[7], v[8]) - p0;
        const glm::vec3 n = glm::cross(e1, e2);
        const float nn = glm::dot(n, n), nd = glm::dot(n, ray.dir), df = glm::dot(ray.dir, footprint_.forward);
        if (nn > 0.0f && nd != 0.0f && df > 0.0f) {
            const glm::vec3 D = ray.dir / df;  // forward component 1, as cameraRayDirection's unnormalised D
            const float DD = glm::dot(D, D), len = std::sqrt(DD);
            auto dPdPixel = [&](const glm::vec3& dD) {
                const glm::vec3 dDhat = (dD * DD - D * glm::dot(D, dD)) / (DD * len);
                return hit.t * (dDhat - ray.dir * (glm::dot(n, dDhat) / nd));
            };
            auto dUv = [&](const glm::vec3& dP) {
                const float b1 = glm::dot(glm::cross(dP, e2), n) / nn, b2 = glm::dot(glm::cross(e1, dP), n) / nn;
                return transform.texTransform(b1 * (uv1 - uv0) + b2 * (uv2 - uv0), uvm, glm::vec2(0.0f));
            };
            lod = shading::TextureLookup{}.texLod(tex.width(), tex.height(), dUv(dPdPixel(footprint_.dDdx)),
                                                  dUv(dPdPixel(footprint_.dDdy)));
        }
    }
    shading::TexelLevelView views[32];
    const int levels = int(std::min<size_t>(tex.levels.size(), 32));
    for (int l = 0; l < levels; ++l)
        views[l] = {tex.levels[size_t(l)].width, tex.levels[size_t(l)].height, tex.levels[size_t(l)].texels.data()};
    shading::TextureLookup lookup{views, levels,
                                  (tex.srgb ? shading::srgbDecodeTable() : shading::unormDecodeTable()).data(),
                                  shading::unormDecodeTable().data()};
    auto wrap = [](TextureWrap w) {
        return w == TextureWrap::MirroredRepeat ? shading::kTexMirroredRepeat
               : w == TextureWrap::ClampToEdge  ? shading::kTexClamp
                                                : shading::kTexRepeat;
    };
    return lookup.texSample(0, levels, wrap(b.sampler.wrapS), wrap(b.sampler.wrapT), b.sampler.magLinear,
                            b.sampler.minLinear, b.sampler.mipmaps, b.sampler.mipLinear, uv, lod);
}

std::optional<Hit> SurfaceSetup::visibleHitMasked(const Ray& ray, float after, int depth) const {
    // A masked-out texel is not there (mesh.frag discards it): continue past it along the same line, up to 64
    // surfaces, and measure t along `ray` so that shading and the footprint see the original ray.
    float start = after;
    for (int k = 0; k < 64; ++k) {
        std::optional<Hit> hit = scene_.intersect(start > 0.0f ? Ray{ray.origin + start * ray.dir, ray.dir} : ray);
        if (!hit) return hit;
        if (start > 0.0f) hit->t += start;
        const Material& m = scene_.material(*hit);
        if (hit->kind != HitKind::Triangle || m.alphaMode != AlphaMode::Mask) return hit;
        const float alpha = m.alpha * (m.baseColorTexture ? mapTexel(ray, *hit, depth, m.baseColorTexture).a : 1.0f);
        if (!(alpha < m.alphaCutoff)) return hit;
        start = hit->t + scene_.epsilon();
    }
    return std::nullopt;
}

Surface SurfaceSetup::at(const Ray& ray, const Hit& hit, int depth) const {
    const Scene& sc = scene_.scene();
    Surface s;
    s.material = &scene_.material(hit);
    s.model = s.material->model ? modelIndex(*s.material->model) : model_;
    s.md = s.material->md;
    s.baseColor = s.material->baseColor;
    s.roughness = s.material->roughness;
    s.metallic = s.material->metallic;
    s.alpha = s.material->alpha;
    s.coat = s.material->clearcoat.packed();
    s.P = ray.origin + hit.t * ray.dir;
    const glm::vec3 V = -ray.dir;
    switch (hit.kind) {
        case HitKind::Sphere: {
            // Same expressions as shaders/sphere.frag.
            const Sphere& sp = sc.spheres[hit.index];
            const glm::vec3 outward = (s.P - sp.center) / sp.radius;
            s.N = shading::faceForward(outward, V);
            s.entering = !(glm::dot(outward, V) < 0.0f);
            s.Nf = glm::normalize(s.N);
            s.coatN = s.N;
            break;
        }
        case HitKind::Plane: {
            // Same expressions as shaders/plane.frag.
            const Plane& pl = sc.planes[hit.index];
            s.N = shading::faceForward(pl.normal, V);
            s.entering = !(glm::dot(pl.normal, V) < 0.0f);
            s.Nf = glm::normalize(s.N);
            s.coatN = s.N;
            if (pl.checker && shading::checkerParity(s.P, pl.normal, pl.checker->size) == 1) {
                s.md = pl.checker->md2;
                s.baseColor = pl.checker->md2;  // pbr: the second tiles' base colour (F0 stays the plane's)
            }
            break;
        }
        case HitKind::Triangle: {
            // Interpolated vertex normal, flipped to the viewer by the winding as gl_FrontFacing does.
            const MeshBvh& mb = *scene_.meshBvh();
            MeshHit mh{hit.t, hit.index, hit.b0, hit.b1, hit.b2};
            const glm::vec3 Ng = mb.geometricNormal(hit.index);
            const bool back = glm::dot(Ng, ray.dir) > 0.0f;
            const glm::vec3 N = mb.interpolatedNormal(mh);
            s.N = back ? -N : N;
            s.entering = !back;
            const float len = glm::length(Ng);
            s.Nf = len > 0.0f ? (back ? -Ng : Ng) / len : glm::normalize(s.N);
            const Material& m = *s.material;
            if (m.baseColorTexture) {
                const glm::vec4 base = mapTexel(ray, hit, depth, m.baseColorTexture);
                s.tex = glm::vec3(base);
                s.alpha *= base.a;
                s.md *= s.tex;
                s.baseColor *= s.tex;
            }
            // The other maps, as mesh.frag applies them (shaders/material_maps.glsl).
            if (m.metallicRoughnessTexture) {
                const glm::vec4 mr = mapTexel(ray, hit, depth, m.metallicRoughnessTexture);
                const float metallic = shading::mapMetallic(m.metallic, mr);
                s.roughness = shading::mapRoughness(m.roughness, mr);
                s.s = shading::mapExponent(s.model, s.roughness);
                s.md = shading::mapDiffuse(s.baseColor, metallic);
                s.metallic = metallic;
                s.ma = s.md;
                s.ms = shading::mapSpecular(s.model, sc.normalized, s.baseColor, metallic, s.s);
                s.mapped = true;
            }
            // The tangent here (w: the bitangent's sign), for the normal maps; zero without tangents.
            const auto tangent = [&] {
                const MeshGeometry& g = *scene_.meshPart(hit).geometry;
                if (g.tangents.size() != g.positions.size()) return glm::vec4(0.0f);
                const size_t i = 3 * size_t(scene_.triangleInPart(hit));
                return hit.b0 * g.tangents[g.indices[i]] + hit.b1 * g.tangents[g.indices[i + 1]] +
                       hit.b2 * g.tangents[g.indices[i + 2]];
            };
            s.coatN = s.N;  // the coat follows the geometry, not the base's normal map
            if (m.anisotropy.on()) s.tangent = tangent();
            if (m.normalTexture) {
                const glm::vec3 n = shading::mapNormal(N, tangent(), mapTexel(ray, hit, depth, m.normalTexture),
                                                       m.normalTexture.strength);
                s.N = back ? -n : n;
            }
            if (m.clearcoatNormalTexture) {
                const glm::vec3 n =
                    shading::mapNormal(N, tangent(), mapTexel(ray, hit, depth, m.clearcoatNormalTexture),
                                       m.clearcoatNormalTexture.strength);
                s.coatN = back ? -n : n;
            }
            if (m.clearcoatTexture) s.coat.x *= mapTexel(ray, hit, depth, m.clearcoatTexture).r;
            if (m.clearcoatRoughnessTexture) s.coat.y *= mapTexel(ray, hit, depth, m.clearcoatRoughnessTexture).g;
            if (m.emissiveTexture) s.emissive = glm::vec3(mapTexel(ray, hit, depth, m.emissiveTexture));
            if (m.occlusionTexture)
                s.ao =
                    shading::mapOcclusion(m.occlusionTexture.strength, mapTexel(ray, hit, depth, m.occlusionTexture));
            break;
        }
    }
    return s;
}

}  // namespace shadelab::trace
