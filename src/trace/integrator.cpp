// WhittedIntegrator: local shading through shading::shadeLocal over the surfaces SurfaceSetup gives
// (trace/surface.h), hard shadows, and the kr / kt recursion bounded by RayTreeLimits.
#include "trace/integrator.h"

#include "scene/coverage.h"
#include "scene/light_at.h"
#include "shading/local_illumination.h"
#include "shading/material_maps.h"
#include "shading/texel_decode.h"
#include "shading/texture_sample.h"
#include "trace/pbr_layers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shadelab::trace {

// modelIndex() hands the scene's model to shadeLocal as one of lighting.glsl's constants.
static_assert(int(ShadingModel::Phong) == shading::SL_MODEL_PHONG);
static_assert(int(ShadingModel::BlinnPhong) == shading::SL_MODEL_BLINN_PHONG);
static_assert(int(ShadingModel::Pbr) == shading::SL_MODEL_PBR);
static_assert(int(ShadingModel::Disney) == shading::SL_MODEL_DISNEY);

namespace {

bool positive(const glm::vec3& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; }

}  // namespace

// The tree of one camera sample, walked depth first in a fixed order (refracted child, then reflected), so
// which children the budget cuts depends only on the sample: never on threads, tiles or timing.
struct WhittedIntegrator::Tree {
    int64_t raysLeft;  // secondary rays this sample may still trace
    const std::atomic<bool>* cancel;
    TreeStats stats;
    RayTreeRecord* record = nullptr;  // when set, every ray traced is appended
    int current = -1;                 // the record's index of the ray being shaded
};

const char* treeRayKindName(TreeRayKind kind) {
    switch (kind) {
        case TreeRayKind::Primary: return "primary";
        case TreeRayKind::Shadow: return "shadow";
        case TreeRayKind::Reflected: return "reflected";
        case TreeRayKind::Refracted: return "refracted";
        case TreeRayKind::Behind: return "behind";
    }
    return "?";
}

// Called only while recording (the callers test tree.record: no call at all in a plain render).
void WhittedIntegrator::note(Tree& tree, TreeRayKind kind, int depth, const Ray& ray, const std::optional<Hit>& hit,
                             const glm::vec3& weight, float after) const {
    TreeRay r;
    r.kind = kind;
    r.parent = tree.current;
    r.depth = depth;
    r.ray = ray;
    r.after = after;
    r.hit = hit;
    r.hitId = hit ? scene_.coverageId(*hit) : 0;
    r.weight = weight;
    tree.current = int(tree.record->rays.size());
    tree.record->rays.push_back(r);
}

WhittedIntegrator::WhittedIntegrator(const TraceScene& scene, int maxDepth, const RayTreeLimits& limits)
    : scene_(scene), maxDepth_(std::max(maxDepth, 0)), limits_(limits), env_(scene.scene()), surfaces_(scene) {}

PrimarySample WhittedIntegrator::primary(const Ray& ray, const std::atomic<bool>* cancel, TreeStats* stats) const {
    Tree tree{limits_.maxRays < 0 ? std::numeric_limits<int64_t>::max() : limits_.maxRays, cancel, {}};
    const PrimarySample s = primary(ray, tree);
    if (stats) *stats = tree.stats;
    return s;
}

PrimarySample WhittedIntegrator::recordPrimary(const Ray& ray, RayTreeRecord& record, TreeStats* stats) const {
    record.rays.clear();
    Tree tree{limits_.maxRays < 0 ? std::numeric_limits<int64_t>::max() : limits_.maxRays, nullptr, {}};
    tree.record = &record;
    const PrimarySample s = primary(ray, tree);
    if (stats) *stats = tree.stats;
    return s;
}

void WhittedIntegrator::primary8(const Ray* rays, unsigned valid, PrimarySample* out,
                                 const std::atomic<bool>* cancel) const {
    std::optional<Hit> hits[8];
    surfaces_.visibleHits8(rays, valid, hits);
    for (unsigned v = valid & 0xFFu; v; v &= v - 1) {
        const int k = __builtin_ctz(v);
        Tree tree{limits_.maxRays < 0 ? std::numeric_limits<int64_t>::max() : limits_.maxRays, cancel, {}};
        out[k] = primaryAt(rays[k], hits[k], tree);
    }
}

PrimarySample WhittedIntegrator::primary(const Ray& ray, Tree& tree) const {
    return primaryAt(ray, visibleHit(ray, 0.0f, 0), tree);
}

PrimarySample WhittedIntegrator::primaryAt(const Ray& ray, const std::optional<Hit>& hit, Tree& tree) const {
    if (tree.record) note(tree, TreeRayKind::Primary, 0, ray, hit, glm::vec3(1.0f));
    if (!hit) return {env_.escaping(ray.dir), kBackgroundId};
    return {shade(ray, *hit, 0, glm::vec3(1.0f), tree), scene_.coverageId(*hit)};
}

glm::vec3 WhittedIntegrator::radiance(const Ray& ray, int depth) const {
    Tree tree{limits_.maxRays < 0 ? std::numeric_limits<int64_t>::max() : limits_.maxRays, nullptr, {}};
    return radiance(ray, depth, glm::vec3(1.0f), tree, TreeRayKind::Primary);
}

glm::vec3 WhittedIntegrator::radiance(const Ray& ray, int depth, const glm::vec3& weight, Tree& tree,
                                      TreeRayKind kind) const {
    const std::optional<Hit> hit = visibleHit(ray, 0.0f, depth);
    const int parent = tree.current;
    if (tree.record) note(tree, kind, depth, ray, hit, weight);
    const glm::vec3 L = hit ? shade(ray, *hit, depth, weight, tree) : env_.escaping(ray.dir);
    tree.current = parent;
    return L;
}

bool WhittedIntegrator::admit(const glm::vec3& weight, Tree& tree) const {
    if (tree.stats.cancelled || (tree.cancel && tree.cancel->load(std::memory_order_relaxed))) {
        tree.stats.cancelled = true;
        return false;
    }
    // POV-Ray's adc_bailout: the child's whole contribution is weight ⊙ its radiance, so skipping it costs
    // less than minWeight × (the largest radiance a ray can carry) in every channel.
    const float w = std::max(weight.x, std::max(weight.y, weight.z));
    if (w < limits_.minWeight) {
        ++tree.stats.pruned;
        tree.stats.prunedWeight += w;
        return false;
    }
    // The budget bounds trees whose weights never fall (kr + kt >= 1, as in a glass tree).
    if (tree.raysLeft <= 0) {
        ++tree.stats.cut;
        return false;
    }
    --tree.raysLeft;
    ++tree.stats.secondaryRays;
    return true;
}

// Inlined into visibility(): a call here costs the Whitted tracer about 1 % of its instructions.
__attribute__((always_inline)) inline Ray WhittedIntegrator::shadowRay(const Surface& s, const Light& light,
                                                                       float& tMax) const {
    Ray shadow;
    shadow.origin = s.P + scene_.epsilon() * s.Nf;
    tMax = INFINITY;
    if (light.positional()) {
        const glm::vec3 toLight = light.position - shadow.origin;
        tMax = glm::length(toLight);
        if (!(tMax > 0.0f)) return shadow;
        shadow.dir = toLight / tMax;
    } else {
        shadow.dir = glm::normalize(-light.direction);
    }
    return shadow;
}

float WhittedIntegrator::visibilityBehind(const Surface& s, const Light& light, Tree* record, size_t index) const {
    const Surface other = underside(s);
    const float v = visibility(other, light);
    if (record) noteShadow(*record, other, index, v);
    return v;
}

float WhittedIntegrator::visibility(const Surface& s, const Light& light) const {
    float tMax = 0.0f;
    const Ray shadow = shadowRay(s, light, tMax);
    if (!(tMax > 0.0f)) return 1.0f;
    return scene_.occluded(shadow, tMax) ? 0.0f : 1.0f;
}

void WhittedIntegrator::noteShadow(Tree& tree, const Surface& s, size_t light, float visibility) const {
    TreeRay r;
    r.kind = TreeRayKind::Shadow;
    r.parent = tree.current;
    r.depth = tree.current >= 0 ? tree.record->rays[size_t(tree.current)].depth : 0;
    r.ray = shadowRay(s, scene_.scene().lights[light], r.tMax);
    r.light = int(light);
    r.blocked = visibility == 0.0f;
    r.weight = tree.current >= 0 ? tree.record->rays[size_t(tree.current)].weight : glm::vec3(1.0f);
    // The blocker: the nearest surface before the light (occluded() stops at any; this names the first).
    if (r.blocked) {
        const std::optional<Hit> h = scene_.intersect(r.ray);
        if (h && h->t < r.tMax) {
            r.hit = h;
            r.hitId = scene_.coverageId(*h);
        }
    }
    tree.record->rays.push_back(r);
}

glm::vec3 WhittedIntegrator::environmentSpecularWeight(const Surface& s, glm::vec3 V) const {
    const Scene& sc = scene_.scene();
    if (!env_.lightsPbr() || !shading::physicallyBased(s.model) || !sc.terms.ambient || !sc.terms.specular)
        return glm::vec3(0.0f);
    const Material& m = *s.material;
    const glm::vec3 f0 =
        s.model == shading::SL_MODEL_DISNEY
            ? shading::disneySpecularF0(s.baseColor, s.metallic, m.disney.specular, m.disney.specularTint)
        : s.mapped ? s.ms
                   : shading::pbrF0(m.baseColor, m.metallic) + m.metallic * m.baseColor * (s.tex - 1.0f);
    const glm::vec2 dfg = env_.dfg(shading::IblLookup{}.iblNoV(s.N, V), s.roughness);
    if (s.model == shading::SL_MODEL_PBR && usesLayeredPbr(m)) {  // glTF's specular layer or anisotropy
        const glm::vec4 layer = m.specular.packed(m.ior);
        const glm::vec3 layeredF0 = shading::pbrSpecularF0(s.baseColor, s.metallic, layer);
        const glm::vec3 Ed = layer.w * shading::specularDFG(glm::vec3(layer), dfg);
        const glm::vec3 E = glm::mix(Ed, shading::specularDFG(s.baseColor, dfg), s.metallic);
        return sc.energyCompensation ? E * shading::energyCompensation(layeredF0, dfg) : E;
    }
    glm::vec3 E = shading::specularDFG(f0, dfg);
    if (sc.energyCompensation) E = E * shading::energyCompensation(f0, dfg);
    return E;
}

shading::SurfaceParams WhittedIntegrator::shadingParams(const Surface& s, glm::vec3 V, glm::vec2* dfgOut) const {
    const Scene& sc = scene_.scene();
    const Material& m = *s.material;
    shading::SurfaceParams params =
        shading::surfaceParams(s.model, m.ma, s.md, m.ms, m.s, m.baseColor, m.metallic, m.roughness, sc.normalized,
                               m.disney.lobes0(), m.disney.lobes1());
    const bool pbr = shading::physicallyBased(s.model);
    if (pbr) params.md = shading::pbrDiffuseColor(s.baseColor, m.metallic);
    // A base-colour texture scales ma, and F0's base colour under pbr, the affine form mesh.frag uses.
    params.ma = params.ma * s.tex;
    if (pbr) params.ms = params.ms + m.metallic * m.baseColor * (s.tex - 1.0f);
    if (s.mapped) {  // a metallic-roughness texel (surfaceAt)
        params.ma = s.ma;
        params.md = s.md;
        params.ms = s.ms;
        params.s = s.s;
    }
    if (s.model == shading::SL_MODEL_DISNEY) {
        // The principled BRDF reads the base colour and metallic here (textured, the checker's, a texel's) and
        // takes the environment's light with its own F0 of them, as surface.glsl's surfaceF0.
        params.baseColor = s.baseColor;
        params.metallic = s.metallic;
        params.ms = shading::disneySpecularF0(s.baseColor, s.metallic, m.disney.specular, m.disney.specularTint);
    }
    if (s.model == shading::SL_MODEL_PBR) setPbrLayers(params, s, V);  // glTF's layers (disney has its own)
    params.ma = params.ma * s.ao;
    glm::vec2 dfg(0.0f);
    if (pbr && (sc.energyCompensation || env_.lightsPbr() || params.transmission.x > 0.0f))
        dfg = env_.dfg(shading::IblLookup{}.iblNoV(s.N, V), s.roughness);
    if (pbr && sc.energyCompensation) params.specScale = shading::energyCompensation(params.ms, dfg);
    if (dfgOut) *dfgOut = dfg;
    return params;
}

glm::vec3 WhittedIntegrator::lightThrough(const Surface& s, const shading::SurfaceParams& params, const glm::vec3& V,
                                          const glm::vec2& dfg, const glm::vec3* transmitted) const {
    const Scene& sc = scene_.scene();
    const glm::vec3 Lt = transmitted ? *transmitted
                                     : params.transmitTint *
                                           env_.prefiltered(shading::transmissionDirection(s.N, V, params.transmission),
                                                            params.s * params.transmission.y);
    return shading::transmissionEnvironment(params.transmitColor, Lt, params.specLayer, dfg, sc.terms.diffuse,
                                            sc.terms.specular);
}

glm::vec3 WhittedIntegrator::coatedEnvironment(const glm::vec3& base, const shading::SurfaceParams& params,
                                               const glm::vec3& V) const {
    shading::IblLookup ibl;  // (its functions are not const: the shared GLSL text has no const methods)
    const glm::vec3 pre = env_.prefiltered(ibl.iblReflect(params.coatN, V), params.coat.y);
    const glm::vec2 dfg = env_.dfg(ibl.iblNoV(params.coatN, V), params.coat.y);
    return shading::clearcoatEnvironment(base, params.coatN, V, pre, dfg, params.coat, scene_.scene().terms.specular);
}

glm::vec3 WhittedIntegrator::local(const Ray& ray, const Surface& s, const glm::vec3* reflected, Tree* tree,
                                   const glm::vec3* transmitted) const {
    const Scene& sc = scene_.scene();
    const Material& m = *s.material;
    // The lecture's step 0, as surface.glsl's shadeSurface: no light term on, the surface's unlit colour.
    if (shading::noIllumination(sc.terms.ambient, sc.terms.diffuse, sc.terms.specular))
        return shading::unlitColour(s.md, s.baseColor, s.model) + m.emission * s.emissive;
    const glm::vec3 V = -ray.dir;
    glm::vec2 dfg(0.0f);
    const shading::SurfaceParams params = shadingParams(s, V, &dfg);
    // The environment replaces the constant ambient of pbr surfaces (design.md §8: what global light replaces).
    const bool environmentLit = env_.lightsPbr() && shading::physicallyBased(s.model);
    // glTF's transmission: what arrives through the surface, a traced ray's radiance or, as the rasterizer reads
    // it, the environment along the transmitted direction times the volume's tint.
    const bool transmits = params.transmission.x > 0.0f;
    glm::vec3 through(0.0f);
    if (transmits && (transmitted || (environmentLit && sc.terms.ambient)))
        through = lightThrough(s, params, V, dfg, transmitted);
    glm::vec3 environment(0.0f);
    if (environmentLit && sc.terms.ambient) {
        shading::IblLookup ibl;
        // Anisotropic: the reflection about the bent normal, of the prefiltered environment alone (as the rasterizer).
        const bool bent = params.layered && params.aniso.w > 0.0f;
        const glm::vec3 R = bent ? ibl.iblReflect(shading::anisotropicBentNormal(s.N, V, params.aniso, s.roughness), V)
                                 : ibl.iblReflect(s.N, V);
        const glm::vec3 pre = reflected && !bent ? env_.prefilteredWithMirror(R, s.roughness, *reflected)
                                                 : env_.prefiltered(R, s.roughness);
        environment =
            params.layered
                ? shading::shadeEnvironmentPbrSpecular(
                      params.md, params.baseColor, params.metallic, params.specLayer, env_.irradiance(s.N), pre, dfg,
                      sc.energyCompensation ? shading::energyCompensation(params.ms, dfg) : glm::vec3(1.0f),
                      sc.terms.diffuse, sc.terms.specular)
                : shading::shadeEnvironment(params.md, params.ms, env_.irradiance(s.N), pre, dfg, sc.energyCompensation,
                                            sc.terms.diffuse, sc.terms.specular);
        if (transmits) {  // under the sheen and the coat, as the base's own light
            environment += through;
            through = glm::vec3(0.0f);
        }
        if (params.sheenTable)  // the sheen reflects the prefiltered environment at its own roughness
            environment =
                shading::sheenEnvironment(environment, env_.prefiltered(ibl.iblReflect(s.N, V), params.sheen.w),
                                          params.sheen, params.sheenEV, sc.terms.diffuse);
        environment = s.ao * environment;
        if (params.coat.x > 0.0f) environment = coatedEnvironment(environment, params, V);
    }
    const bool ambientOn = sc.terms.ambient && !environmentLit;
    const bool lit = sc.terms.diffuse || sc.terms.specular;
    // Lights go to shadeLocal in batches of kMaxLights (one batch for every scene the rasterizer takes).
    const bool recording = tree && tree->record;
    shading::LightSample samples[kMaxLights];
    glm::vec3 I(0.0f);
    size_t first = 0;
    do {
        const size_t count = std::min(sc.lights.size() - first, size_t(kMaxLights));
        for (size_t k = 0; k < count; ++k) {
            const Light& l = sc.lights[first + k];
            shading::LightSample& ls = samples[k];
            const LightAt at = lightAt(l, s.P);
            ls.L = at.L;
            ls.Il = at.Il;
            // Only a light that could contribute (N·L > 0, or behind a transmitting surface, and inside a spot's
            // cone and a light's range) needs a shadow ray: otherwise its term is 0.
            const bool front = glm::dot(s.N, ls.L) > 0.0f;
            const bool reaches = (front || transmits) && ls.Il != glm::vec3(0.0f);
            if (front || !reaches) {
                ls.visibility = sc.terms.shadows && lit && reaches ? visibility(s, l) : 1.0f;
                if (recording && sc.terms.shadows && lit && reaches) noteShadow(*tree, s, first + k, ls.visibility);
            } else {  // behind a transmitting surface: sought from its far side (out of the common path)
                ls.visibility =
                    sc.terms.shadows && lit ? visibilityBehind(s, l, recording ? tree : nullptr, first + k) : 1.0f;
            }
        }
        shading::TermFlags terms{ambientOn && first == 0, sc.terms.diffuse, sc.terms.specular};
        const glm::vec3 batch = shading::shadeLocal(s.N, V, samples, count, params, sc.ambient, s.model, terms);
        I = first == 0 ? batch : I + batch;
        first += count;
    } while (first < sc.lights.size());
    // An emitter's own light (design.md §8), as surface.glsl adds u_emission.
    if (transmits) I += through;
    return (environmentLit ? I + environment : I) + m.emission * s.emissive;
}

glm::vec3 WhittedIntegrator::shade(const Ray& ray, const Hit& hit, int depth, const glm::vec3& weight,
                                   Tree& tree) const {
    const Surface s = surfaceAt(ray, hit, depth);
    const int self = tree.current;  // this ray's index in the record, the parent of what it spawns
    // alphaMode BLEND: this surface over what lies behind it on the same ray, as the rasterizer's blend state
    // composites it (docs/gltf-import.md); the surface behind is shaded at the same depth.
    const float alpha = s.material->alphaMode == AlphaMode::Blend ? glm::clamp(s.alpha, 0.0f, 1.0f) : 1.0f;
    glm::vec3 behind(0.0f);
    if (alpha < 1.0f) {
        const std::optional<Hit> next = visibleHit(ray, hit.t + scene_.epsilon(), depth);
        if (tree.record)
            note(tree, TreeRayKind::Behind, depth, ray, next, weight * (1.0f - alpha), hit.t + scene_.epsilon());
        behind = next ? shade(ray, *next, depth, weight * (1.0f - alpha), tree) : env_.escaping(ray.dir);
        tree.current = self;
    }
    auto over = [&](const glm::vec3& c) { return alpha < 1.0f ? c * alpha + behind * (1.0f - alpha) : c; };
    const Material& m = *s.material;
    // glTF's transmission (pbr): a volume's inside only passes light out (its surface is shaded from outside).
    const bool transmits = s.model == shading::SL_MODEL_PBR && m.transmission.on();
    if (transmits && m.volume.on() && !s.entering) return over(leaveVolume(ray, hit, s, depth, weight, tree));
    if (!scene_.scene().terms.reflections || depth >= maxDepth_) return over(local(ray, s, nullptr, &tree));

    const glm::vec3 V = -ray.dir;
    const glm::vec3 N = glm::normalize(s.N);
    const float NoV = glm::dot(N, V);
    const float eps = scene_.epsilon();
    // The light through a transmitting surface, traced: straight on through a thin wall, refracted into a volume
    // (absorbed on the way out, leaveVolume). local() weighs it as the rasterizer weighs the environment there.
    // In an environment the traced radiance stands in for the prefiltered lookup's mirror level, as the reflected
    // ray's does (and the rasterizer's environment cube): from the roughness where that level's weight is 0 on, the
    // lookup alone, and no ray.
    std::optional<glm::vec3> through;
    if (transmits && scene_.scene().terms.diffuse) {
        const glm::vec4 packed = transmissionPacked(m);
        const float roughness = s.roughness * packed.y;
        const glm::vec3 share = m.transmission.factor * (1.0f - s.metallic) * s.baseColor;
        const glm::vec3 D = shading::transmissionDirection(N, V, packed);
        if ((!env_.lightsPbr() || env_.mirrorWeight(roughness) > 0.0f) && admit(weight * share, tree)) {
            through = transmittedRadiance(Ray{s.P - eps * s.Nf, D}, depth + 1, weight * share, tree);
            if (env_.lightsPbr()) through = env_.prefilteredWithMirror(D, roughness, *through);
        }
        tree.current = self;
    }
    const glm::vec3* transmitted = through ? &*through : nullptr;
    glm::vec3 reflectWeight = m.kr;
    glm::vec3 refracted(0.0f);
    if (positive(m.kt)) {
        // Snell's law, n1 sin θ1 = n2 sin θ2, as a vector (Heckbert 1989, "Writing a ray tracer" in Glassner):
        // T = −η V + (η cos θ1 − cos θ2) N with η = n1/n2 and cos² θ2 = 1 − η² (1 − cos² θ1).
        const float eta = s.entering ? 1.0f / m.ior : m.ior;
        const float cos2 = 1.0f - eta * eta * (1.0f - NoV * NoV);
        if (cos2 < 0.0f) {
            reflectWeight += m.kt;  // total internal reflection: the transmitted energy is reflected
        } else if (admit(weight * m.kt, tree)) {
            const glm::vec3 T = glm::normalize(-eta * V + (eta * NoV - std::sqrt(cos2)) * N);
            refracted =
                m.kt * radiance(Ray{s.P - eps * s.Nf, T}, depth + 1, weight * m.kt, tree, TreeRayKind::Refracted);
        }
    }
    // One reflected ray serves kr and a pbr surface's environment specular: one reflected ray per pixel and
    // the same prefiltered lookup (docs/lighting.md, "Image-based lighting"). Escaping, it reads the environment: kr
    // the radiance along R, the specular the prefiltered lookup at the surface's roughness, exactly as the rasterizer.
    // Hitting an object, kr takes the object's radiance (Whitted), and so does the mirror level (level 0) of the
    // specular's trilinear lookup, with its weight 1 − roughness·(levels − 1): smooth surfaces reflect
    // objects sharply, and from roughness 1/(levels − 1) (0.2) on the lookup is the prefiltered one alone.
    const glm::vec3 specularWeight = environmentSpecularWeight(s, V);
    const float mirror = positive(specularWeight) ? env_.mirrorWeight(s.roughness) : 0.0f;
    const glm::vec3 rayWeight = reflectWeight + mirror * specularWeight;
    glm::vec3 I;
    if (positive(rayWeight) && admit(weight * rayWeight, tree)) {
        // Whitted 1980: mirror direction 2N(N·V) − V.
        const glm::vec3 R = glm::normalize(2.0f * NoV * N - V);
        const Ray reflectedRay{s.P + eps * s.Nf, R};
        const std::optional<Hit> next = visibleHit(reflectedRay, 0.0f, depth + 1);
        if (tree.record) note(tree, TreeRayKind::Reflected, depth + 1, reflectedRay, next, weight * rayWeight);
        if (next) {
            const glm::vec3 Lr = shade(reflectedRay, *next, depth + 1, weight * rayWeight, tree);
            tree.current = self;
            I = local(ray, s, mirror > 0.0f ? &Lr : nullptr, &tree, transmitted);
            I += reflectWeight * Lr;
        } else {
            tree.current = self;
            I = local(ray, s, nullptr, &tree, transmitted);
            I += reflectWeight * env_.escaping(R);
        }
    } else {
        I = local(ray, s, nullptr, &tree, transmitted);
    }
    return over(I + refracted);
}

glm::vec3 WhittedIntegrator::transmittedRadiance(const Ray& ray, int depth, const glm::vec3& weight, Tree& tree) const {
    const std::optional<Hit> hit = visibleHit(ray, 0.0f, depth);
    const int parent = tree.current;
    if (tree.record) note(tree, TreeRayKind::Refracted, depth, ray, hit, weight);
    const glm::vec3 L = hit ? shade(ray, *hit, depth, weight, tree) : env_.escaping(ray.dir);
    tree.current = parent;
    return L;
}

glm::vec3 WhittedIntegrator::leaveVolume(const Ray& ray, const Hit& hit, const Surface& s, int depth,
                                         const glm::vec3& weight, Tree& tree) const {
    const Material& m = *s.material;
    const glm::vec3 absorbed = m.volume.transmittance(hit.t);  // the ray's direction is unit: t is the distance
    // N faces the ray, inside; out of the medium n1/n2 = ior. Past the critical angle the light stays inside.
    const glm::vec3 N = glm::normalize(s.N);
    glm::vec3 dir = glm::refract(ray.dir, N, m.ior);
    const bool inside = !(glm::dot(dir, dir) > 0.0f);
    dir = inside ? glm::reflect(ray.dir, N) : glm::normalize(dir);
    // Out of depth or budget: the environment the ray would leave toward.
    if (!scene_.scene().terms.reflections || depth >= maxDepth_ || !admit(weight * absorbed, tree))
        return absorbed * env_.escaping(dir);
    const float eps = scene_.epsilon();
    const Ray next{inside ? s.P + eps * s.Nf : s.P - eps * s.Nf, dir};
    return absorbed * transmittedRadiance(next, depth + 1, weight * absorbed, tree);
}

}  // namespace shadelab::trace
