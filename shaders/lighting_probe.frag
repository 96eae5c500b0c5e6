// Shader-unit test kernel (tests/shader_unit_test.cpp): evaluates shadeLight from lighting.glsl for the
// inputs stored in one texel per case, so the GPU's results can be read back and compared with C++.
#include "lighting.glsl"

uniform sampler2D t_N;        // xyz: N
uniform sampler2D t_L;        // xyz: L
uniform sampler2D t_V;        // xyz: V
uniform sampler2D t_params;   // x: s (pbr: roughness), y: model (0 Phong, 1 Blinn-Phong, 2 pbr), z: metallic
                              // y = 3: a spot light's intensity instead: N the spot's direction, L the light
                              // vector, V its attenuation (kc, kl, kq), x, z its cone scale and offset, w its range
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
    if (model == 3) {
        vec4 cone = vec4(params.x, params.z, params.w, 1.0f);
        vec3 I = lightIntensityAt(u_Il, true, V, L, N, cone);
        o_result = vec4(I, spotAttenuation(N, L, vec2(params.x, params.z)));
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
