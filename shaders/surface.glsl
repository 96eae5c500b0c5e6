// Fragment-side shading shared by the mesh, sphere and plane passes: the material uniforms, the outputs
// (linear colour + coverage id), and the sum over lights that mirrors src/shading/local_illumination.h.
#include "lighting.glsl"
#include "frame.glsl"
#include "shadow.glsl"

uniform vec3 u_ma;
uniform vec3 u_md;
uniform vec3 u_ms;
uniform vec3 u_msTex;  // pbr: metallic·baseColor, so F0 = u_ms + u_msTex·(tex − 1) with a base-colour texture; else 0

// The base-colour texture's linear RGB at this fragment (mesh.frag sets it; 1 elsewhere). It multiplies md and
// ma, and under pbr the base colour inside F0 (src/trace/integrator.cpp does the same on the CPU).
vec3 s_tex = vec3(1.0f);
// A metallic-roughness texture re-derives ma, ms and s per fragment (material_maps.glsl; mesh.frag sets
// s_mapped and these); occlusion scales the indirect light by s_ao. Unset, the uniforms are used unchanged.
bool s_mapped = false;
vec3 s_ma = vec3(0.0f);
vec3 s_ms = vec3(0.0f);
float s_s = 0.0f;
float s_ao = 1.0f;
// The mesh's interpolated tangent (xyz, w the bitangent's sign; mesh.frag sets it), zero elsewhere: anisotropy's X.
vec4 s_tangent = vec4(0.0f);
uniform float u_s;
vec3 surfaceMs() { return s_mapped ? s_ms : u_ms + u_msTex * (s_tex - 1.0f); }
vec3 surfaceMa() { return s_mapped ? s_ma : u_ma * s_tex; }
float surfaceS() { return s_mapped ? s_s : u_s; }
uniform vec3 u_baseColor;  // the pbr base colour factor (mesh.frag's maps re-derive coefficients from it; unlitColour)
// disney (shadeLightDisney): the metallic factor, or a metallic-roughness texel's (s_metallic, mesh.frag), and
// the packed parameters (scene/disney_params.h, lobes0 and lobes1).
uniform float u_metallic;
uniform vec4 u_disney0;
uniform vec4 u_disney1;
float s_metallic = 0.0f;
float surfaceMetallic() { return s_mapped ? s_metallic : u_metallic; }
#if defined(SL_SPECULAR_LAYER) && SL_MODEL == 2
// pbr with glTF's specular layer and index, or anisotropic (lighting.glsl's shadeLightPbrSpecular): (f0d, w),
// SpecularLayer::packed.
#define SL_LAYERED 1
uniform vec4 u_specLayer;
uniform vec3 u_aniso;  // glTF's anisotropy (Anisotropy::packed): (strength, cos, sin) of its direction's turn
vec4 s_aniso = vec4(0.0f);  // this fragment's (T, strength), set by shadeSurface (gltf_layers.glsl)
// glTF's transmission and volume (transmissionPacked; factor 0: none) and the volume's tint over its thickness
// (transmissionTint); s_transmitColor the transmitted colour md·t, set by shadeSurface.
uniform vec4 u_transmission;
uniform vec3 u_transmitTint;
vec3 s_transmitColor = vec3(0.0f);
#else
#define SL_LAYERED 0
#endif
#ifdef SL_CUBE
// The object's environment cube (src/raster/environment_cubes.h; sphere.frag and mesh.frag define SL_CUBE in their
// environment programs): the scene around it, rendered from its centre without it. environment.glsl reflects it
// (kr); a transmitting pbr surface sees it through itself.
uniform samplerCube t_environment;
#endif
// The F0 of the environment's light and of the energy compensation: under disney its own from the base colour
// `base` here (disneySpecularF0), under glTF's specular layer pbrSpecularF0, else surfaceMs().
vec3 surfaceF0(vec3 base) {
#if SL_LAYERED
    return pbrSpecularF0(base, surfaceMetallic(), u_specLayer);
#else
    return SL_MODEL == SL_MODEL_DISNEY ? disneySpecularF0(base, surfaceMetallic(), u_disney0.y, u_disney0.z) : surfaceMs();
#endif
}
// One light's diffuse + specular under the variant's model (lighting.glsl's shadeLightModel, chosen here by the
// preprocessor: the other models' programs keep exactly the code, and so the rounding, they had without disney).
vec3 shadeOneLight(vec3 N, vec3 L, vec3 V, vec3 Il, vec3 md, vec3 base, vec3 specScale) {
#if SL_MODEL == 3
    return shadeLightDisney(N, L, V, Il, base, surfaceMetallic(), surfaceS(), u_disney0, u_disney1, SL_DIFFUSE,
                            SL_SPECULAR, specScale);
#elif SL_LAYERED
    return shadeLightPbrSpecular(N, L, V, Il, md, base, surfaceMetallic(), surfaceS(), u_specLayer, s_aniso,
                                 SL_DIFFUSE, SL_SPECULAR, specScale);
#else
    return shadeLightScaled(N, L, V, Il, md, surfaceMs(), surfaceS(), SL_MODEL, SL_DIFFUSE, SL_SPECULAR, specScale);
#endif
}
#if defined(SL_CLEARCOAT) && SL_MODEL == 2
// pbr's clear coat (lighting.glsl's clearcoatLight): (factor, roughness) times its maps' texels (mesh.frag sets
// s_coat when the part has them), and its normal: s_coatN when mesh.frag sets one (the geometry's normal under a
// base normal map, or the coat's own map's), else the shading normal.
#define SL_COATED 1
uniform vec2 u_coat;
vec2 s_coat = vec2(-1.0f);
vec3 s_coatN = vec3(0.0f);
vec2 surfaceCoat() { return s_coat.x < 0.0f ? u_coat : s_coat; }
vec3 coatNormal(vec3 N) { return s_coatN == vec3(0.0f) ? N : s_coatN; }
#else
#define SL_COATED 0
#endif
#if defined(SL_SHEEN) && SL_MODEL == 2
// pbr's sheen (gltf_layers.glsl's sheenLight): (colour, roughness), Sheen::packed, and its albedo table
// (shading/sheen_lut.h) read texel by texel; s_sheenEV its albedo toward the viewer, set by shadeSurface.
#define SL_SHEENED 1
uniform vec4 u_sheen;
uniform sampler2D t_sheenE;
float sheenTexel(int x, int y) { return texelFetch(t_sheenE, ivec2(x, y), 0).r; }
#include "sheen_albedo.glsl"
float s_sheenEV = 0.0f;
#else
#define SL_SHEENED 0
#endif
// One light's term `c` of the base under glTF's layers the variant has: the light through a transmitting base, the
// sheen, then the coat over both (the spec's order; local_illumination.h's shadeLightPbrLayers).
vec3 layeredLight(vec3 c, vec3 N, vec3 L, vec3 V, vec3 Il) {
#if SL_LAYERED
    // A light behind a transmitting surface, through it: part of the base, under the sheen and the coat.
    if (u_transmission.x > 0.0f)
        c += transmissionLight(N, L, V, Il, s_transmitColor, u_transmitTint, u_specLayer, surfaceS() * u_transmission.y, SL_DIFFUSE, SL_SPECULAR);
#endif
#if SL_SHEENED
    c = sheenLight(c, N, L, V, Il, u_sheen, s_sheenEV, sheenAlbedo(SL_SHEEN_SIZE, sheenCos(N, L), u_sheen.w), SL_DIFFUSE);
#endif
#if SL_COATED
    c = clearcoatLight(c, coatNormal(N), L, V, Il, surfaceCoat(), SL_SPECULAR);
#endif
    return c;
}
uniform vec3 u_emission;  // the material's emitted radiance (design.md §8), added as the tracer's local() adds it
// The emissive texture's linear RGB at this fragment (mesh.frag sets it; 1 elsewhere): scales u_emission.
vec3 s_emissive = vec3(1.0f);
uniform uint u_objectId;

layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_coverage;

#if SL_IBL || SL_ENERGY_COMPENSATION
// Split-sum image-based lighting and energy compensation (docs/lighting.md): the tables of src/raster/ibl_textures.h,
// read texel by texel so that ibl.glsl filters them exactly as the tracer does.
uniform sampler2D t_iblCube;
uniform sampler2D t_iblDfg;
vec3 iblTexel(int x, int y) { return texelFetch(t_iblCube, ivec2(x, y), 0).rgb; }
vec2 dfgTexel(int x, int y) { return texelFetch(t_iblDfg, ivec2(x, y), 0).rg; }
#include "ibl.glsl"
#endif

#if SL_IBL
// The environment's light on a pbr surface (src/trace/integrator.cpp, WhittedIntegrator::local, with the
// prefiltered lookup): diffuse·irradiance + prefiltered(R, roughness)·E, md the diffuse colour, f0 the F0, base the
// base colour and u_s the roughness. disney takes it as pbr does (docs/lighting.md).
vec3 environmentLight(vec3 N, vec3 V, vec3 md, vec3 f0, vec3 base, vec2 dfg) {
#if SL_IBL == 2
#if SL_LAYERED
    // Anisotropic: the reflection about the bent normal (gltf_layers.glsl, anisotropicBentNormal).
    vec3 R = s_aniso.w > 0.0f ? iblReflect(anisotropicBentNormal(N, V, s_aniso, surfaceS()), V) : iblReflect(N, V);
#else
    vec3 R = iblReflect(N, V);
#endif
    vec3 sh[9];
    for (int i = 0; i < 9; ++i) sh[i] = u_iblSH[i].xyz;
    vec3 irradiance = u_iblParams.x * iblIrradianceSH(sh, iblRotate(normalize(N), u_iblParams.y, u_iblParams.z));
    vec3 prefiltered = u_iblParams.x * iblPrefiltered(u_iblInfo.y, u_iblInfo.z, iblRotate(R, u_iblParams.y, u_iblParams.z), surfaceS());
#else
    vec3 irradiance = u_iblRadiance.xyz;
    vec3 prefiltered = u_iblRadiance.xyz;
#endif
#if SL_LAYERED
    vec3 compensation = SL_ENERGY_COMPENSATION != 0 ? energyCompensation(f0, dfg) : vec3(1.0f);
    return shadeEnvironmentPbrSpecular(md, base, surfaceMetallic(), u_specLayer, irradiance, prefiltered, dfg,
                                       compensation, SL_DIFFUSE, SL_SPECULAR);
#else
    return shadeEnvironment(md, f0, irradiance, prefiltered, dfg, SL_ENERGY_COMPENSATION != 0, SL_DIFFUSE, SL_SPECULAR);
#endif
}
#endif

#if SL_IBL && (SL_COATED || SL_SHEENED || SL_LAYERED)
// The environment prefiltered at `roughness` along the unit direction D (EnvironmentLight::prefiltered).
vec3 environmentAlong(vec3 D, float roughness) {
#if SL_IBL == 2
    return u_iblParams.x * iblPrefiltered(u_iblInfo.y, u_iblInfo.z, iblRotate(D, u_iblParams.y, u_iblParams.z), roughness);
#else
    return u_iblRadiance.xyz;
#endif
}
// The same along V mirrored about N.
vec3 environmentPrefiltered(vec3 N, vec3 V, float roughness) { return environmentAlong(iblReflect(N, V), roughness); }
#endif

#if SL_IBL && SL_LAYERED
// What a transmitting surface sees through itself along D at the transmitted lobe's roughness: the environment
// prefiltered there; with the object's cube, the cube (what lies behind: the floor, the other objects) stands in
// for the prefilter's mirror level, weighted as EnvironmentLight::prefilteredWithMirror weighs a traced ray's
// radiance, so smooth glass shows what is behind it sharply and rough glass the blurred environment.
vec3 lightBehind(vec3 D, float roughness) {
#ifdef SL_CUBE
    float steps = float(u_iblInfo.z - 1);
    float w = max(0.0f, 1.0f - clamp(roughness, 0.0f, 1.0f) * steps);
    if (w > 0.0f) return mix(environmentAlong(D, 1.0f / steps), texture(t_environment, D).rgb, w);
#endif
    return environmentAlong(D, roughness);
}
#endif

#if SL_IBL && SL_COATED
// The environment's light `base` under the clear coat (WhittedIntegrator::coatedEnvironment): the prefiltered
// environment at the coat's normal and roughness.
vec3 coatedEnvironment(vec3 base, vec3 Nc, vec3 V, vec2 coat) {
    vec2 dfg = iblDFG(SL_DFG_SIZE, iblNoV(Nc, V), coat.y);
    return clearcoatEnvironment(base, Nc, V, environmentPrefiltered(Nc, V, coat.y), dfg, coat, SL_SPECULAR);
}
#endif

// One light's diffuse + specular at P, times its shadow visibility when the variant has shadows. isPoint (a point
// or spot light), isAttenuated (attenuation, range or cone), kind, planeMask and layer (its first shadow-map layer) are compile-time constants for the
// specialised lights, so their branches fold away.
vec3 lightTerm(int i, bool isPoint, bool isAttenuated, int kind, int planeMask, int layer, vec3 P, vec3 N, vec3 V,
               vec3 md, vec3 base, vec3 specScale) {
    vec3 L = lightVector(u_lightPos[i].xyz, isPoint, P);
    // Attenuation (1, 0, 0), no range and no cone multiply by exactly 1: skipped, bit for bit the same.
    vec3 Il = isAttenuated ? lightIntensityAt(u_lightColor[i].xyz, isPoint, u_lightAtten[i].xyz, L, u_lightSpot[i].xyz, u_lightCone[i])
                           : u_lightColor[i].xyz;
    vec3 c = layeredLight(shadeOneLight(N, L, V, Il, md, base, specScale), N, L, V, Il);
#if SL_SHADOWS
    // vis_l multiplies diffuse + specular only; where N·L <= 0 both are already 0.
    c *= shadowVisibility(i, isPoint, kind, planeMask, layer, P, normalize(N));
#endif
    return c;
}

// Ia·ma plus the sum over lights, as src/shading/local_illumination.h (the variant fixes model and terms).
// A pbr surface in an environment (SL_IBL) gets the environment's light in place of Ia·ma. md is the diffuse
// colour the fragment shades with, base its base colour (both textured); with no light term on, the surface
// shows unlitColour() of them (WhittedIntegrator::local does the same).
vec3 shadeSurface(vec3 P, vec3 N, vec3 V, vec3 md, vec3 base) {
    if (noIllumination(SL_AMBIENT, SL_DIFFUSE, SL_SPECULAR)) return unlitColour(md, base, SL_MODEL) + u_emission * s_emissive;
#if SL_IBL || SL_ENERGY_COMPENSATION
    vec2 dfg = iblDFG(SL_DFG_SIZE, iblNoV(N, V), surfaceS());
#endif
#if SL_ENERGY_COMPENSATION
    vec3 specScale = energyCompensation(surfaceF0(base), dfg);
#else
    vec3 specScale = vec3(1.0f);
#endif
#if SL_SHEENED
    s_sheenEV = sheenAlbedo(SL_SHEEN_SIZE, sheenCos(N, V), u_sheen.w);
#endif
#if SL_LAYERED
    s_aniso = vec4(anisotropyDirection(N, s_tangent, u_aniso), u_aniso.x);
    if (u_transmission.x > 0.0f) {  // md splits into what stays diffuse and what passes through
        s_transmitColor = md * u_transmission.x;
        md = md * (1.0f - u_transmission.x);
    }
#endif
#if SL_IBL
    vec3 I = vec3(0.0f);
#else
    vec3 I = shadeAmbient(u_ambient.xyz, surfaceMa() * s_ao, SL_AMBIENT);
#endif
    // One call per specialised light with literal arguments (the variant's X-macro, unrolled).
#define SL_LIGHT_TERM(i, isPoint, isAttenuated, kind, mask, layer) I += lightTerm(i, isPoint, isAttenuated, kind, mask, layer, P, N, V, md, base, specScale);
    SL_FOR_EACH_LIGHT(SL_LIGHT_TERM)
#undef SL_LIGHT_TERM
#if SL_MORE_LIGHTS
    // Lights past the specialised (and shadowed) ones: a generic loop, unshadowed.
    for (int i = SL_LIGHTS; i < u_flags.z; ++i) {
        bool isPoint = u_lightPos[i].w != 0.0f;
        vec3 L = lightVector(u_lightPos[i].xyz, isPoint, P);
        vec3 Il = lightIntensityAt(u_lightColor[i].xyz, isPoint, u_lightAtten[i].xyz, L, u_lightSpot[i].xyz, u_lightCone[i]);
        I += layeredLight(shadeOneLight(N, L, V, Il, md, base, specScale), N, L, V, Il);
    }
#endif
#if SL_IBL
    vec3 environment = environmentLight(N, V, md, surfaceF0(base), base, dfg);
#if SL_LAYERED
    // The environment through a transmitting surface, along −V or refracted (the rasterizer sees nothing else behind).
    if (u_transmission.x > 0.0f)
        environment += transmissionEnvironment(s_transmitColor, u_transmitTint * lightBehind(transmissionDirection(N, V, u_transmission), surfaceS() * u_transmission.y),
                                               u_specLayer, dfg, SL_DIFFUSE, SL_SPECULAR);
#endif
#if SL_SHEENED
    environment = sheenEnvironment(environment, environmentPrefiltered(N, V, u_sheen.w), u_sheen, s_sheenEV, SL_DIFFUSE);
#endif
    environment = environment * s_ao;
#if SL_COATED
    environment = coatedEnvironment(environment, coatNormal(N), V, surfaceCoat());
#endif
    I += environment;
#endif
    return I + u_emission * s_emissive;
}

// The primary ray through this fragment's pixel centre, exactly as the tracer builds it. When the image is
// drawn in bands, u_viewport.w shifts the band's rows back to their place in the full image.
vec3 fragmentRay() {
    return cameraRayDirection(u_forward.xyz, u_right.xyz, u_up.xyz, u_viewport.z, u_viewport.x, u_viewport.y,
                              gl_FragCoord.x, u_viewport.y - (gl_FragCoord.y + u_viewport.w));
}

// Window-space depth of a world point, for ray-cast impostors.
float depthOf(vec3 P) {
    vec4 clip = u_viewProj * vec4(P, 1.0f);
    return min(0.5f * (clip.z / clip.w) + 0.5f, 1.0f);
}

// Mirror passes draw only what lies on the viewer's side of the mirror plane (impostors test their hit).
bool clippedByMirror(vec3 P) {
    return dot(u_clipPlane.xyz, P) + u_clipPlane.w < 0.0f;
}
