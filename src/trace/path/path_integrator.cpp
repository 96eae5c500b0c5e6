// PathIntegrator: one path per call, iterative, with next-event estimation and MIS (design.md §8).
#include "trace/path/path_integrator.h"

#include "scene/coverage.h"
#include "scene/light_at.h"
#include "shading/lighting.h"
#include "trace/luminance.h"
#include "trace/path/path_bsdf.h"
#include "trace/path/warp.h"

#include <algorithm>
#include <cmath>

namespace shadelab::trace {
namespace {

// The groups of four numbers each path vertex draws (SampleRng::draw), fixed so that one decision's numbers
// never depend on another's.
constexpr uint32_t kGroupBsdf = 0;     // lobe pick, direction (2), Russian roulette
constexpr uint32_t kGroupEmitter = 1;  // emitter pick, point on it (3)
constexpr uint32_t kGroupBlend = 2;    // alpha BLEND: pass through or not, one group per layer (2, 3, ...)
constexpr int kMaxBlendLayers = 64;

bool positive(const glm::vec3& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; }

}  // namespace

PathIntegrator::PathIntegrator(const TraceScene& scene, const PathSettings& settings)
    : scene_(scene),
      settings_(settings),
      surfaces_(scene),
      whitted_(scene, 0),
      environment_(scene.scene()),
      emitters_(scene, environment_) {
    settings_.maxDepth = std::max(settings_.maxDepth, 0);
}

float PathIntegrator::weightBsdf(float own, float other) const {
    switch (settings_.estimator) {
        case PathEstimator::Bsdf: return 1.0f;
        case PathEstimator::Light: return other > 0.0f ? 0.0f : 1.0f;  // what light sampling cannot reach stays
        case PathEstimator::Mis: break;
    }
    return powerHeuristic(own, other);
}

float PathIntegrator::weightLight(float own, float other) const {
    switch (settings_.estimator) {
        case PathEstimator::Bsdf: return 0.0f;
        case PathEstimator::Light: return 1.0f;
        case PathEstimator::Mis: break;
    }
    return powerHeuristic(own, other);
}

PathSample PathIntegrator::trace(const Ray& cameraRay, const SampleRng& rng) const {
    const Scene& sc = scene_.scene();
    const float eps = scene_.epsilon();
    const BsdfTerms terms{sc.terms.diffuse, sc.terms.specular, sc.terms.reflections};
    PathSample out;
    // A contribution that reached the eye after `scattered` non-delta scatterings: 0 is an emitter seen
    // (directly or in mirrors), 1 direct light, 2 and more indirect light.
    auto add = [&](const glm::vec3& c, int scattered) {
        const bool keep =
            settings_.part == PathPart::All || (settings_.part == PathPart::Direct ? scattered <= 1 : scattered >= 2);
        if (keep && std::isfinite(c.x + c.y + c.z)) out.color += c;
    };

    Ray ray = cameraRay;
    glm::vec3 beta(1.0f);
    float prevPdf = 0.0f;  // density of the BSDF sample that made `ray`; 0 after the camera or a delta lobe
    int scattered = 0;
    for (int bounce = 0;; ++bounce) {
        // Alpha MASK cut-outs are not there (as in the Whitted tracer); an alpha BLEND surface is passed
        // through with probability 1 − alpha, which composites it over what lies behind on average.
        std::optional<Hit> hit = surfaces_.visibleHit(ray, 0.0f, bounce == 0 ? 0 : 1);
        for (int layer = 0; hit && layer < kMaxBlendLayers; ++layer) {
            const Material& hm = scene_.material(*hit);
            if (hm.alphaMode != AlphaMode::Blend) break;
            const float alpha = surfaces_.at(ray, *hit, bounce == 0 ? 0 : 1).alpha;
            if (rng.draw(uint32_t(bounce), kGroupBlend + uint32_t(layer)).x < alpha) break;
            hit = surfaces_.visibleHit(ray, hit->t + eps, bounce == 0 ? 0 : 1);
        }
        if (!hit) {
            if (environment_.emits() || bounce == 0) {
                const float w = prevPdf > 0.0f ? weightBsdf(prevPdf, emitters_.pdfEnvironment(ray.dir)) : 1.0f;
                add(beta * whitted_.environment().escaping(ray.dir) * w, scattered);
            }
            break;
        }
        if (bounce == 0) out.coverage = scene_.coverageId(*hit);
        const Surface s = surfaces_.at(ray, *hit, bounce == 0 ? 0 : 1);
        const Material& m = *s.material;
        // Leaving a transmitting volume (glTF's volume): what the medium let through on the way (Beer–Lambert; the
        // ray's direction is unit, so t is the distance).
        if (s.model == shading::SL_MODEL_PBR && m.transmission.on() && m.volume.on() && !s.entering)
            beta *= m.volume.transmittance(hit->t);
        if (positive(m.emission)) {
            const float w = prevPdf > 0.0f ? weightBsdf(prevPdf, emitters_.pdfHit(ray, *hit)) : 1.0f;
            add(beta * m.emission * s.emissive * w, scattered);  // s.emissive: the emissive texture, or 1
        }
        // The lecture's step 0 (no light term on): no light to carry, so the camera ray's first hit shows its
        // unlit colour, as in the Whitted tracer and the rasterizer, and the path ends there.
        if (shading::noIllumination(sc.terms.ambient, sc.terms.diffuse, sc.terms.specular)) {
            add(beta * shading::unlitColour(s.md, s.baseColor, s.model), scattered);
            break;
        }
        if (bounce > settings_.maxDepth) break;

        const glm::vec3 V = -ray.dir;
        const PathBsdf bsdf(s, whitted_.shadingParams(s, V), V, s.model, terms);
        const glm::vec3 above = s.P + eps * s.Nf, below = s.P - eps * s.Nf;
        if (bsdf.hasSmooth()) {
            // Point, spot and directional lights: the Whitted tracer's terms, π·f·N·L·Il·vis (design.md §7, §8). A
            // light behind a thin transmitting wall is sought from its far side.
            for (const Light& l : sc.lights) {
                const LightAt at = lightAt(l, s.P);
                if (!positive(at.Il)) continue;  // outside a spot's cone or a light's range: no shadow ray
                const glm::vec3 Ld = glm::normalize(at.L);
                const glm::vec3 f = bsdf.evalCos(Ld);
                if (!positive(f)) continue;
                if (sc.terms.shadows && (glm::dot(Ld, s.Nf) < 0.0f ? whitted_.visibility(underside(s), l)
                                                                   : whitted_.visibility(s, l)) <= 0.0f)
                    continue;
                add(beta * f * kPi * at.Il, scattered + 1);
            }
            // One sample of the emissive objects and the environment, drawn from the shadow ray's own origin:
            // a direction aimed from s.P but sent from `above` meets a nearby emitter early, obliquely, and
            // the emitter then shadows itself (light sampling was half the irradiance 0.02 under a sphere
            // lamp). From `above` the ray reaches the sampled point at the sampled distance, and the density
            // is the one pdfHit gives the BSDF's rays, which start there too.
            if (!emitters_.empty() && settings_.estimator != PathEstimator::Bsdf) {
                if (const std::optional<EmitterSample> e =
                        emitters_.sample(above, rng.draw(uint32_t(bounce), kGroupEmitter))) {
                    const bool down = !(glm::dot(e->wi, s.Nf) > 0.0f);
                    const glm::vec3 f = !down || bsdf.transmits() ? bsdf.evalCos(e->wi) : glm::vec3(0.0f);
                    if (positive(f)) {
                        const float tMax = e->environment ? INFINITY : e->distance * (1.0f - 1e-3f) - eps;
                        if (!sc.terms.shadows || !(tMax > 0.0f) ||
                            !scene_.occluded(Ray{down ? below : above, e->wi}, tMax)) {
                            const glm::vec3 Le = e->environment ? whitted_.environment().escaping(e->wi) : e->Le;
                            const float w = weightLight(e->pdf, bsdf.pdf(e->wi));
                            add(beta * f * Le * (w / e->pdf), scattered + 1);
                        }
                    }
                }
            }
        }

        // Continue the path through one BSDF lobe.
        const glm::vec4 u = rng.draw(uint32_t(bounce), kGroupBsdf);
        const std::optional<BsdfSample> b = bsdf.sample(glm::vec3(u));
        if (!b) break;
        beta *= b->weight;
        if (!b->delta) ++scattered;
        prevPdf = b->delta ? 0.0f : b->pdf;
        ray = Ray{b->transmitted ? s.P - eps * s.Nf : above, b->wi};
        if (bounce + 1 >= settings_.rouletteDepth) {
            const float q = std::min(1.0f, std::max(beta.x, std::max(beta.y, beta.z)));
            if (!(u.w < q)) break;
            beta /= q;
        }
    }
    return out;
}

}  // namespace shadelab::trace
