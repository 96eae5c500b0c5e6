// glTF's material layers on the pbr model (docs/lighting.md, "glTF's specular and ior", "glTF's clear coat layer"),
// in the subset of GLSL that is also C++ with GLM, by the rules of lighting.glsl, which includes this file after
// the microfacet functions it builds on (F_Schlick, specularGGX, specularDFG).

// glTF's KHR_materials_specular with KHR_materials_ior (docs/lighting.md, "glTF's specular and ior"): the dielectric
// and metal parts mixed by metallic as in glTF 2.0 Appendix B's mix(dielectric_brdf, metal_brdf, metallic). The
// dielectric's Fresnel Fd = w·F_Schlick(f0d, V·H), f0d the index's F0 tinted by the specular colour and w the
// specular factor, over its diffuse, which keeps 1 − max3(Fd) (the extension's fresnel_mix); the metal's Fresnel
// F_Schlick(baseColor, V·H). layer = (f0d, w) (SpecularLayer::packed), md the diffuse colour baseColor·(1 −
// metallic), specScale as shadeLightScaled's. N, L, V need not be unit.
SL_FN vec3 shadeLightPbrSpecular(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 md, vec3 baseColor, float metallic,
                                 float roughness, vec4 layer, bool diffuseOn, bool specularOn, vec3 specScale) {
    N = normalize(N);
    L = normalize(L);
    V = normalize(V);
    float NoL = dot(N, L);
    vec3 I = vec3(0.0f);
    if (diffuseOn) I = md * max(NoL, 0.0f);
    if (specularOn && NoL > 0.0f) {
        float VoH = max(dot(V, normalize(L + V)), 0.0f);
        vec3 Fd = layer.w * F_Schlick(vec3(layer.x, layer.y, layer.z), VoH);
        vec3 F = mix(Fd, F_Schlick(baseColor, VoH), metallic);
        vec3 DV = specularGGX(N, L, V, vec3(1.0f), roughness);  // F_Schlick(1, ·) is 1: D·V alone
        I = I * (1.0f - max(Fd.x, max(Fd.y, Fd.z))) + (SL_PI * NoL) * DV * F * specScale;
    }
    return Il * I;
}

// The same material's F0 for the split sum and the energy compensation: mix(w·f0d, baseColor, metallic).
SL_FN vec3 pbrSpecularF0(vec3 baseColor, float metallic, vec4 layer) {
    return mix(layer.w * vec3(layer.x, layer.y, layer.z), baseColor, metallic);
}

// Its environment light (split sum, as shadeEnvironment): the dielectric's E_d = w·(f0d·A + B) and the metal's
// baseColor·A + B mixed by metallic and times `compensation` (energyCompensation of pbrSpecularF0, or 1), the
// diffuse keeping 1 − max3(E_d).
SL_FN vec3 shadeEnvironmentPbrSpecular(vec3 diffuseColor, vec3 baseColor, float metallic, vec4 layer,
                                       vec3 irradiance, vec3 prefiltered, vec2 dfg, vec3 compensation,
                                       bool diffuseOn, bool specularOn) {
    vec3 I = diffuseOn ? diffuseColor * irradiance : vec3(0.0f);
    if (specularOn) {
        vec3 Ed = layer.w * specularDFG(vec3(layer.x, layer.y, layer.z), dfg);
        vec3 E = mix(Ed, specularDFG(baseColor, dfg), metallic) * compensation;
        I = I * (1.0f - max(Ed.x, max(Ed.y, Ed.z))) + prefiltered * E;
    }
    return I;
}

// glTF's KHR_materials_clearcoat (its "Layering" section, as the Khronos Sample Viewer evaluates it): a clear
// dielectric coat (F0 = 0.04, index 1.5) over the base, coat = (factor, roughness). The coat takes
// factor·Fc(Nc·V) of the base's light, Fc Schlick's Fresnel at the coat normal Nc, and adds its own GGX lobe
// times factor. Nc is the geometry's normal, or the coat's own normal map's: the base's normal map leaves it.
SL_FN float clearcoatWeight(vec3 Nc, vec3 V, float factor) {
    float NoV = clamp(dot(normalize(Nc), normalize(V)), 0.0f, 1.0f);
    return factor * F_Schlick(vec3(0.04f), NoV).x;
}

// One light's term `base` (the base material's, before visibility) under the coat: base·(1 − factor·Fc) +
// factor·π·f_coat·Il·Nc·L. The coat is a specular layer: with the specular term off, or factor 0, the base is
// returned as it is. N, L, V need not be unit.
SL_FN vec3 clearcoatLight(vec3 base, vec3 Nc, vec3 L, vec3 V, vec3 Il, vec2 coat, bool specularOn) {
    if (!specularOn || coat.x <= 0.0f) return base;
    Nc = normalize(Nc);
    L = normalize(L);
    V = normalize(V);
    float NoL = dot(Nc, L);
    vec3 layer = NoL > 0.0f ? (SL_PI * NoL) * specularGGX(Nc, L, V, vec3(0.04f), coat.y) : vec3(0.0f);
    return base * (1.0f - clearcoatWeight(Nc, V, coat.x)) + coat.x * Il * layer;
}

// The environment's light `base` under the coat (split sum, as shadeEnvironment): base·(1 − factor·Fc) +
// factor·prefiltered·(0.04·A + B), prefiltered and dfg = (A, B) looked up for the coat's normal and roughness.
SL_FN vec3 clearcoatEnvironment(vec3 base, vec3 Nc, vec3 V, vec3 prefiltered, vec2 dfg, vec2 coat, bool specularOn) {
    if (!specularOn || coat.x <= 0.0f) return base;
    return base * (1.0f - clearcoatWeight(Nc, V, coat.x)) + coat.x * prefiltered * specularDFG(vec3(0.04f), dfg);
}
