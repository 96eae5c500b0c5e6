// The lecture's lighting equations (design.md §1), written once in the subset of GLSL that is also C++
// with GLM. shaders/*.frag include this file; src/shading/lighting.h compiles the same text as C++.
// Rules for this file: float literals carry an f suffix, no swizzles, no out-parameters, SL_FN on functions.

const int SL_MODEL_PHONG = 0;
const int SL_MODEL_BLINN_PHONG = 1;
const int SL_MODEL_PBR = 2;  // glTF 2.0 metallic-roughness (design.md §7): md = diffuse colour, ms = F0, s = roughness
const int SL_MODEL_DISNEY = 3;  // Burley 2012's principled BRDF: pbr's fields plus eight more (shadeLightDisney)

const float SL_PI = 3.14159265358979f;
const float SL_MIN_ALPHA = 0.002025f;  // Filament's MIN_ROUGHNESS: α = 0.045², keeps D_GGX finite in fp32

// x^s with x^0 = 1 for every x (design.md §1): GLSL leaves pow(0, 0) undefined, so s = 0 never reaches pow.
SL_FN float shininessPow(float x, float s) {
    if (s <= 0.0f) return 1.0f;
    if (x <= 0.0f) return 0.0f;
    return pow(x, s);
}

// Phong 1975: mirror of L about N, R = 2N(N·L) − L.
SL_FN vec3 reflectLight(vec3 N, vec3 L) {
    return 2.0f * dot(N, L) * N - L;
}

// Phong 1975 specular factor max(R·V, 0)^s, zero on the unlit side (N·L <= 0).
SL_FN float specularPhong(vec3 N, vec3 L, vec3 V, float s) {
    if (dot(N, L) <= 0.0f) return 0.0f;
    vec3 R = reflectLight(N, L);
    return shininessPow(max(dot(R, V), 0.0f), s);
}

// Energy-conserving Phong lobe (Lewis 1994, "Making Shaders More Physically Plausible"): (s + 2)/2 relative
// to the π-scaled light of design.md §7; `normalized: true` scales ms by it (shading::surfaceParams).
SL_FN float phongNormalization(float s) {
    return (s + 2.0f) / 2.0f;
}

// Energy-conserving Blinn-Phong lobe (Akenine-Möller et al., Real-Time Rendering, 3rd ed., §7.6): (s + 8)/8.
SL_FN float blinnPhongNormalization(float s) {
    return (s + 8.0f) / 8.0f;
}

// Blinn 1977, half-way vector: max(N·H, 0)^s with H = normalize(L + V), zero on the unlit side.
SL_FN float specularBlinnPhong(vec3 N, vec3 L, vec3 V, float s) {
    if (dot(N, L) <= 0.0f) return 0.0f;
    vec3 H = normalize(L + V);
    return shininessPow(max(dot(N, H), 0.0f), s);
}

// Trowbridge & Reitz 1975, Walter et al. 2007 (GGX): normal distribution D(h) with α = roughness²,
// D = α² / (π ((1 − N·H²) + (N·H α)²)²). The caller passes 1 − N·H² as |N × H|² (Filament brdf.fs): near the
// peak of a sharp lobe 1 − N·H² would cancel to a few ulps, and GLSL and C++ would round it apart.
SL_FN float D_GGX(float NoH, float oneMinusNoHSquared, float a) {
    float aNoH = NoH * a;
    float k = a / (oneMinusNoHSquared + aNoH * aNoH);
    return k * k * (1.0f / SL_PI);
}

// Heitz 2014, "Understanding the Masking-Shadowing Function", height-correlated Smith G2 folded with the
// microfacet denominator: V = G2 / (4 N·L N·V) (Filament brdf.fs, glTF 2.0 Appendix B).
SL_FN float V_SmithGGXCorrelated(float NoV, float NoL, float a) {
    float a2 = a * a;
    float GGXV = NoL * sqrt(NoV * NoV * (1.0f - a2) + a2);
    float GGXL = NoV * sqrt(NoL * NoL * (1.0f - a2) + a2);
    return 0.5f / (GGXV + GGXL);
}

// Schlick 1994: F = F0 + (1 − F0)(1 − V·H)^5, the fifth power multiplied out (no pow: GLSL ≡ C++ exactly).
SL_FN vec3 F_Schlick(vec3 f0, float VoH) {
    float x = 1.0f - VoH;
    float x2 = x * x;
    float x5 = x2 * x2 * x;
    return f0 + (vec3(1.0f) - f0) * x5;
}

// The microfacet models (pbr, disney): md is the diffuse colour, ms F0 and s the roughness, the environment
// replaces the constant ambient, and the unlit colour is the base colour.
SL_FN bool physicallyBased(int model) {
    return model == SL_MODEL_PBR || model == SL_MODEL_DISNEY;
}

// Lambert 1760: the diffuse BRDF 1/π. Under the π-scaled light of design.md §7 it contributes exactly md·N·L.
SL_FN float Fd_Lambert() {
    return 1.0f / SL_PI;
}

// glTF 2.0 Appendix B, metallic-roughness: the diffuse colour baseColor·(1 − metallic); metals have none.
SL_FN vec3 pbrDiffuseColor(vec3 baseColor, float metallic) {
    return baseColor * (1.0f - metallic);
}

// glTF 2.0 Appendix B: F0 = mix(0.04, baseColor, metallic); dielectrics reflect 4 % at normal incidence.
SL_FN vec3 pbrF0(vec3 baseColor, float metallic) {
    return mix(vec3(0.04f), baseColor, metallic);
}

// glTF 2.0 Appendix B: α = roughness², clamped so that a mirror-smooth material keeps a finite D.
SL_FN float pbrAlpha(float roughness) {
    return max(roughness * roughness, SL_MIN_ALPHA);
}

// Cook & Torrance 1982 with GGX (glTF 2.0 Appendix B): the specular BRDF D·V·F, unit vectors, N·L > 0.
SL_FN vec3 specularGGX(vec3 N, vec3 L, vec3 V, vec3 f0, float roughness) {
    vec3 H = normalize(L + V);
    float a = pbrAlpha(roughness);
    float NoL = max(dot(N, L), 0.0f);
    float NoV = max(dot(N, V), 1e-4f);
    float NoH = max(dot(N, H), 0.0f);
    float VoH = max(dot(V, H), 0.0f);
    vec3 NxH = cross(N, H);
    return D_GGX(NoH, dot(NxH, NxH), a) * V_SmithGGXCorrelated(NoV, NoL, a) * F_Schlick(f0, VoH);
}

// Karis 2013, "Real Shading in Unreal Engine 4", split sum: the specular environment BRDF integrated over
// the hemisphere is F0·A + B, with dfg = (A, B) read from the DFG table (src/shading/dfg_lut.h).
SL_FN vec3 specularDFG(vec3 f0, vec2 dfg) {
    return f0 * dfg.x + vec3(dfg.y);
}

// Filament, "Energy loss in specular reflectance" (Lagarde & de Rousiers' form, Kulla & Conty 2017): single
// scattering GGX reflects A + B of the light when F = 1; scaling the lobe by 1 + F0·(1/(A + B) − 1) restores
// the energy the single-scattering model loses to multiple bounces between microfacets.
SL_FN vec3 energyCompensation(vec3 f0, vec2 dfg) {
    return vec3(1.0f) + f0 * (1.0f / max(dfg.x + dfg.y, 1e-4f) - 1.0f);
}


// Burley 2012, "Physically Based Shading at Disney", and its published disney.brdf: the principled BRDF.
// Schlick's weight (1 − u)⁵, u clamped to [0, 1], the fifth power multiplied out.
SL_FN float schlickWeight(float u) {
    float m = clamp(1.0f - u, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

// ln(x) for x in (0, 1) from square roots and arithmetic alone, which IEEE 754 rounds the same everywhere: the
// C++ libraries' log (glibc natively, musl in the web page's WebAssembly) may differ in the last bit, and the
// page's reference must equal the native tracer's bit for bit. Eight square roots bring x near 1 (x^(1/256)),
// where ln y = 2 atanh((y − 1)/(y + 1)) converges in four terms: relative error below 1e-6 for x from 1e-6 to
// 0.01 (the clearcoat's α² takes 1e-6 to 0.01), 1e-5 at 0.5; toward 1 the rounding of y − 1 grows.
SL_FN float logUnit(float x) {
    float y = x;
    for (int i = 0; i < 8; ++i) y = sqrt(y);
    float t = (y - 1.0f) / (y + 1.0f);
    float t2 = t * t;
    return 512.0f * t * (1.0f + t2 * (1.0f / 3.0f + t2 * (1.0f / 5.0f + t2 * (1.0f / 7.0f))));
}

// Burley 2012, eq. 4 with γ = 1 (Berry 1923): GTR1, the clearcoat's long-tailed distribution, normalised so that
// ∫ D·cos θh dω = 1: D = (α² − 1) / (π ln(α²) (1 + (α² − 1) cos² θh)); α >= 1 is the uniform 1/π. The
// denominator's 1 + (α² − 1) cos² θh is written α² cos² θh + |N × H|², the caller passing 1 − N·H² as |N × H|²
// (as D_GGX): near a gloss coat's peak 1 − N·H² would cancel, and GLSL and C++ would round it apart.
SL_FN float D_GTR1(float NoH, float oneMinusNoHSquared, float a) {
    if (a >= 1.0f) return 1.0f / SL_PI;
    float a2 = a * a;
    float t = a2 * NoH * NoH + oneMinusNoHSquared;
    return (a2 - 1.0f) / (SL_PI * logUnit(a2) * t);
}

// Burley 2012, eq. 13: anisotropic GTR2 (GGX) with widths ax along the tangent X and ay along Y = N × X,
// D = 1 / (π ax ay ((H·X/ax)² + (H·Y/ay)² + (N·H)²)²), normalised as D_GTR1.
SL_FN float D_GTR2Aniso(float NoH, float HoX, float HoY, float ax, float ay) {
    float x = HoX / ax;
    float y = HoY / ay;
    float d = x * x + y * y + NoH * NoH;
    return 1.0f / (SL_PI * ax * ay * d * d);
}

// disney.brdf's separable Smith masking for GGX of width a, folded with the microfacet denominator:
// G1(v) / (2 N·V) = 1 / (N·V + sqrt(a² + N·V² − a²·N·V²)); the product over L and V is G / (4 N·L N·V).
SL_FN float smithGGXSeparable(float NoV, float a) {
    float a2 = a * a;
    float b = NoV * NoV;
    return 1.0f / (NoV + sqrt(a2 + b - a2 * b));
}

// The same with anisotropic widths (Heitz 2014, eq. 86): 1 / (N·V + sqrt((V·X ax)² + (V·Y ay)² + N·V²)).
SL_FN float smithGGXAniso(float NoV, float VoX, float VoY, float ax, float ay) {
    float x = VoX * ax;
    float y = VoY * ay;
    return 1.0f / (NoV + sqrt(x * x + y * y + NoV * NoV));
}

// The base colour's hue at unit luminance (disney.brdf's Ctint, luminance 0.3 R + 0.6 G + 0.1 B); white for black.
SL_FN vec3 disneyTint(vec3 baseColor) {
    float lum = 0.3f * baseColor.x + 0.6f * baseColor.y + 0.1f * baseColor.z;
    return lum > 0.0f ? baseColor / lum : vec3(1.0f);
}

// The specular colour at normal incidence: 0.08·specular (tinted by specularTint) for a dielectric, the base
// colour for a metal (disney.brdf's Cspec0). specular = 0.5, untinted, is pbr's 0.04.
SL_FN vec3 disneySpecularF0(vec3 baseColor, float metallic, float specular, float specularTint) {
    return mix(specular * 0.08f * mix(vec3(1.0f), disneyTint(baseColor), specularTint), baseColor, metallic);
}

// The width of the anisotropic lobe along X and Y (disney.brdf): aspect √(1 − 0.9·anisotropic), α = roughness²,
// each at least 0.001.
SL_FN vec2 disneyAnisoAlpha(float roughness, float anisotropic) {
    float aspect = sqrt(1.0f - 0.9f * anisotropic);
    float a = roughness * roughness;
    return vec2(max(0.001f, a / aspect), max(0.001f, a * aspect));
}

// The clearcoat's GTR1 width: clearcoatGloss 0 a satin 0.1, 1 a gloss 0.001.
SL_FN float disneyClearcoatAlpha(float clearcoatGloss) {
    return mix(0.1f, 0.001f, clearcoatGloss);
}

// The tangent X along which an anisotropic lobe stretches, from N alone so that every renderer agrees: the way
// around the world's vertical axis (a sphere's parallels, brushed as on a lathe), around x where N is vertical.
SL_FN vec3 anisotropyTangent(vec3 N) {
    vec3 axis = abs(N.y) < 0.999f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
    return normalize(cross(axis, N));
}

// The principled BRDF f(L, V) times π·N·L·Il (design.md §7's π-scaled light), as disney.brdf's BRDF(): the
// diffuse with its retro-reflection mixed toward the subsurface approximation, and the sheen, both scaled by
// (1 − metallic); the anisotropic GGX specular lobe (times specScale, as pbr's); and the clearcoat's GTR1 lobe
// (fixed F0 = 0.04, Smith width 0.25). d0 = (subsurface, specular, specularTint, anisotropic), d1 = (sheen,
// sheenTint, clearcoat, clearcoatGloss). diffuseOn: diffuse, subsurface and sheen; specularOn: specular and
// clearcoat. Unlike disney.brdf, N·V is clamped to 1e-4 (as specularGGX), so interpolated normals facing
// slightly away keep their diffuse light; an isotropic lobe (anisotropic 0) is evaluated as the GGX it equals,
// with no tangent, and a coat of 0 not at all. N, L, V need not be unit.
SL_FN vec3 shadeLightDisney(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 baseColor, float metallic, float roughness, vec4 d0,
                            vec4 d1, bool diffuseOn, bool specularOn, vec3 specScale) {
    N = normalize(N);
    L = normalize(L);
    V = normalize(V);
    float NoL = dot(N, L);
    if (NoL <= 0.0f) return vec3(0.0f);
    float NoV = max(dot(N, V), 1e-4f);
    vec3 H = normalize(L + V);
    float NoH = dot(N, H);
    float LoH = dot(L, H);
    float FL = schlickWeight(NoL);
    float FV = schlickWeight(NoV);
    float FH = schlickWeight(LoH);
    vec3 tint = disneyTint(baseColor);
    vec3 f = vec3(0.0f);
    if (diffuseOn) {
        float Fd90 = 0.5f + 2.0f * LoH * LoH * roughness;
        float Fd = mix(1.0f, Fd90, FL) * mix(1.0f, Fd90, FV);
        float Fss90 = LoH * LoH * roughness;
        float Fss = mix(1.0f, Fss90, FL) * mix(1.0f, Fss90, FV);
        float ss = 1.25f * (Fss * (1.0f / (NoL + NoV) - 0.5f) + 0.5f);
        vec3 sheen = FH * d1.x * mix(vec3(1.0f), tint, d1.y);
        f = ((1.0f / SL_PI) * mix(Fd, ss, d0.x) * baseColor + sheen) * (1.0f - metallic);
    }
    if (specularOn) {
        vec2 a = disneyAnisoAlpha(roughness, d0.w);
        vec3 NxH = cross(N, H);
        float Ds;
        float Gs;
        if (d0.w > 0.0f) {
            vec3 X = anisotropyTangent(N);
            vec3 Y = cross(N, X);
            Ds = D_GTR2Aniso(NoH, dot(H, X), dot(H, Y), a.x, a.y);
            Gs = smithGGXAniso(NoL, dot(L, X), dot(L, Y), a.x, a.y) * smithGGXAniso(NoV, dot(V, X), dot(V, Y), a.x, a.y);
        } else {
            // Isotropic: GTR2 with ax = ay is GGX, (H·X)² + (H·Y)² = |N × H|², and no tangent is needed.
            Ds = D_GGX(NoH, dot(NxH, NxH), a.x);
            Gs = smithGGXSeparable(NoL, a.x) * smithGGXSeparable(NoV, a.x);
        }
        vec3 Fs = mix(disneySpecularF0(baseColor, metallic, d0.y, d0.z), vec3(1.0f), FH);
        f = f + (Gs * Ds) * Fs * specScale;
        if (d1.z > 0.0f) {
            float Dr = D_GTR1(NoH, dot(NxH, NxH), disneyClearcoatAlpha(d1.w));
            float Gr = smithGGXSeparable(NoL, 0.25f) * smithGGXSeparable(NoV, 0.25f);
            float Fr = mix(0.04f, 1.0f, FH);
            f = f + vec3(0.25f * d1.z * Gr * Fr * Dr);
        }
    }
    return Il * (SL_PI * NoL) * f;
}

// glTF's material layers on pbr (the specular layer and index, the clear coat, the sheen, the anisotropy), in a file
// of their own, after the microfacet and anisotropic functions they build on.
#include "gltf_layers.glsl"

// One light's contribution Il ⊙ (md·max(N·L,0) + ms·spec), before visibility. N, L, V need not be unit:
// both renderers hand in raw vectors and this normalises them, so the order of operations is shared.
// SL_MODEL_PBR reads md as the diffuse colour, ms as F0 and s as roughness (pbrDiffuseColor, pbrF0) and
// returns π·f(L,V)·Il·N·L (design.md §7): π·Fd_Lambert() = 1, so its diffuse term is the lecture's md·N·L,
// taken by (1 − F) under the specular layer (glTF 2.0 Appendix B, fresnel_mix) when that layer is on.
// specScale multiplies the pbr specular lobe: energyCompensation(), or vec3(1) (shadeLight) for none.
// Not for SL_MODEL_DISNEY, which reads more than md, ms and s: shadeLightModel sends it to shadeLightDisney.
SL_FN vec3 shadeLightScaled(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 md, vec3 ms, float s, int model,
                            bool diffuseOn, bool specularOn, vec3 specScale) {
    N = normalize(N);
    L = normalize(L);
    V = normalize(V);
    float NoL = dot(N, L);
    vec3 I = vec3(0.0f);
    if (diffuseOn) I = I + md * max(NoL, 0.0f);
    if (specularOn) {
        if (model == SL_MODEL_PBR) {
            if (NoL > 0.0f) {
                vec3 F = F_Schlick(ms, max(dot(V, normalize(L + V)), 0.0f));
                I = I * (vec3(1.0f) - F) + SL_PI * NoL * specularGGX(N, L, V, ms, s) * specScale;
            }
        } else {
            float spec = model == SL_MODEL_PHONG ? specularPhong(N, L, V, s) : specularBlinnPhong(N, L, V, s);
            I = I + ms * spec;
        }
    }
    return Il * I;
}

// One light's contribution under any model: shadeLightDisney for disney (its base colour, metallic, s as the
// roughness, d0 and d1), shadeLightScaled for the others (which ignore the last four).
SL_FN vec3 shadeLightModel(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 md, vec3 ms, float s, int model, bool diffuseOn,
                           bool specularOn, vec3 specScale, vec3 baseColor, float metallic, vec4 d0, vec4 d1) {
    if (model == SL_MODEL_DISNEY)
        return shadeLightDisney(N, L, V, Il, baseColor, metallic, s, d0, d1, diffuseOn, specularOn, specScale);
    return shadeLightScaled(N, L, V, Il, md, ms, s, model, diffuseOn, specularOn, specScale);
}

// shadeLightScaled without energy compensation (the default, and the lecture's models).
SL_FN vec3 shadeLight(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 md, vec3 ms, float s, int model,
                      bool diffuseOn, bool specularOn) {
    return shadeLightScaled(N, L, V, Il, md, ms, s, model, diffuseOn, specularOn, vec3(1.0f));
}

// Split-sum image-based lighting of a pbr surface (Karis 2013; Filament "Image based lights"): the diffuse
// colour times the irradiance (as radiance: E/π, so a uniform environment L gives L), and the prefiltered
// radiance times the specular DFG term E, optionally energy-compensated. As for lights, the diffuse layer
// loses what the specular layer reflects, (1 − E) (Filament's evaluateIBL), so a white dielectric in a
// uniform environment reflects exactly the environment.
SL_FN vec3 shadeEnvironment(vec3 diffuseColor, vec3 f0, vec3 irradiance, vec3 prefiltered, vec2 dfg,
                            bool compensate, bool diffuseOn, bool specularOn) {
    vec3 I = diffuseOn ? diffuseColor * irradiance : vec3(0.0f);
    if (specularOn) {
        vec3 E = specularDFG(f0, dfg);
        if (compensate) E = E * energyCompensation(f0, dfg);
        I = I * (vec3(1.0f) - E) + prefiltered * E;
    }
    return I;
}

// The lecture's step 0, "no illumination" (docs/lighting.md): with none of the light terms on, a surface shows its
// unlit colour instead of black.
SL_FN bool noIllumination(bool ambientOn, bool diffuseOn, bool specularOn) {
    return !ambientOn && !diffuseOn && !specularOn;
}

// That unlit colour: md under Phong and Blinn-Phong, the base colour under pbr (so a metal keeps its colour,
// though it has no diffuse one); each as the surface has it at the point (textured, a checker's tile).
SL_FN vec3 unlitColour(vec3 md, vec3 baseColor, int model) {
    return physicallyBased(model) ? baseColor : md;
}

// Ambient term Ia ⊙ ma.
SL_FN vec3 shadeAmbient(vec3 Ia, vec3 ma, bool ambientOn) {
    return ambientOn ? Ia * ma : vec3(0.0f);
}

// Optional distance attenuation 1 / (kc + kl·d + kq·d²); (1, 0, 0) is none.
SL_FN float distanceAttenuation(vec3 k, float d) {
    return 1.0f / max(k.x + k.y * d + k.z * d * d, 1e-8f);
}

// Vector from P toward a light: point and spot lights sit at posOrDir, directional lights travel along posOrDir.
SL_FN vec3 lightVector(vec3 posOrDir, bool isPositional, vec3 P) {
    return isPositional ? posOrDir - P : -posOrDir;
}

// KHR_lights_punctual, "Inner and Outer Cone Angles", the reference code's two constants, computed once per
// light on the CPU: x = lightAngleScale = 1 / max(0.001, cos(inner) − cos(outer)) and y = lightAngleOffset =
// −cos(outer)·lightAngleScale. The 0.001 keeps inner = outer finite: a hard edge.
SL_FN vec2 spotConeScaleOffset(float innerConeAngle, float outerConeAngle) {
    float cosOuter = cos(outerConeAngle);
    float scale = 1.0f / max(0.001f, cos(innerConeAngle) - cosOuter);
    return vec2(scale, -cosOuter * scale);
}

// The same section's angular attenuation: cd = dot(spotDir, −L), the cosine of the angle between the spot's
// axis (spotDir, the direction its light travels) and the way from the light to the point, then
// saturate(cd·scale + offset)², 1 inside the inner cone, 0 outside the outer one.
SL_FN float spotAttenuation(vec3 spotDir, vec3 L, vec2 cone) {
    float cd = dot(normalize(spotDir), -normalize(L));
    float a = clamp(cd * cone.x + cone.y, 0.0f, 1.0f);
    return a * a;
}

// KHR_lights_punctual, "Range Property", the recommended window: max(min(1 − (d/range)⁴, 1), 0). The spec's
// formula divides it by d²; here the inverse square is the light's own distanceAttenuation (kq), off by default
// as in the lecture. range <= 0 is no range: 1 everywhere.
SL_FN float rangeWindow(float d, float range) {
    if (range <= 0.0f) return 1.0f;
    float r = d / range;
    float r2 = r * r;
    return clamp(1.0f - r2 * r2, 0.0f, 1.0f);
}

// Intensity arriving at the point (L = lightVector()): Il, and for point and spot lights times the distance
// attenuation and the range window, and for spot lights the cone. spotDir: a spot's direction of travel;
// cone: x, y spotConeScaleOffset(), z the range (0: none), w 1 for a spot light, else 0. A point light with
// no range multiplies by exactly 1 where the spot and range factors would be, bit for bit its old intensity.
SL_FN vec3 lightIntensityAt(vec3 Il, bool isPositional, vec3 attenuation, vec3 L, vec3 spotDir, vec4 cone) {
    if (!isPositional) return Il;
    float d = length(L);
    float a = distanceAttenuation(attenuation, d) * rangeWindow(d, cone.z);
    if (cone.w != 0.0f) a = a * spotAttenuation(spotDir, L, vec2(cone.x, cone.y));
    return Il * a;
}

// Two-sided lighting: N flipped to face the viewer.
SL_FN vec3 faceForward(vec3 N, vec3 V) {
    return dot(N, V) < 0.0f ? -N : N;
}

// Primary ray direction through pixel-space point (px, py), with py measured from the top of the image
// and pixel centres at +0.5 (design.md §1). forward/right/up are the camera's orthonormal basis.
SL_FN vec3 cameraRayDirection(vec3 forward, vec3 right, vec3 up, float tanHalfFovY, float width,
                              float height, float px, float py) {
    float aspect = width / height;
    float x = (2.0f * px / width - 1.0f) * tanHalfFovY * aspect;
    float y = (1.0f - 2.0f * py / height) * tanHalfFovY;
    return normalize(forward + x * right + y * up);
}

// Ray–sphere intersection, the nearest t > tMin, or -1 on a miss. dir must be unit length.
// Uses the half-b form and Vieta's second root to avoid cancellation (Hearn & Baker; pbrt §3.2.2).
SL_FN float intersectSphere(vec3 origin, vec3 dir, vec3 center, float radius, float tMin) {
    vec3 oc = origin - center;
    float b = dot(oc, dir);
    vec3 perp = oc - b * dir;   // distance of the line from the centre, computed without cancellation
    float disc = radius * radius - dot(perp, perp);
    if (disc < 0.0f) return -1.0f;
    float sq = sqrt(disc);
    float c = dot(oc, oc) - radius * radius;
    float q = b > 0.0f ? -b - sq : -b + sq;
    float t0 = q != 0.0f ? c / q : 0.0f;
    float t1 = q;
    float tNear = min(t0, t1);
    float tFar = max(t0, t1);
    if (tNear > tMin) return tNear;
    if (tFar > tMin) return tFar;
    return -1.0f;
}

// Ray–plane intersection for {x : dot(n, x) = offset}, t > tMin or -1 (parallel or behind).
SL_FN float intersectPlane(vec3 origin, vec3 dir, vec3 n, float offset, float tMin) {
    float denom = dot(n, dir);
    if (abs(denom) < 1e-12f) return -1.0f;
    float t = (offset - dot(n, origin)) / denom;
    return t > tMin ? t : -1.0f;
}

// A fixed tangent basis on a plane with unit normal n (Duff et al. 2017, "Building an Orthonormal
// Basis, Revisited"), used to lay the checker pattern identically in both renderers.
SL_FN vec3 planeTangent(vec3 n) {
    float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sgn + n.z);
    float b = n.x * n.y * a;
    return vec3(1.0f + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
}

SL_FN vec3 planeBitangent(vec3 n) {
    float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sgn + n.z);
    float b = n.x * n.y * a;
    return vec3(b, sgn + n.y * n.y * a, -n.y);
}

// Checker parity at point P on a plane with tangent basis (t, b): 0 for material.md tiles, 1 for checker
// md2 tiles. The rasterizer passes the basis the CPU computed once per plane (a uniform).
SL_FN int checkerParityInBasis(vec3 P, vec3 t, vec3 b, float size) {
    float u = floor(dot(P, t) / size);
    float v = floor(dot(P, b) / size);
    float sum = u + v;
    return sum - 2.0f * floor(sum * 0.5f) > 0.5f ? 1 : 0;
}

// The same with the basis of the plane's normal n.
SL_FN int checkerParity(vec3 P, vec3 n, float size) {
    return checkerParityInBasis(P, planeTangent(n), planeBitangent(n), size);
}
