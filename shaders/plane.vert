// Infinite plane: a quad in the plane, centred under the eye and large enough to reach within half a pixel
// of the horizon. It is rasterized with ordinary depth, so pixels already covered are rejected before the
// fragment shader runs; the fragment shader still shades the exact ray–plane hit.
#include "frame.glsl"

uniform vec3 u_planeCenter;
uniform vec3 u_planeT;          // unit tangent (planeTangent)
uniform vec3 u_planeB;          // unit bitangent (planeBitangent)
uniform float u_planeExtent;    // half the quad's edge, world units

void main() {
    vec2 c = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0f - 1.0f;  // a 4-vertex strip
    vec3 P = u_planeCenter + u_planeExtent * (c.x * u_planeT + c.y * u_planeB);
    gl_Position = u_viewProj * vec4(P, 1.0f);
}
