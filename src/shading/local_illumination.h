// Local illumination summed over lights (design.md §1): I = Ia⊙ma + Σ vis·Il⊙(md·max(N·L,0) + ms·spec).
// The per-light maths is shaders/lighting.glsl; this is the C++ loop, mirrored by the loop in
// shaders/surface.glsl. No scene types: callers hand in light samples already evaluated at the point.
#pragma once

#include "shading/lighting.h"
#include "shading/sheen_lut.h"

#include <cstddef>

namespace shadelab::shading {

struct LightSample {
    vec3 L;                   // from the point toward the light, any length > 0
    vec3 Il;                  // intensity arriving at the point (attenuation applied), linear RGB
    float visibility = 1.0f;  // 0 when shadowed
};

struct SurfaceParams {
    vec3 ma, md, ms;
    float s;
    vec3 specScale{1.0f};  // pbr specular lobe scale: energyCompensation() when the scene asks for it
    // disney only (shadeLightDisney): the base colour, metallic and the packed parameters (DisneyParams::lobes0/1);
    // md, ms and s then hold the diffuse colour, the specular F0 and the roughness for the environment's light.
    vec3 baseColor{0.0f};
    float metallic = 0.0f;
    vec4 disney0{0.0f}, disney1{0.0f};
    // pbr only: the clear coat (Clearcoat::packed, textures applied; factor 0: none) and its normal, the
    // geometry's or the coat's normal map's (clearcoatLight).
    vec2 coat{0.0f};
    vec3 coatN{0.0f};
    // pbr only: glTF's specular layer and index (SpecularLayer::packed) and its anisotropy, shaded by
    // shadeLightPbrSpecular with baseColor and metallic above when `layered`; ms then holds pbrSpecularF0.
    bool layered = false;
    vec4 specLayer{0.0f};
    vec4 aniso{0.0f};  // glTF's anisotropy here, (T, strength) (anisotropyDirection); strength 0: isotropic
    // pbr only: glTF's sheen (Sheen::packed) when `sheenTable` (its albedo table, sheen_lut.h) is set, and its
    // albedo at the view direction, read once per surface point.
    vec4 sheen{0.0f};
    float sheenEV = 0.0f;
    const SheenLut* sheenTable = nullptr;
    // pbr only: glTF's transmission and volume (transmissionPacked; factor 0: none), the transmitted colour md·t
    // (md above then holds md·(1 − t)) and the volume's tint over its thickness (transmissionLight).
    vec4 transmission{0.0f};
    vec3 transmitColor{0.0f};
    vec3 transmitTint{1.0f};
};

// Whether a pbr surface's coefficients carry any of glTF's layers (shadeLightPbrLayers shades them).
inline bool hasPbrLayers(const SurfaceParams& m) { return m.layered || m.coat.x > 0.0f || m.sheenTable; }

// One light's term of a pbr surface with glTF's layers (`m.layered`, `m.sheenTable`, `m.coat`), before visibility:
// the base (the specular layer's mix, or pbr's own, with the light through it when it transmits), under the sheen,
// under the coat (the spec's order).
inline vec3 shadeLightPbrLayers(vec3 N, const LightSample& l, vec3 V, const SurfaceParams& m, bool diffuseOn,
                                bool specularOn) {
    vec3 base = m.layered ? shadeLightPbrSpecular(N, l.L, V, l.Il, m.md, m.baseColor, m.metallic, m.s, m.specLayer,
                                                  m.aniso, diffuseOn, specularOn, m.specScale)
                          : shadeLightScaled(N, l.L, V, l.Il, m.md, m.ms, m.s, SL_MODEL_PBR, diffuseOn, specularOn,
                                             m.specScale);
    if (m.transmission.x > 0.0f)  // a light behind the surface, through it (part of the base, under the layers)
        base += transmissionLight(N, l.L, V, l.Il, m.transmitColor, m.transmitTint, m.specLayer, m.s * m.transmission.y,
                                  diffuseOn, specularOn);
    if (m.sheenTable) {
        SheenLookup sheen{m.sheenTable};
        const float EL = sheen.at(sheen.sheenCos(N, l.L), m.sheen.w);
        base = sheenLight(base, N, l.L, V, l.Il, m.sheen, m.sheenEV, EL, diffuseOn);
    }
    return m.coat.x > 0.0f ? clearcoatLight(base, m.coatN, l.L, V, l.Il, m.coat, specularOn) : base;
}

// The coefficients shadeLight reads under `model`: the lecture's (ma, md, ms, s), or for SL_MODEL_PBR the
// ambient ma, the diffuse colour, F0 and the roughness derived from the metallic-roughness fields; for
// SL_MODEL_DISNEY the same with disney's F0 (disneySpecularF0) and its own fields. `normalized` (design.md §7)
// scales a Phong or Blinn-Phong lobe by its energy-conserving factor.
inline SurfaceParams surfaceParams(int model, vec3 ma, vec3 md, vec3 ms, float s, vec3 baseColor, float metallic,
                                   float roughness, bool normalized = false, vec4 disney0 = vec4(0.0f),
                                   vec4 disney1 = vec4(0.0f)) {
    if (model == SL_MODEL_PHONG) return {ma, md, normalized ? ms * phongNormalization(s) : ms, s};
    if (model == SL_MODEL_BLINN_PHONG) return {ma, md, normalized ? ms * blinnPhongNormalization(s) : ms, s};
    if (model == SL_MODEL_DISNEY)
        return {ma,
                pbrDiffuseColor(baseColor, metallic),
                disneySpecularF0(baseColor, metallic, disney0.y, disney0.z),
                roughness,
                vec3(1.0f),
                baseColor,
                metallic,
                disney0,
                disney1};
    return {ma, pbrDiffuseColor(baseColor, metallic), pbrF0(baseColor, metallic), roughness};
}

struct TermFlags {
    bool ambient = true, diffuse = true, specular = true;
};

inline vec3 shadeLocal(vec3 N, vec3 V, const LightSample* lights, size_t lightCount, const SurfaceParams& m, vec3 Ia,
                       int model, TermFlags t) {
    vec3 I = shadeAmbient(Ia, m.ma, t.ambient);
    // The model is decided once, outside the loop (shadeLightModel per light would ask per light).
    if (model == SL_MODEL_DISNEY) {
        for (size_t i = 0; i < lightCount; ++i) {
            const LightSample& l = lights[i];
            if (l.visibility <= 0.0f) continue;
            I += l.visibility * shadeLightDisney(N, l.L, V, l.Il, m.baseColor, m.metallic, m.s, m.disney0, m.disney1,
                                                 t.diffuse, t.specular, m.specScale);
        }
        return I;
    }
    if (model == SL_MODEL_PBR && hasPbrLayers(m)) {  // pbr with glTF's layers
        for (size_t i = 0; i < lightCount; ++i) {
            const LightSample& l = lights[i];
            if (l.visibility <= 0.0f) continue;
            I += l.visibility * shadeLightPbrLayers(N, l, V, m, t.diffuse, t.specular);
        }
        return I;
    }
    for (size_t i = 0; i < lightCount; ++i) {
        const LightSample& l = lights[i];
        if (l.visibility <= 0.0f) continue;
        I += l.visibility *
             shadeLightScaled(N, l.L, V, l.Il, m.md, m.ms, m.s, model, t.diffuse, t.specular, m.specScale);
    }
    return I;
}

}  // namespace shadelab::shading
