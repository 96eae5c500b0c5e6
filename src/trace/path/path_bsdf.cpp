// PathBsdf: evaluation through lighting.glsl's shadeLightScaled, shadeLightDisney and glTF's layers
// (shadeLightPbrLayers: the specular layer, the sheen and the clear coat), lobe sampling through warp.h and
// sheen_lut.h (the Charlie distribution's normals).
#include "trace/path/path_bsdf.h"

#include "shading/lighting.h"
#include "trace/luminance.h"

#include <algorithm>
#include <cmath>

namespace shadelab::trace {
namespace {

float nonNegative(float x) { return x > 0.0f ? x : 0.0f; }

}  // namespace

PathBsdf::PathBsdf(const Surface& s, const shading::SurfaceParams& params, const glm::vec3& V, int model,
                   const BsdfTerms& terms)
    : frame_(glm::normalize(s.N)),
      N_(frame_.n),
      Nf_(s.Nf),
      V_(V),
      md_(params.md),
      ms_(params.ms),
      s_(params.s),
      specScale_(params.specScale),
      model_(model),
      diffuseOn_(terms.diffuse),
      specularOn_(terms.specular) {
    const Material& m = *s.material;
    if (model_ == shading::SL_MODEL_PBR) alpha_ = shading::pbrAlpha(s_);
    const bool transmitting = model_ == shading::SL_MODEL_PBR && params.transmission.x > 0.0f;
    if (transmitting && m.volume.on() && !s.entering) {
        // Inside a transmitting volume the light only leaves it, refracted by the index (as the Whitted tracer's
        // leaveVolume), about a micro-normal of the transmitted lobe.
        through_ =
            Through{glm::vec3(1.0f), shading::pbrAlpha(s_ * params.transmission.y), m.ior, true, params.specLayer};
        pVolume_ = 1.0f;
        return;
    }
    const float NoV = std::clamp(glm::dot(N_, V_), 0.0f, 1.0f);
    if (model_ == shading::SL_MODEL_DISNEY) {
        const glm::vec3 X = shading::anisotropyTangent(N_);
        const glm::vec2 a = shading::disneyAnisoAlpha(s_, params.disney0.w);
        disney_ = DisneyLobes{params.baseColor, params.metallic, params.disney0, params.disney1,
                              shading::disneyClearcoatAlpha(params.disney1.w)};
        stretched_ = Stretched{X, glm::cross(N_, X), a.x, a.y};
    }
    if (model_ == shading::SL_MODEL_PBR && params.layered && params.aniso.w > 0.0f) {
        // glTF's anisotropy: GGX stretched to mix(α, 1, strength²) along its direction T, α across it.
        const glm::vec3 T(params.aniso);
        const float a = shading::pbrAlpha(s_);
        stretched_ = Stretched{T, glm::cross(N_, T), glm::mix(a, 1.0f, params.aniso.w * params.aniso.w), a};
    }

    // Estimated albedos of each lobe pick the lobe: a sample goes where the light it carries is.
    float diffuse = diffuseOn_ ? luminance(md_) : 0.0f;
    float specular = 0.0f, coat = 0.0f, sheen = 0.0f, transmit = 0.0f;
    if (transmitting && diffuseOn_) {
        // glTF's transmission takes its share of the diffuse lobe's light (md here is what stays diffuse).
        through_ = Through{params.transmitColor, shading::pbrAlpha(s_ * params.transmission.y), params.transmission.z,
                           false, params.specLayer};
        transmit = luminance(params.transmitColor * params.transmitTint);
    }
    if (model_ == shading::SL_MODEL_PBR && params.sheenTable) {
        // glTF's sheen reflects max3(c)·E(N·V) of the light toward the viewer and the base keeps the rest (as the
        // environment's light is split); its fibre normals are sampled by D_Charlie·N·H.
        layers_ = params;
        sheenAlpha_ = shading::sheenAlpha(params.sheen.w);
        const glm::vec3 c(params.sheen);
        if (diffuseOn_) sheen = std::max(luminance(c) * params.sheenEV, 0.02f * std::max(c.x, std::max(c.y, c.z)));
    }
    if (model_ == shading::SL_MODEL_DISNEY) {
        pickDisneyLobes(NoV, diffuse, specular, coat);
    } else if (specularOn_) {
        if (model_ == shading::SL_MODEL_PHONG) {
            specular = luminance(ms_) * 2.0f / (s_ + 2.0f);  // ∫ cos^s over the hemisphere, relative to the cosine's
        } else if (model_ == shading::SL_MODEL_BLINN_PHONG) {
            specular = luminance(ms_) * 8.0f / (s_ + 8.0f);
        } else {
            float F = luminance(shading::F_Schlick(ms_, NoV) * specScale_);
            if (params.layered) {
                // glTF's specular layer: the dielectric's weighted Fresnel and the metal's, mixed by metallic.
                layers_ = params;
                const glm::vec4 l = params.specLayer;
                const glm::vec3 Fd = l.w * shading::F_Schlick(glm::vec3(l), NoV);
                F = luminance(glm::mix(Fd, shading::F_Schlick(params.baseColor, NoV), params.metallic) * specScale_);
            }
            specular = F;
            diffuse *= 1.0f - std::min(F, 1.0f);
            transmit *= 1.0f - std::min(F, 1.0f);
            if (sheen > 0.0f) {
                const float keep = shading::sheenScaling(params.sheen, params.sheenEV, params.sheenEV);
                diffuse *= keep;
                specular *= keep;
                transmit *= keep;
            }
            if (params.coat.x > 0.0f) {
                // The coat reflects about factor·Fc(Nc·V) of the light and passes the rest to the base.
                const glm::vec3 Nc = glm::normalize(params.coatN);
                clearcoat_ = Clearcoat{params.coat, Frame(Nc), shading::pbrAlpha(params.coat.y)};
                layers_ = params;
                const float w = shading::clearcoatWeight(Nc, V_, params.coat.x);
                diffuse *= 1.0f - w;
                specular *= 1.0f - w;
                transmit *= 1.0f - w;
                sheen *= 1.0f - w;
                coat = std::max(w, 0.02f * params.coat.x);
            }
        }
        // A lobe with any weight keeps a floor of samples: its albedo estimate may be off near grazing angles.
        if (luminance(ms_) > 0.0f) specular = std::max(specular, 0.05f * luminance(ms_));
    }
    if (terms.reflections) {
        kr_ = m.kr;
        if (glm::any(glm::greaterThan(m.kt, glm::vec3(0.0f)))) {
            // Snell's law as the Whitted tracer applies it (integrator.cpp, shade()).
            eta_ = s.entering ? 1.0f / m.ior : m.ior;
            const float cos2 = 1.0f - eta_ * eta_ * (1.0f - NoV * NoV);
            if (cos2 < 0.0f) {
                totalInternal_ = true;
                kr_ += m.kt;
            } else {
                kt_ = m.kt;
                refracted_ = glm::normalize(-eta_ * V_ + (eta_ * NoV - std::sqrt(cos2)) * N_);
            }
        }
    }
    if (through_) {
        // Evaluated by the layered function; a volume's light is refracted (sampled alone, never evaluated).
        if (!layers_) layers_ = params;
        if (through_->eta > 0.0f) layers_->transmission.x = 0.0f;
    }
    const bool thin = through_ && !(through_->eta > 0.0f);
    const float mirror = nonNegative(luminance(kr_)), glass = nonNegative(luminance(kt_));
    const float total = diffuse + specular + coat + sheen + mirror + glass + transmit;
    if (total > 0.0f) {
        (thin ? pThin_ : pVolume_) = transmit / total;
        pDiffuse_ = diffuse / total;
        pSpecular_ = specular / total;
        pCoat_ = coat / total;
        pSheen_ = sheen / total;
        pMirror_ = mirror / total;
        pGlass_ = glass / total;
    }
}

// disney's lobes picked by estimates of what each reflects: the diffuse (with subsurface and sheen) as its
// colour, the specular lobe as its Fresnel at N·V, the clearcoat as a quarter of its own; each with a floor.
void PathBsdf::pickDisneyLobes(float NoV, float& diffuse, float& specular, float& coat) const {
    const float FV = shading::schlickWeight(NoV);
    const DisneyLobes& d = *disney_;
    const float diffuseWeight = 1.0f - d.metallic;
    diffuse = diffuseOn_ ? diffuseWeight * (luminance(d.baseColor) + 0.25f * d.params1.x) : 0.0f;
    if (!specularOn_) return;
    const glm::vec3 f0 = shading::disneySpecularF0(d.baseColor, d.metallic, d.params0.y, d.params0.z);
    specular = std::max(luminance(glm::mix(f0, glm::vec3(1.0f), FV) * specScale_), 0.02f);
    if (d.params1.z > 0.0f) coat = std::max(0.25f * d.params1.z * glm::mix(0.04f, 1.0f, FV), 0.02f);
}

glm::vec3 PathBsdf::evalCos(const glm::vec3& wi) const {
    if (!hasSmooth()) return glm::vec3(0.0f);
    if (disney_) return evalCosDisney(wi);
    if (layers_) return evalCosLayered(wi);
    return shading::shadeLightScaled(N_, wi, V_, glm::vec3(1.0f), md_, ms_, s_, model_, diffuseOn_, specularOn_,
                                     specScale_) *
           (1.0f / kPi);
}

glm::vec3 PathBsdf::evalCosDisney(const glm::vec3& wi) const {
    const DisneyLobes& d = *disney_;
    return shading::shadeLightDisney(N_, wi, V_, glm::vec3(1.0f), d.baseColor, d.metallic, s_, d.params0, d.params1,
                                     diffuseOn_, specularOn_, specScale_) *
           (1.0f / kPi);
}

// pbr with glTF's layers, as the Whitted tracer shades a light (shadeLightPbrLayers).
glm::vec3 PathBsdf::evalCosLayered(const glm::vec3& wi) const {
    const shading::LightSample light{wi, glm::vec3(1.0f)};
    return shading::shadeLightPbrLayers(N_, light, V_, *layers_, diffuseOn_, specularOn_) * (1.0f / kPi);
}

// The half vector of wi and V and V·H, for the densities of lobes sampled by their micro-normals (the reflection's
// Jacobian is 1 / (4 V·H)); false where there is none (wi = −V) or V·H <= 0.
bool PathBsdf::halfVector(const glm::vec3& wi, glm::vec3& H, float& VoH) const {
    const glm::vec3 h = wi + V_;
    const float len = glm::length(h);
    if (!(len > 0.0f)) return false;
    H = h / len;
    VoH = glm::dot(V_, H);
    return VoH > 0.0f;
}

float PathBsdf::specularPdf(const glm::vec3& wi) const {
    if (model_ == shading::SL_MODEL_PHONG) return powerCosinePdf(glm::dot(wi, reflectAbout(V_, N_)), s_);
    glm::vec3 H;
    float VoH;
    if (!halfVector(wi, H, VoH)) return 0.0f;
    if (model_ == shading::SL_MODEL_BLINN_PHONG) return powerCosinePdf(glm::dot(N_, H), s_) / (4.0f * VoH);
    if (stretched_)  // disney's lobe, or pbr's under glTF's anisotropy
        return ggxAnisoVisibleNormalPdf(toTangentFrame(V_), toTangentFrame(H), stretched_->ax, stretched_->ay) /
               (4.0f * VoH);
    return ggxVisibleNormalPdf(frame_.toLocal(V_), frame_.toLocal(H), alpha_) / (4.0f * VoH);
}

// The clearcoat's density over the reflection's Jacobian 1 / (4 V·H): GTR1's normal density (disney), or the GGX
// visible-normal density around the coat's normal (pbr's clear coat).
float PathBsdf::coatPdf(const glm::vec3& wi) const {
    glm::vec3 H;
    float VoH;
    if (!halfVector(wi, H, VoH)) return 0.0f;
    if (clearcoat_) {
        const Frame& f = clearcoat_->frame;
        return ggxVisibleNormalPdf(f.toLocal(V_), f.toLocal(H), clearcoat_->alpha) / (4.0f * VoH);
    }
    return gtr1NormalPdf(glm::dot(N_, H), disney_->coatAlpha) / (4.0f * VoH);
}

glm::vec3 PathBsdf::sampleCoat(glm::vec2 u) const {
    if (!clearcoat_) return reflectAbout(V_, frame_.toWorld(sampleGtr1Normal(u, disney_->coatAlpha)));
    const Frame& f = clearcoat_->frame;
    const glm::vec3 v = f.toLocal(V_);
    if (v.z <= 0.0f) return glm::vec3(0.0f);
    return reflectAbout(V_, f.toWorld(sampleGgxVisibleNormal(v, clearcoat_->alpha, u)));
}

float PathBsdf::pdf(const glm::vec3& wi) const {
    // Below the surface only the thin wall's transmitted lobe reaches.
    if (pThin_ > 0.0f && glm::dot(N_, wi) < 0.0f) return pThin_ * thinPdf(wi);
    float p = 0.0f;
    if (pDiffuse_ > 0.0f) p += pDiffuse_ * cosineHemispherePdf(glm::dot(N_, wi));
    if (pSpecular_ > 0.0f) p += pSpecular_ * specularPdf(wi);
    if (pCoat_ > 0.0f) p += pCoat_ * coatPdf(wi);
    if (pSheen_ > 0.0f) p += pSheen_ * sheenPdf(wi);
    return p;
}

// glTF's sheen: the Charlie distribution's density D·N·H over the reflection's Jacobian 1 / (4 V·H).
float PathBsdf::sheenPdf(const glm::vec3& wi) const {
    glm::vec3 H;
    float VoH;
    if (!halfVector(wi, H, VoH)) return 0.0f;
    const float NoH = glm::dot(N_, H);
    if (!(NoH > 0.0f)) return 0.0f;
    return shading::D_Charlie(NoH, sheenAlpha_) * NoH / (4.0f * VoH);
}

// The thin wall's transmitted lobe: the GGX reflection's visible-normal density at the lobe's α of wi mirrored back
// above the surface (the mirror keeps solid angle).
float PathBsdf::thinPdf(const glm::vec3& wi) const {
    glm::vec3 H;
    float VoH;
    if (!halfVector(wi - 2.0f * glm::dot(wi, N_) * N_, H, VoH)) return 0.0f;
    return ggxVisibleNormalPdf(frame_.toLocal(V_), frame_.toLocal(H), through_->alpha) / (4.0f * VoH);
}

// Light through a volume's surface, in or out: V refracted about a micro-normal drawn from the transmitted lobe's
// visible normals, weighted by Smith's G1 of the way on (Heitz 2018's estimator) and, going in, by what the
// dielectric's Fresnel leaves (1 − max3(Fd), as the diffuse lobe). Leaving past the critical angle the light is
// reflected back inside.
std::optional<BsdfSample> PathBsdf::sampleThrough(glm::vec2 u) const {
    const Through& t = *through_;
    const glm::vec3 v = frame_.toLocal(V_);
    if (!(v.z > 0.0f)) return std::nullopt;
    const glm::vec3 m = frame_.toWorld(sampleGgxVisibleNormal(v, t.alpha, u));
    BsdfSample out;
    out.delta = true;
    const glm::vec3 refracted = glm::refract(-V_, m, t.eta);
    if (!(glm::dot(refracted, refracted) > 0.0f)) {
        if (!t.leaving) return std::nullopt;
        out.wi = glm::normalize(reflectAbout(V_, m));
        const float cosOut = glm::dot(out.wi, N_);
        if (!(cosOut > 0.0f) || !(glm::dot(out.wi, Nf_) > 0.0f)) return std::nullopt;
        out.weight = glm::vec3(ggxG1(cosOut, t.alpha) / pVolume_);
        return out;
    }
    out.wi = glm::normalize(refracted);
    const float cosOut = -glm::dot(out.wi, N_);
    if (!(cosOut > 0.0f) || !(glm::dot(out.wi, Nf_) < 0.0f)) return std::nullopt;
    float keep = 1.0f;
    if (!t.leaving && specularOn_) {
        const glm::vec3 Fd = t.layer.w * shading::F_Schlick(glm::vec3(t.layer), std::max(glm::dot(V_, m), 0.0f));
        keep = 1.0f - std::max(Fd.x, std::max(Fd.y, Fd.z));
    }
    out.weight = t.color * (keep * ggxG1(cosOut, t.alpha) / pVolume_);
    out.transmitted = true;
    return out;
}

glm::vec3 PathBsdf::sampleSpecular(glm::vec2 u) const {
    if (model_ == shading::SL_MODEL_PHONG) return Frame(reflectAbout(V_, N_)).toWorld(samplePowerCosine(u, s_));
    if (model_ == shading::SL_MODEL_BLINN_PHONG) return reflectAbout(V_, frame_.toWorld(samplePowerCosine(u, s_)));
    if (stretched_) {
        const glm::vec3 v = toTangentFrame(V_);
        if (v.z <= 0.0f) return glm::vec3(0.0f);
        const glm::vec3 h = sampleGgxAnisoVisibleNormal(v, stretched_->ax, stretched_->ay, u);
        return reflectAbout(V_, h.x * stretched_->tangentX + h.y * stretched_->tangentY + h.z * N_);
    }
    const glm::vec3 v = frame_.toLocal(V_);
    if (v.z <= 0.0f) return glm::vec3(0.0f);
    return reflectAbout(V_, frame_.toWorld(sampleGgxVisibleNormal(v, alpha_, u)));
}

std::optional<BsdfSample> PathBsdf::sample(const glm::vec3& u) const {
    float pick = u.x;
    const glm::vec2 uv(u.y, u.z);
    BsdfSample out;
    if (pick < pMirror_) {
        out.wi = glm::normalize(reflectAbout(V_, N_));
        out.weight = kr_ / pMirror_;
        out.delta = true;
        return out;
    }
    pick -= pMirror_;
    if (pick < pGlass_) {
        out.wi = refracted_;
        out.weight = kt_ / pGlass_;
        out.delta = true;
        out.transmitted = true;
        return out;
    }
    pick -= pGlass_;
    if (pick < pVolume_) return sampleThrough(uv);
    pick -= pVolume_;
    if (!hasSmooth()) return std::nullopt;
    bool below = false;
    if (pick < pDiffuse_) {
        out.wi = frame_.toWorld(sampleCosineHemisphere(uv));
    } else if (pick < pDiffuse_ + pSpecular_) {
        out.wi = sampleSpecular(uv);
    } else if (pick < pDiffuse_ + pSpecular_ + pSheen_) {
        out.wi = reflectAbout(V_, frame_.toWorld(shading::importanceSampleCharlie(uv.x, uv.y, sheenAlpha_)));
    } else if (pick < pDiffuse_ + pSpecular_ + pSheen_ + pThin_) {
        // The thin wall's lobe: a GGX reflection at its α mirrored through the surface.
        const glm::vec3 v = frame_.toLocal(V_);
        if (!(v.z > 0.0f)) return std::nullopt;
        const glm::vec3 r = reflectAbout(V_, frame_.toWorld(sampleGgxVisibleNormal(v, through_->alpha, uv)));
        out.wi = r - 2.0f * glm::dot(r, N_) * N_;
        below = true;
    } else {
        out.wi = sampleCoat(uv);
    }
    // Directions on the wrong side of the shading or the geometric surface carry nothing back (f is 0 there, or
    // the ray would start inside the object): above for reflections, below for the thin wall's transmission.
    if (below) {
        if (!(glm::dot(out.wi, N_) < 0.0f) || !(glm::dot(out.wi, Nf_) < 0.0f)) return std::nullopt;
        out.transmitted = true;
    } else if (!(glm::dot(out.wi, N_) > 0.0f) || !(glm::dot(out.wi, Nf_) > 0.0f)) {
        return std::nullopt;
    }
    out.pdf = pdf(out.wi);
    if (!(out.pdf > 0.0f)) return std::nullopt;
    out.weight = evalCos(out.wi) / out.pdf;
    return out;
}

}  // namespace shadelab::trace
