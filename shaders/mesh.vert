// Triangle meshes: world-space positions and normals straight through (transforms are applied on import).
#include "frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

out vec3 v2f_position;
out vec3 v2f_normal;

void main() {
    v2f_position = a_position;
    v2f_normal = a_normal;
    gl_Position = u_viewProj * vec4(a_position, 1.0f);
    gl_ClipDistance[0] = dot(u_clipPlane.xyz, a_position) + u_clipPlane.w;   // enabled in mirror passes only
}
