// Shadow-map pass for sphere impostors: the light's ray through this texel (unprojected, so orthographic,
// perspective and cube layers are one code path) hits the exact sphere; its depth is written. No tessellation.
#include "lighting.glsl"

uniform mat4 u_lightViewProj;
uniform mat4 u_lightInverse;    // inverse of u_lightViewProj
uniform vec3 u_center;
uniform float u_radius;
uniform float u_mapSize;        // texels per side

void main() {
    vec2 ndc = 2.0f * gl_FragCoord.xy / u_mapSize - 1.0f;
    vec4 a = u_lightInverse * vec4(ndc, -1.0f, 1.0f);
    vec4 b = u_lightInverse * vec4(ndc, 1.0f, 1.0f);
    vec3 origin = a.xyz / a.w;
    vec3 dir = normalize(b.xyz / b.w - origin);
    float t = intersectSphere(origin, dir, u_center, u_radius, 0.0f);
    if (t < 0.0f) discard;
    vec4 clip = u_lightViewProj * vec4(origin + t * dir, 1.0f);
    gl_FragDepth = clamp(0.5f * (clip.z / clip.w) + 0.5f, 0.0f, 1.0f);
}
