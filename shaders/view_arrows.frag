// Probe arrows: flat colour, drawn over the image with depth testing off.
in vec3 v2f_color;

layout(location = 0) out vec4 o_color;

void main() {
    o_color = vec4(v2f_color, 1.0f);
}
