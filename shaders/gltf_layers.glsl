// glTF's material layers on the pbr model (docs/lighting.md, "glTF's specular and ior", "glTF's clear coat layer"),
// in the subset of GLSL that is also C++ with GLM, by the rules of lighting.glsl, which includes this file after
// the microfacet functions it builds on (F_Schlick, specularGGX, specularDFG, D_GTR2Aniso, anisotropyTangent).

// glTF's KHR_materials_anisotropy (docs/lighting.md, "glTF's anisotropy"): GGX stretched along a direction T in the
// tangent plane, αt = mix(α, 1, s²) along T and αb = α across it, s the strength. Packed per material as
// (s, cos r, sin r) (Anisotropy::packed), r the direction's turn from the tangent X toward the bitangent Y; per point
// as (T, s), T from anisotropyDirection.

// T = X·cos r + Y·sin r: X the mesh's tangent (xyz, w the bitangent's sign) made orthogonal to N, Y = w·(N × X); where
// there is none (a zero tangent: spheres, planes, meshes without texture coordinates), X = anisotropyTangent(N) and
// Y = N × X. N need not be unit.
SL_FN vec3 anisotropyDirection(vec3 N, vec4 tangent, vec3 aniso) {
    vec3 n = normalize(N);
    vec3 t = vec3(tangent.x, tangent.y, tangent.z);
    vec3 inPlane = t - dot(n, t) * n;
    vec3 X = anisotropyTangent(n);
    float handed = 1.0f;
    if (dot(inPlane, inPlane) > 1e-12f) {
        X = normalize(inPlane);
        handed = tangent.w < 0.0f ? -1.0f : 1.0f;
    }
    return aniso.y * X + (aniso.z * handed) * cross(n, X);
}

// D·V of the stretched lobe (F = 1): D_GTR2Aniso at (αt, αb) and the height-correlated anisotropic Smith visibility
// V = 0.5 / (N·L·|(αt T·V, αb B·V, N·V)| + N·V·|(αt T·L, αb B·L, N·L)|), B = N × T (Heitz 2014; the extension's).
// α = pbrAlpha(roughness). N, L, V, T unit, N·L > 0; N·V kept above 1e-4 as specularGGX does.
SL_FN float anisotropicGGX(vec3 N, vec3 L, vec3 V, vec3 T, float roughness, float strength) {
    float a = pbrAlpha(roughness);
    float at = mix(a, 1.0f, strength * strength);
    vec3 B = cross(N, T);
    vec3 H = normalize(L + V);
    float NoL = dot(N, L);
    float NoV = max(dot(N, V), 1e-4f);
    float D = D_GTR2Aniso(dot(N, H), dot(H, T), dot(H, B), at, a);
    float lv = length(vec3(at * dot(T, V), a * dot(B, V), NoV));
    float ll = length(vec3(at * dot(T, L), a * dot(B, L), NoL));
    return D * 0.5f / (NoL * lv + NoV * ll);
}

// The normal the environment's reflection is looked up about under anisotropy (Filament's bent normal, as the
// Khronos Sample Viewer uses it): N bent toward the normal facing V across T, the more the stronger and smoother,
// bend = (1 − s·(1 − roughness))⁴ of N kept; aniso = (T, s). N, V need not be unit.
SL_FN vec3 anisotropicBentNormal(vec3 N, vec3 V, vec4 aniso, float roughness) {
    vec3 n = normalize(N);
    vec3 v = normalize(V);
    vec3 T = vec3(aniso.x, aniso.y, aniso.z);
    vec3 across = cross(cross(T, v), T);
    float bend = 1.0f - aniso.w * (1.0f - roughness);
    float keep = bend * bend * bend * bend;
    return normalize(mix(across, n, keep));
}

// glTF's KHR_materials_specular with KHR_materials_ior (docs/lighting.md, "glTF's specular and ior"): the dielectric
// and metal parts mixed by metallic as in glTF 2.0 Appendix B's mix(dielectric_brdf, metal_brdf, metallic). The
// dielectric's Fresnel Fd = w·F_Schlick(f0d, V·H), f0d the index's F0 tinted by the specular colour and w the
// specular factor, over its diffuse, which keeps 1 − max3(Fd) (the extension's fresnel_mix); the metal's Fresnel
// F_Schlick(baseColor, V·H). layer = (f0d, w) (SpecularLayer::packed), md the diffuse colour baseColor·(1 −
// metallic), specScale as shadeLightScaled's; aniso = glTF's anisotropy (T, s) (s = 0: the isotropic lobe).
// N, L, V need not be unit.
SL_FN vec3 shadeLightPbrSpecular(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 md, vec3 baseColor, float metallic,
                                 float roughness, vec4 layer, vec4 aniso, bool diffuseOn, bool specularOn,
                                 vec3 specScale) {
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
        // F_Schlick(1, ·) is 1: D·V alone, isotropic or stretched along T.
        vec3 DV = aniso.w > 0.0f ? vec3(anisotropicGGX(N, L, V, vec3(aniso.x, aniso.y, aniso.z), roughness, aniso.w))
                                 : specularGGX(N, L, V, vec3(1.0f), roughness);
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

// glTF's KHR_materials_sheen (its "Sheen BRDF" and "Albedo scaling" sections): a layer of fibres with colour c
// and roughness r over the base. f_sheen = c·D_Charlie·V_sheen, and the base keeps min(1 − max3(c)·E(N·V),
// 1 − max3(c)·E(N·L)) of its light, E the sheen's directional albedo (c = 1), read from a table computed
// numerically (shading/sheen_lut.h, sheenAlbedo). sheen = (c, r), Sheen::packed.

// The fibres' α = r², r kept at least 0.07 (α 0.0049): below it D_Charlie's power 1/α grows past what a float's
// sin² resolves, and the lobe is already a thin rim light.
SL_FN float sheenAlpha(float roughness) {
    float r = max(roughness, 0.07f);
    return r * r;
}

// Conty & Kulla 2017, "Production Friendly Microfacet Sheen BRDF" (the "Charlie" sheen): fibres' normals
// D = (2 + 1/α) sin^(1/α) θh / (2π), normalised so that ∫ D·cos θh dω = 1.
SL_FN float D_Charlie(float NoH, float a) {
    float invA = 1.0f / a;
    float sin2 = max(1.0f - NoH * NoH, 0.0f);
    return (2.0f + invA) * pow(sin2, 0.5f * invA) / (2.0f * SL_PI);
}

// Estevez & Kulla 2017's fit of the fibres' masking exponent, L(x) = a/(1 + b·x^c) + d·x + e, its five
// coefficients interpolated between their fits at α = 1 and α = 0 by t = (1 − α)².
SL_FN float sheenL(float x, float a) {
    float t = (1.0f - a) * (1.0f - a);
    float A = mix(21.5473f, 25.3245f, t);
    float B = mix(3.82987f, 3.32435f, t);
    float C = mix(0.19823f, 0.16801f, t);
    float D = mix(-1.97760f, -1.27393f, t);
    float E = mix(-4.32054f, -4.85967f, t);
    return A / (1.0f + B * pow(x, C)) + D * x + E;
}

// Their Λ(cos θ): exp(L(cos θ)) below cos θ = 0.5, mirrored above it so that Λ falls smoothly to 0 at the normal.
SL_FN float sheenLambda(float cosTheta, float a) {
    if (cosTheta < 0.5f) return exp(sheenL(cosTheta, a));
    return exp(2.0f * sheenL(0.5f, a) - sheenL(1.0f - cosTheta, a));
}

// π·f_sheen·N·L for c = 1: π·D_Charlie·V_sheen·N·L with the uncorrelated visibility V_sheen = 1 / ((1 + Λ(N·V) +
// Λ(N·L))·4 N·V N·L), N·V kept above 1e-4 as specularGGX does; 0 where N·L <= 0. N, L, V need not be unit.
SL_FN float sheenLobe(vec3 N, vec3 L, vec3 V, float roughness) {
    N = normalize(N);
    L = normalize(L);
    V = normalize(V);
    float NoL = dot(N, L);
    if (NoL <= 0.0f) return 0.0f;
    float NoV = max(dot(N, V), 1e-4f);
    float a = sheenAlpha(roughness);
    float D = D_Charlie(max(dot(N, normalize(L + V)), 0.0f), a);
    return SL_PI * D / (4.0f * NoV * (1.0f + sheenLambda(NoV, a) + sheenLambda(NoL, a)));
}

// What the base keeps under the sheen seen along V and lit along L: min(1 − max3(c)·E_V, 1 − max3(c)·E_L), at
// least 0. E exceeds 1 within a few degrees of grazing at roughness below about 0.3 (Estevez & Kulla's
// visibility is not energy-conserving there: the table holds the lobe's true albedo), and the base is then gone.
SL_FN float sheenScaling(vec4 sheen, float EV, float EL) {
    float c = max(sheen.x, max(sheen.y, sheen.z));
    return max(min(1.0f - c * EV, 1.0f - c * EL), 0.0f);
}

// One light's term `base` (the base material's, before visibility) under the sheen: base·sheenScaling +
// c·Il·sheenLobe. EV and EL are the sheen's albedos at N·V and N·L. Sheen belongs with the diffuse term (as
// disney's own): with it off, or c = 0, the base is returned as it is.
SL_FN vec3 sheenLight(vec3 base, vec3 N, vec3 L, vec3 V, vec3 Il, vec4 sheen, float EV, float EL, bool diffuseOn) {
    if (!diffuseOn || max(sheen.x, max(sheen.y, sheen.z)) <= 0.0f) return base;
    vec3 c = vec3(sheen.x, sheen.y, sheen.z);
    return base * sheenScaling(sheen, EV, EL) + c * Il * sheenLobe(N, L, V, sheen.w);
}

// The environment's light `base` under the sheen (split sum): base·(1 − max3(c)·E_V) + c·prefiltered·E_V, the
// prefiltered environment looked up at the sheen's roughness along the mirror direction (as Filament does: the
// GGX-prefiltered map stands in for a Charlie-prefiltered one; exact in a uniform environment).
SL_FN vec3 sheenEnvironment(vec3 base, vec3 prefiltered, vec4 sheen, float EV, bool diffuseOn) {
    if (!diffuseOn || max(sheen.x, max(sheen.y, sheen.z)) <= 0.0f) return base;
    vec3 c = vec3(sheen.x, sheen.y, sheen.z);
    return base * sheenScaling(sheen, EV, EV) + c * prefiltered * EV;
}

// glTF's KHR_materials_transmission with KHR_materials_volume (docs/lighting.md, "glTF's transmission and volume"):
// the dielectric's diffuse lobe gives up the share t of its light to a GGX lobe through the surface (the spec's
// mix(diffuse_brdf, specular_btdf, t) inside fresnel_mix), its roughness the material's times transmission.y
// (transmissionPacked). tc = md·t is the transmitted colour, md the diffuse colour baseColor·(1 − metallic);
// the rest of md, md·(1 − t), stays diffuse. A thin wall (transmission.z = 0) lets light straight through; a volume
// refracts it by η = transmission.z and absorbs along the way (Volume::transmittance, `tint`).

// The direction light arrives from through the surface at the point seen along −V: −V through a thin wall, V
// refracted into the volume by η (Snell's law; −V where η would reflect it totally). N, V need not be unit.
SL_FN vec3 transmissionDirection(vec3 N, vec3 V, vec4 transmission) {
    vec3 v = normalize(V);
    if (transmission.z <= 0.0f) return -v;
    vec3 T = refract(-v, normalize(N), transmission.z);
    return dot(T, T) > 0.0f ? normalize(T) : -v;
}

// One light's transmitted term for a light behind the surface (N·L < 0): Il·tc·tint·π·|N·L|·D·V(L', V)·(1 −
// max3(Fd(V·H'))), the GGX lobe of the mirrored light L' = L − 2(N·L)N (the thin wall's BTDF, as the Khronos
// Sample Viewer evaluates every punctual light through the surface), Fd the dielectric's Fresnel of the specular
// layer (layer = (f0d, w), SpecularLayer::packed) that the diffuse lobe also gives up. Part of the diffuse term:
// 0 with it off; without the specular term nothing is reflected away. N, L, V need not be unit.
SL_FN vec3 transmissionLight(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 tc, vec3 tint, vec4 layer, float roughness,
                             bool diffuseOn, bool specularOn) {
    N = normalize(N);
    L = normalize(L);
    V = normalize(V);
    float NoL = dot(N, L);
    if (!diffuseOn || NoL >= 0.0f) return vec3(0.0f);
    vec3 Lm = L - (2.0f * NoL) * N;
    float keep = 1.0f;
    if (specularOn) {
        vec3 Fd = layer.w * F_Schlick(vec3(layer.x, layer.y, layer.z), max(dot(V, normalize(Lm + V)), 0.0f));
        keep = 1.0f - max(Fd.x, max(Fd.y, Fd.z));
    }
    return Il * tc * tint * ((-SL_PI * NoL) * keep) * specularGGX(N, Lm, V, vec3(1.0f), roughness);
}

// The environment's (or a traced ray's) light through the surface, `through` the radiance arriving along
// transmissionDirection (times the volume's tint where the caller applies it): tc·through·(1 − max3(E_d)), E_d =
// w·(f0d·A + B) the dielectric's split-sum reflection, as the diffuse lobe keeps in
// shadeEnvironmentPbrSpecular. Part of the diffuse term.
SL_FN vec3 transmissionEnvironment(vec3 tc, vec3 through, vec4 layer, vec2 dfg, bool diffuseOn, bool specularOn) {
    if (!diffuseOn) return vec3(0.0f);
    float keep = 1.0f;
    if (specularOn) {
        vec3 Ed = layer.w * specularDFG(vec3(layer.x, layer.y, layer.z), dfg);
        keep = 1.0f - max(Ed.x, max(Ed.y, Ed.z));
    }
    return tc * through * keep;
}
