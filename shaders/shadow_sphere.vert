// Shadow-map pass for sphere impostors: the bounding cube (back faces) in one layer's light clip space.
layout(location = 0) in vec3 a_position;   // unit cube corner in [-1, 1]^3

uniform mat4 u_lightViewProj;
uniform vec3 u_center;
uniform float u_radius;

void main() {
    gl_Position = u_lightViewProj * vec4(u_center + u_radius * a_position, 1.0f);
}
