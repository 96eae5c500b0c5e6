// Infinite plane with optional checker: shades the exact ray–plane hit per pixel, as the tracer does, and
// writes that hit's depth, as sphere.frag does; plane.vert only covers the viewport. A plane rasterized as
// wedges to its points at infinity (w = 0) takes a depth that implementations interpolate differently
// (ANGLE and SwiftShader put whole wedges in front of spheres standing on the plane), and loses what is
// nearer than the near plane: only the exact depth makes where a sphere meets the floor the same everywhere.
// Writing gl_FragDepth turns off early depth testing for planes: their fragments behind meshes and spheres
// are shaded, then rejected, and the pixels above the horizon run up to the intersection and discard.
#include "surface.glsl"

uniform vec3 u_planeNormal;
uniform float u_planeOffset;
uniform int u_checker;          // 1 when the plane has a checker pattern
uniform vec3 u_md2;
uniform vec3 u_baseColor2;       // the checker's md2 itself: the second tiles' base colour under pbr
uniform float u_checkerSize;
uniform vec3 u_planeT;          // planeTangent(u_planeNormal), the tracer's tangent
uniform vec3 u_planeB;          // planeBitangent(u_planeNormal)
uniform vec3 u_kr;
#if SL_ENVIRONMENT
// A mirror plane (its program is the variant's environment program): add kr ⊙ I(reflected) from the
// planar reflection pass. A compile-time switch: llvmpipe would fetch for every plane otherwise.
uniform sampler2D t_reflection;     // the mirrored render of this band, pixel for pixel
#endif

void main() {
    vec3 dir = fragmentRay();
    float t = intersectPlane(u_eye.xyz, dir, u_planeNormal, u_planeOffset, 0.0f);
    if (t < 0.0f) discard;
    vec3 P = u_eye.xyz + t * dir;
    if (clippedByMirror(P)) discard;
    gl_FragDepth = depthOf(P);
    vec3 V = -dir;
    vec3 N = faceForward(u_planeNormal, V);
    // The tangent basis as computed on the CPU (the tracer's own planeTangent/planeBitangent), once per plane.
    bool second = u_checker != 0 && checkerParityInBasis(P, u_planeT, u_planeB, u_checkerSize) == 1;
    vec3 I = shadeSurface(P, N, V, second ? u_md2 : u_md, second ? u_baseColor2 : u_baseColor);
    // Planar reflection: the mirrored scene seen through this pixel is exactly I(reflected ray).
#if SL_ENVIRONMENT
    I += u_kr * texelFetch(t_reflection, ivec2(gl_FragCoord.xy), 0).rgb;
#endif
    o_color = vec4(I, 1.0f);
    o_coverage = u_objectId;
}
