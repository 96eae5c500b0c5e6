// Triangle meshes: interpolated normal, renormalised in shadeLight, flipped to face the viewer by winding.
#include "surface.glsl"

in vec3 v2f_position;
in vec3 v2f_normal;

void main() {
    vec3 N = gl_FrontFacing ? v2f_normal : -v2f_normal;
    vec3 V = u_eye.xyz - v2f_position;
    o_color = vec4(shadeSurface(v2f_position, N, V, u_md), 1.0f);
    o_coverage = u_objectId;
}
