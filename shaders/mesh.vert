// Triangle meshes: world-space positions, normals, tangents and both texture-coordinate sets straight
// through (transforms are applied on import).
#include "frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;   // TEXCOORD_0, (0, 0) where the part has none
layout(location = 3) in vec2 a_texcoord1;  // TEXCOORD_1, likewise
layout(location = 4) in vec4 a_tangent;    // TANGENT (xyz, handedness w), 0 where the part has none

out vec3 v2f_position;
out vec3 v2f_normal;
out vec2 v2f_texcoord;
out vec2 v2f_texcoord1;
out vec4 v2f_tangent;

void main() {
    v2f_position = a_position;
    v2f_normal = a_normal;
    v2f_texcoord = a_texcoord;
    v2f_texcoord1 = a_texcoord1;
    v2f_tangent = a_tangent;
    gl_Position = u_viewProj * vec4(a_position, 1.0f);
#if SL_CLIP_DISTANCE
    gl_ClipDistance[0] = dot(u_clipPlane.xyz, a_position) + u_clipPlane.w;   // enabled in mirror passes only
#endif
}
