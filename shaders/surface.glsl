// Fragment-side shading shared by the mesh, sphere and plane passes: the material uniforms, the outputs
// (linear colour + coverage id), and the sum over lights that mirrors src/shading/local_illumination.h.
#include "lighting.glsl"
#include "frame.glsl"
#include "shadow.glsl"

uniform vec3 u_ma;
uniform vec3 u_md;
uniform vec3 u_ms;
uniform float u_s;
uniform uint u_objectId;

layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_coverage;

vec3 shadeSurface(vec3 P, vec3 N, vec3 V, vec3 md) {
    int terms = u_flags.y;
    vec3 I = shadeAmbient(u_ambient.xyz, u_ma, (terms & 1) != 0);
    for (int i = 0; i < u_flags.z; ++i) {
        bool isPoint = u_lightPos[i].w != 0.0f;
        vec3 L = lightVector(u_lightPos[i].xyz, isPoint, P);
        vec3 Il = lightIntensityAt(u_lightColor[i].xyz, isPoint, u_lightAtten[i].xyz, L);
        vec3 c = shadeLight(N, L, V, Il, md, u_ms, u_s, u_flags.x, (terms & 2) != 0, (terms & 4) != 0);
#if SL_SHADOWS
        // vis_l multiplies diffuse + specular only; no lookup where N·L <= 0 (the term is 0 there anyway).
        // A compile-time switch, not a uniform one: llvmpipe would evaluate the lookup for every fragment.
        if (dot(N, L) > 0.0f) c *= shadowVisibility(i, P, normalize(N));
#endif
        I += c;
    }
    return I;
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
