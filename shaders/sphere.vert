// Sphere impostor proxy: the sphere's bounding cube (unit cube scaled and moved), back faces only, so it
// covers the sphere's footprint from outside and inside alike.
#include "frame.glsl"

layout(location = 0) in vec3 a_position;   // unit cube corner in [-1, 1]^3

uniform vec3 u_center;
uniform float u_radius;

void main() {
    gl_Position = u_viewProj * vec4(u_center + u_radius * a_position, 1.0f);
}
