// Sphere impostor: intersect the pixel's primary ray with the exact sphere, as the tracer does, and write
// its depth. Exact silhouette and normal, no tessellation.
#if SL_ENVIRONMENT
#define SL_CUBE 1  // this object's environment cube (surface.glsl)
#endif
#include "surface.glsl"
#if SL_ENVIRONMENT
#include "environment.glsl"
#endif

uniform vec3 u_center;
uniform float u_radius;

void main() {
    vec3 dir = fragmentRay();
    float t = intersectSphere(u_eye.xyz, dir, u_center, u_radius, 0.0f);
    if (t < 0.0f) discard;
    vec3 P = u_eye.xyz + t * dir;
    if (clippedByMirror(P)) discard;
    vec3 V = -dir;
    vec3 N = faceForward((P - u_center) / u_radius, V);
    gl_FragDepth = depthOf(P);
    vec3 I = shadeSurface(P, N, V, u_md, u_baseColor);
#if SL_ENVIRONMENT
    I += environmentReflection(N, V);
#endif
    o_color = vec4(I, 1.0f);
    o_coverage = u_objectId;
}
