// What glTF's metallic-roughness, normal and occlusion maps do to a surface (design.md §9), written once in
// the GLSL subset that is also C++ with GLM (the rules of lighting.glsl; src/shading/material_maps.h is the
// C++ view). Sampling is texture_sample.glsl's; this file maps sampled linear texels to shading inputs.
// Needs lighting.glsl's model constants, pbrDiffuseColor, pbrF0 and the lobe normalisations.

// Walter et al. 2007, eq. 33, as scene/material.h's shininessFromRoughness: s = 2/α² − 2, α = roughness².
SL_FN float mapShininess(float roughness) {
    float alpha = roughness * roughness;
    float alpha2 = max(alpha * alpha, 1e-12f);
    return clamp(2.0f / alpha2 - 2.0f, 1.0f, 10000.0f);
}

// glTF 2.0 §3.9.2: blue is metalness and green roughness, each multiplying its factor.
SL_FN float mapMetallic(float metallic, vec4 texel) {
    return metallic * texel.b;
}
SL_FN float mapRoughness(float roughness, vec4 texel) {
    return roughness * texel.g;
}

// The texel's coefficients, re-derived by glTF 2.0 Appendix B as gltf_materials.cpp maps a material: the
// diffuse colour baseColor·(1 − metallic) (md, and ma under every model), F0 = mix(0.04, baseColor, metallic)
// (pbr's F0, Phong's ms, normalised when asked) and the exponent (pbr, disney: roughness; Phong: mapShininess).
SL_FN vec3 mapDiffuse(vec3 baseColor, float metallic) {
    return pbrDiffuseColor(baseColor, metallic);
}
SL_FN float mapExponent(int model, float roughness) {
    return physicallyBased(model) ? roughness : mapShininess(roughness);
}
SL_FN vec3 mapSpecular(int model, bool normalized, vec3 baseColor, float metallic, float exponent) {
    vec3 f0 = pbrF0(baseColor, metallic);
    if (physicallyBased(model) || !normalized) return f0;
    return f0 * (model == SL_MODEL_PHONG ? phongNormalization(exponent) : blinnPhongNormalization(exponent));
}

// glTF 2.0 §3.9.3: occlusion 1 + strength·(R − 1); it scales indirect light (ambient, environment) only.
SL_FN float mapOcclusion(float strength, vec4 texel) {
    return 1.0f + strength * (texel.r - 1.0f);
}

// glTF 2.0 §3.9.3 normal textures: n = normalize((2·texel − 1) ⊙ (scale, scale, 1)) in the frame
// (T, B = w·(N × T), N), T Gram-Schmidt orthogonalised against the unit interpolated normal. n_ is the
// interpolated vertex normal (any length), tangent the interpolated TANGENT (w's sign is the handedness).
// Returns a unit normal on n_'s side of the frame; a degenerate frame or texel gives normalize(n_).
SL_FN vec3 mapNormal(vec3 n_, vec4 tangent, vec4 texel, float scale) {
    vec3 N = normalize(n_);
    vec3 t = vec3(tangent.x, tangent.y, tangent.z);
    vec3 T = t - N * dot(N, t);
    float tt = dot(T, T);
    if (!(tt > 1e-20f)) return N;
    T = T / sqrt(tt);
    vec3 B = cross(N, T) * (tangent.w < 0.0f ? -1.0f : 1.0f);
    vec3 m = vec3((2.0f * texel.r - 1.0f) * scale, (2.0f * texel.g - 1.0f) * scale, 2.0f * texel.b - 1.0f);
    vec3 P = T * m.x + B * m.y + N * m.z;
    float pp = dot(P, P);
    return pp > 1e-20f ? P / sqrt(pp) : N;
}
