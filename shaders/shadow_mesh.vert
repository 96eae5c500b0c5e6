// Shadow-map pass for meshes: world positions into one layer's light clip space. Depth only (Williams 1978).
layout(location = 0) in vec3 a_position;

uniform mat4 u_lightViewProj;

void main() {
    gl_Position = u_lightViewProj * vec4(a_position, 1.0f);
}
