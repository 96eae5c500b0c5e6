// Infinite plane with optional checker: shades the exact ray–plane hit per pixel, as the tracer does.
// Depth comes from rasterizing the plane's quad (plane.vert), so early depth testing stays on.
#include "surface.glsl"

uniform vec3 u_planeNormal;
uniform float u_planeOffset;
uniform int u_checker;          // 1 when the plane has a checker pattern
uniform vec3 u_md2;
uniform float u_checkerSize;

void main() {
    vec3 dir = fragmentRay();
    float t = intersectPlane(u_eye.xyz, dir, u_planeNormal, u_planeOffset, 0.0f);
    if (t < 0.0f) discard;
    vec3 P = u_eye.xyz + t * dir;
    vec3 V = -dir;
    vec3 N = faceForward(u_planeNormal, V);
    vec3 md = (u_checker != 0 && checkerParity(P, u_planeNormal, u_checkerSize) == 1) ? u_md2 : u_md;
    o_color = vec4(shadeSurface(P, N, V, md), 1.0f);
    o_coverage = u_objectId;
}
