// Triangle meshes: interpolated normal, renormalised in shadeLight, flipped to face the viewer by winding.
#include "surface.glsl"
#if SL_ENVIRONMENT
#include "environment.glsl"
#endif

in vec3 v2f_position;
in vec3 v2f_normal;

void main() {
    vec3 N = gl_FrontFacing ? v2f_normal : -v2f_normal;
    vec3 V = u_eye.xyz - v2f_position;
    vec3 I = shadeSurface(v2f_position, N, V, u_md);
#if SL_ENVIRONMENT
    I += environmentReflection(N, V);
#endif
    o_color = vec4(I, 1.0f);
    o_coverage = u_objectId;
}
