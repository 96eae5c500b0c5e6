// Local illumination summed over lights (design.md §1): I = Ia⊙ma + Σ vis·Il⊙(md·max(N·L,0) + ms·spec).
// The per-light maths is shaders/lighting.glsl; this is the C++ loop, mirrored by the loop in
// shaders/surface.glsl. No scene types: callers hand in light samples already evaluated at the point.
#pragma once

#include "shading/lighting.h"

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
};

// The coefficients shadeLight reads under `model`: the lecture's (ma, md, ms, s), or for SL_MODEL_PBR the
// ambient ma, the diffuse colour, F0 and the roughness derived from the metallic-roughness fields.
// `normalized` (design.md §7) scales a Phong or Blinn-Phong lobe by its energy-conserving factor.
inline SurfaceParams surfaceParams(int model, vec3 ma, vec3 md, vec3 ms, float s, vec3 baseColor, float metallic,
                                   float roughness, bool normalized = false) {
    if (model == SL_MODEL_PHONG) return {ma, md, normalized ? ms * phongNormalization(s) : ms, s};
    if (model == SL_MODEL_BLINN_PHONG) return {ma, md, normalized ? ms * blinnPhongNormalization(s) : ms, s};
    return {ma, pbrDiffuseColor(baseColor, metallic), pbrF0(baseColor, metallic), roughness};
}

struct TermFlags {
    bool ambient = true, diffuse = true, specular = true;
};

inline vec3 shadeLocal(vec3 N, vec3 V, const LightSample* lights, size_t lightCount, const SurfaceParams& m, vec3 Ia,
                       int model, TermFlags t) {
    vec3 I = shadeAmbient(Ia, m.ma, t.ambient);
    for (size_t i = 0; i < lightCount; ++i) {
        const LightSample& l = lights[i];
        if (l.visibility <= 0.0f) continue;
        I += l.visibility *
             shadeLightScaled(N, l.L, V, l.Il, m.md, m.ms, m.s, model, t.diffuse, t.specular, m.specScale);
    }
    return I;
}

}  // namespace shadelab::shading
