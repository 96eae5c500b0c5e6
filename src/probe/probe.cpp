// probePixel and probeAnchor: the tracer's ray, nearest hit and surface, then every lighting term there.
#include "probe/probe.h"

#include "scene/coverage.h"
#include "scene/light_at.h"
#include "scene/ray_epsilon.h"
#include "scene/view.h"
#include "shading/local_illumination.h"
#include "trace/integrator.h"
#include "trace/pbr_layers.h"
#include "trace/tile_renderer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

namespace shadelab {

namespace {

// Every quantity at the nearest hit of `ray`, which comes from the eye (V = −ray.dir).
ProbeResult probeRay(const trace::TraceScene& traced, const trace::Ray& ray, ProbeResult r) {
    const Scene& scene = traced.scene();
    const std::optional<trace::Hit> hit = traced.intersect(ray);
    if (!hit) return r;
    const trace::WhittedIntegrator integrator(traced, scene.maxDepth);
    const trace::Surface s = integrator.surfaceAt(ray, *hit);
    const glm::vec3 V = -ray.dir;

    r.hit = true;
    r.objectId = traced.coverageId(*hit);
    r.kind = objectRef(scene, r.objectId).kind;
    r.label = objectLabel(scene, r.objectId);
    r.t = hit->t;
    r.P = s.P;
    r.N = glm::normalize(s.N);
    r.V = glm::normalize(V);
    r.material = *s.material;
    r.material.md = s.md;
    const Material& m = r.material;
    r.ambient = shading::shadeAmbient(scene.ambient, m.ma, true);

    // Each model's specular coefficient, with its energy normalisation when the scene asks for it.
    const auto paramsFor = [&](int model) {
        return shading::surfaceParams(model, m.ma, m.md, m.ms, m.s, m.baseColor, m.metallic, m.roughness,
                                      scene.normalized, m.disney.lobes0(), m.disney.lobes1());
    };
    const glm::vec3 msPhong = paramsFor(shading::SL_MODEL_PHONG).ms;
    const glm::vec3 msBlinn = paramsFor(shading::SL_MODEL_BLINN_PHONG).ms;
    // As WhittedIntegrator: the checker's second tiles change pbr's base colour (F0 stays the plane's).
    shading::SurfaceParams paramsPbr = paramsFor(shading::SL_MODEL_PBR);
    paramsPbr.md = shading::pbrDiffuseColor(s.baseColor, m.metallic);
    trace::setPbrLayers(paramsPbr, s, V);  // glTF's layers, as WhittedIntegrator::shadingParams gives them to pbr
    // The base's terms, without the coat, the sheen and the light through (their parts are listed on their own).
    shading::SurfaceParams basePbr = paramsPbr;
    basePbr.coat = glm::vec2(0.0f);
    basePbr.sheenTable = nullptr;
    basePbr.transmission.x = 0.0f;
    r.pbrDiffuseColor = paramsPbr.md;
    r.pbrF0 = paramsPbr.ms;
    const int pbr = shading::SL_MODEL_PBR;
    // disney, as WhittedIntegrator::shadingParams: the base colour here (the checker's), its own F0.
    shading::SurfaceParams paramsDisney = paramsFor(shading::SL_MODEL_DISNEY);
    paramsDisney.md = paramsPbr.md;
    paramsDisney.baseColor = s.baseColor;
    paramsDisney.ms = shading::disneySpecularF0(s.baseColor, m.metallic, m.disney.specular, m.disney.specularTint);
    r.disneyF0 = paramsDisney.ms;
    // One lobe of disney's at a time: the diffuse or specular group, with sheen or clearcoat (d1.x, d1.z) kept or
    // zeroed, so that the four parts are the shared function's own and sum to its term.
    const auto disneyPart = [&](const glm::vec3& L, const glm::vec3& Il, bool diffuse, bool withExtra) {
        glm::vec4 d1 = paramsDisney.disney1;
        if (!withExtra) (diffuse ? d1.x : d1.z) = 0.0f;
        return shading::shadeLightDisney(s.N, L, V, Il, paramsDisney.baseColor, paramsDisney.metallic, paramsDisney.s,
                                         paramsDisney.disney0, d1, diffuse, !diffuse, glm::vec3(1.0f));
    };
    // Each light: the same raw vectors the fragment shaders pass (surface.glsl), then shadeLight.
    std::vector<shading::LightSample> samples;
    for (const Light& light : scene.lights) {
        const LightAt at = lightAt(light, r.P);
        const glm::vec3 Lraw = at.L;
        const glm::vec3 Il = at.Il;
        const bool lit = glm::dot(s.N, Lraw) > 0.0f;  // the terms are 0 on the unlit side: no ray needed
        // A light behind a transmitting pbr surface shines through it, and is sought from its far side.
        const bool behind = !lit && paramsPbr.transmission.x > 0.0f;
        const float vis = scene.terms.shadows && (lit || behind)
                              ? integrator.visibility(behind ? trace::underside(s) : s, light)
                              : 1.0f;
        samples.push_back({Lraw, Il, vis});
        ProbeLight pl;
        pl.name = light.name;
        pl.L = glm::normalize(Lraw);
        pl.R = shading::reflectLight(r.N, pl.L);
        pl.H = glm::normalize(pl.L + r.V);
        pl.NoL = glm::dot(r.N, pl.L);
        pl.RoV = glm::dot(pl.R, r.V);
        pl.NoH = glm::dot(r.N, pl.H);
        pl.Il = Il;
        pl.visibility = vis;
        pl.specPhong = shading::specularPhong(r.N, pl.L, r.V, m.s);
        pl.specBlinn = shading::specularBlinnPhong(r.N, pl.L, r.V, m.s);
        const int phong = shading::SL_MODEL_PHONG, blinn = shading::SL_MODEL_BLINN_PHONG;
        pl.diffuse = vis * shading::shadeLight(s.N, Lraw, V, Il, m.md, m.ms, m.s, phong, true, false);
        pl.specularPhong = vis * shading::shadeLight(s.N, Lraw, V, Il, m.md, msPhong, m.s, phong, false, true);
        pl.specularBlinn = vis * shading::shadeLight(s.N, Lraw, V, Il, m.md, msBlinn, m.s, blinn, false, true);
        // pbr: the factors as specularGGX computes them, and the two parts as shadeLight adds them.
        const float a = shading::pbrAlpha(paramsPbr.s);
        const glm::vec3 NxH = glm::cross(r.N, pl.H);
        pl.D = shading::D_GGX(std::max(pl.NoH, 0.0f), glm::dot(NxH, NxH), a);
        pl.Vis = shading::V_SmithGGXCorrelated(std::max(glm::dot(r.N, r.V), 1e-4f), std::max(pl.NoL, 0.0f), a);
        pl.F = shading::F_Schlick(paramsPbr.ms, std::max(glm::dot(r.V, pl.H), 0.0f));
        const shading::LightSample sample{Lraw, Il};
        glm::vec3 both = shading::shadeLightPbrLayers(s.N, sample, V, basePbr, true, true);
        pl.specularPbr = vis * shading::shadeLightPbrLayers(s.N, sample, V, basePbr, false, true);
        pl.diffusePbr = vis * both - pl.specularPbr;
        if (paramsPbr.transmission.x > 0.0f) {  // glTF's transmission: the light through, part of the base
            const glm::vec3 through =
                shading::transmissionLight(s.N, Lraw, V, Il, paramsPbr.transmitColor, paramsPbr.transmitTint,
                                           paramsPbr.specLayer, paramsPbr.s * paramsPbr.transmission.y, true, true);
            both += through;
            pl.transmissionPbr = vis * through;
        }
        if (paramsPbr.sheenTable) {
            // Under the sheen the base's two parts keep sheenScaling, and the sheen's lobe is the rest of the term.
            shading::SheenLookup table{paramsPbr.sheenTable};
            const glm::vec4 sheen = paramsPbr.sheen;
            const float EL = table.at(table.sheenCos(s.N, Lraw), sheen.w);
            const float keep = shading::sheenScaling(sheen, paramsPbr.sheenEV, EL);
            both = shading::sheenLight(both, s.N, Lraw, V, Il, sheen, paramsPbr.sheenEV, EL, true);
            pl.diffusePbr *= keep;
            pl.specularPbr *= keep;
            pl.transmissionPbr *= keep;
            pl.sheenPbr = vis * both - pl.diffusePbr - pl.specularPbr - pl.transmissionPbr;
        }
        if (paramsPbr.coat.x > 0.0f) {
            // Under the coat the parts below keep 1 − c·Fc, and the coat's lobe is the rest of the term.
            const float keep = 1.0f - shading::clearcoatWeight(s.coatN, V, paramsPbr.coat.x);
            const glm::vec3 coated = vis * shading::clearcoatLight(both, s.coatN, Lraw, V, Il, paramsPbr.coat, true);
            pl.diffusePbr *= keep;
            pl.specularPbr *= keep;
            pl.sheenPbr *= keep;
            pl.transmissionPbr *= keep;
            pl.clearcoatPbr = coated - pl.diffusePbr - pl.specularPbr - pl.sheenPbr - pl.transmissionPbr;
        }
        pl.diffuseDisney = vis * disneyPart(Lraw, Il, true, false);
        pl.sheenDisney = vis * disneyPart(Lraw, Il, true, true) - pl.diffuseDisney;
        pl.specularDisney = vis * disneyPart(Lraw, Il, false, false);
        pl.clearcoatDisney = vis * disneyPart(Lraw, Il, false, true) - pl.specularDisney;
        r.lights.push_back(pl);
    }
    const shading::SurfaceParams paramsPhong{m.ma, m.md, msPhong, m.s}, paramsBlinn{m.ma, m.md, msBlinn, m.s};
    const shading::TermFlags flags{scene.terms.ambient, scene.terms.diffuse, scene.terms.specular};
    r.totalPhong = shading::shadeLocal(s.N, V, samples.data(), samples.size(), paramsPhong, scene.ambient,
                                       shading::SL_MODEL_PHONG, flags);
    r.totalBlinn = shading::shadeLocal(s.N, V, samples.data(), samples.size(), paramsBlinn, scene.ambient,
                                       shading::SL_MODEL_BLINN_PHONG, flags);
    r.totalPbr = shading::shadeLocal(s.N, V, samples.data(), samples.size(), paramsPbr, scene.ambient, pbr, flags);
    r.totalDisney = shading::shadeLocal(s.N, V, samples.data(), samples.size(), paramsDisney, scene.ambient,
                                        shading::SL_MODEL_DISNEY, flags);
    // The lecture's step 0: with no light term on, both renderers show the surface's unlit colour, not black.
    if (shading::noIllumination(scene.terms.ambient, scene.terms.diffuse, scene.terms.specular)) {
        r.unlit = true;
        r.totalPhong = r.totalBlinn = shading::unlitColour(m.md, s.baseColor, shading::SL_MODEL_PHONG);
        r.totalPbr = r.totalDisney = shading::unlitColour(m.md, s.baseColor, pbr);
    }
    return r;
}

}  // namespace

ProbeResult probePixel(const trace::TraceScene& traced, int width, int height, int x, int y) {
    ProbeResult r;
    r.x = x;
    r.y = y;
    r.width = width;
    r.height = height;
    if (width <= 0 || height <= 0) return r;
    // The tracer's own primary ray, nearest hit and surface: the probe explains the reference's pixel.
    return probeRay(traced, trace::sampleRay(makeViewSetup(traced.scene(), width, height), 1, x, y, 0, 0), r);
}

ProbeResult probeAnchor(const trace::TraceScene& traced, int width, int height, const ProbeAnchor& anchor) {
    const Scene& scene = traced.scene();
    ProbeResult r;
    r.width = width;
    r.height = height;
    if (width <= 0 || height <= 0 || anchor.objectId == 0 || anchor.objectId > objectCount(scene)) return r;
    const ViewSetup view = makeViewSetup(scene, width, height);
    const glm::vec3 toPoint = anchor.point - view.eye;
    const float distance = glm::length(toPoint);
    if (!(distance > 0.0f)) return r;
    // The pixel the point falls in now, for the window and the overlay (it may be outside the image).
    const glm::vec4 clip = view.viewProj * glm::vec4(anchor.point, 1.0f);
    if (clip.w > 0.0f) {
        r.x = int(std::floor((clip.x / clip.w * 0.5f + 0.5f) * float(width)));
        r.y = int(std::floor((1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * float(height)));
    }
    // A ray from the eye's direction that starts just short of the point: it reaches the anchored surface
    // whatever now stands in front of it. V is still the direction to the eye.
    const float eps = secondaryRayEpsilon(scene, view.eye);
    trace::Ray ray;
    ray.dir = toPoint / distance;
    ray.origin = anchor.point - ray.dir * std::min(64.0f * eps, 0.5f * distance);
    ProbeResult hit = probeRay(traced, ray, r);
    if (!hit.hit || hit.objectId != anchor.objectId || glm::length(hit.P - anchor.point) > 256.0f * eps) {
        r.hit = false;  // the object has changed under the anchor (an undo, another file): no probe
        return r;
    }
    hit.t = distance;  // from the eye, as a pixel probe reports it
    return hit;
}

}  // namespace shadelab
