// Shader-unit test kernel (tests/shader_unit_test.cpp): evaluates shadeLight from lighting.glsl for the
// inputs stored in one texel per case, so the GPU's results can be read back and compared with C++.
#include "lighting.glsl"

uniform sampler2D t_N;        // xyz: N
uniform sampler2D t_L;        // xyz: L
uniform sampler2D t_V;        // xyz: V
uniform sampler2D t_params;   // x: s (pbr, disney: roughness), y: model (0 Phong, 1 Blinn-Phong, 2 pbr, 3 disney),
                              // z: metallic
                              // y = 7: pbr with glTF's specular layer, t_disney0 its (f0d, weight), t_disney1
                              // its anisotropy (strength, cos, sin)
                              // y = 8: pbr under glTF's clear coat, t_disney0 its (factor, roughness), t_disney1
                              // its normal
                              // y = 10: pbr under glTF's sheen, t_disney0 its (colour, roughness), t_disney1
                              // its albedos (E at N·V, E at N·L)
                              // y = 11: pbr under glTF's transmission, t_disney0 its specular layer (f0d,
                              // weight), t_disney1 (transmissionPacked's factor, roughness scale, η; the tint)
                              // y = 9: a spot light's intensity instead: N the spot's direction, L the light
                              // vector, V its attenuation (kc, kl, kq), x, z its cone scale and offset, w its range
uniform sampler2D t_disney0;  // disney: (subsurface, specular, specularTint, anisotropic)
uniform sampler2D t_disney1;  // disney: (sheen, sheenTint, clearcoat, clearcoatGloss)
uniform vec3 u_Il;
uniform vec3 u_md;
uniform vec3 u_ms;

layout(location = 0) out vec4 o_result;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 N = texelFetch(t_N, p, 0).xyz;
    vec3 L = texelFetch(t_L, p, 0).xyz;
    vec3 V = texelFetch(t_V, p, 0).xyz;
    vec4 params = texelFetch(t_params, p, 0);
    int model = int(params.y + 0.5f);
    if (model == 9) {
        vec4 cone = vec4(params.x, params.z, params.w, 1.0f);
        vec3 I = lightIntensityAt(u_Il, true, V, L, N, cone);
        o_result = vec4(I, spotAttenuation(N, L, vec2(params.x, params.z)));
        return;
    }
    if (model == 7) {
        // u_md is the base colour; w: the layered F0's green (pbrSpecularF0).
        vec4 layer = texelFetch(t_disney0, p, 0);
        vec3 turn = texelFetch(t_disney1, p, 0).xyz;  // Anisotropy::packed
        vec4 aniso = vec4(anisotropyDirection(N, vec4(0.0f), turn), turn.x);
        vec3 I = shadeLightPbrSpecular(N, L, V, u_Il, pbrDiffuseColor(u_md, params.z), u_md, params.z, params.x, layer, aniso,
                                       true, true, vec3(1.0f));
        o_result = vec4(I, pbrSpecularF0(u_md, params.z, layer).y);
        return;
    }
    if (model == 8) {
        // u_md is the base colour; w: the coat's Fresnel weight.
        vec2 coat = texelFetch(t_disney0, p, 0).xy;
        vec3 Nc = texelFetch(t_disney1, p, 0).xyz;
        vec3 base = shadeLight(N, L, V, u_Il, pbrDiffuseColor(u_md, params.z), pbrF0(u_md, params.z), params.x,
                               SL_MODEL_PBR, true, true);
        o_result = vec4(clearcoatLight(base, Nc, L, V, u_Il, coat, true), clearcoatWeight(Nc, V, coat.x));
        return;
    }
    if (model == 10) {
        // u_md is the base colour; w: the sheen's lobe alone (sheenLobe).
        vec4 sheen = texelFetch(t_disney0, p, 0);
        vec2 E = texelFetch(t_disney1, p, 0).xy;
        vec3 base = shadeLight(N, L, V, u_Il, pbrDiffuseColor(u_md, params.z), pbrF0(u_md, params.z), params.x,
                               SL_MODEL_PBR, true, true);
        o_result = vec4(sheenLight(base, N, L, V, u_Il, sheen, E.x, E.y, true), sheenLobe(N, L, V, sheen.w));
        return;
    }
    if (model == 11) {
        // u_md is the base colour; w: the environment through (of a radiance 0.7) plus half the direction's y.
        vec4 layer = texelFetch(t_disney0, p, 0);
        vec4 t = texelFetch(t_disney1, p, 0);
        vec3 md = pbrDiffuseColor(u_md, params.z);
        vec3 tc = md * t.x;
        vec3 I = shadeLightPbrSpecular(N, L, V, u_Il, md * (1.0f - t.x), u_md, params.z, params.x, layer, vec4(0.0f),
                                       true, true, vec3(1.0f)) +
                 transmissionLight(N, L, V, u_Il, tc, vec3(t.w), layer, params.x * t.y, true, true);
        vec4 tp = vec4(t.x, t.y, t.z, 0.0f);
        float through = transmissionEnvironment(tc, vec3(0.7f), layer, vec2(params.x, params.z), true, true).y;
        o_result = vec4(I, through + 0.5f * transmissionDirection(N, V, tp).y);
        return;
    }
    if (model == SL_MODEL_DISNEY) {
        // u_md is the base colour; w: the specular group alone (anisotropic GGX and clearcoat), green.
        vec4 d0 = texelFetch(t_disney0, p, 0);
        vec4 d1 = texelFetch(t_disney1, p, 0);
        vec3 I = shadeLightModel(N, L, V, u_Il, pbrDiffuseColor(u_md, params.z), vec3(0.0f), params.x, model, true,
                                 true, vec3(1.0f), u_md, params.z, d0, d1);
        vec3 spec = shadeLightDisney(N, L, V, vec3(1.0f), u_md, params.z, params.x, d0, d1, false, true, vec3(1.0f));
        o_result = vec4(I, spec.y);
        return;
    }
    if (model == SL_MODEL_PBR) {
        // u_md is the base colour: the derived diffuse colour and F0 are part of what is proved equal.
        vec3 md = pbrDiffuseColor(u_md, params.z);
        vec3 f0 = pbrF0(u_md, params.z);
        vec3 I = shadeLight(N, L, V, u_Il, md, f0, params.x, model, true, true);
        vec3 spec = specularGGX(normalize(N), normalize(L), normalize(V), f0, params.x);
        o_result = vec4(I, spec.y);
        return;
    }
    vec3 I = shadeLight(N, L, V, u_Il, u_md, u_ms, params.x, model, true, true);
    float spec = model == SL_MODEL_PHONG ? specularPhong(normalize(N), normalize(L), normalize(V), params.x)
                                         : specularBlinnPhong(normalize(N), normalize(L), normalize(V), params.x);
    o_result = vec4(I, spec);
}
