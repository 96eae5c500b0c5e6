// Infinite plane: four triangles fanning out from the point under the eye to the plane's points at infinity
// (homogeneous w = 0) along ±tangent and ±bitangent, so the rasterized plane ends exactly at the horizon.
// It is drawn with ordinary depth, so covered pixels are rejected before the fragment shader runs; the
// fragment shader still shades the exact ray–plane hit.
#include "frame.glsl"

uniform vec3 u_planeCenter;     // the point of the plane under the eye
uniform vec3 u_planeT;          // unit tangent (planeTangent)
uniform vec3 u_planeB;          // unit bitangent (planeBitangent)

void main() {
    int corner = gl_VertexID % 3;   // 0: the centre, 1 and 2: two neighbouring directions to infinity
    int wedge = gl_VertexID / 3;    // 0..3
    int k = (wedge + corner - 1) % 4;
    vec3 dir = k == 0 ? u_planeT : k == 1 ? u_planeB : k == 2 ? -u_planeT : -u_planeB;
    vec4 P = corner == 0 ? vec4(u_planeCenter, 1.0f) : vec4(dir, 0.0f);
    gl_Position = u_viewProj * P;
}
