// An environment map behind the scene: each pixel's primary ray, built as fragmentRay() in
// surface.glsl builds it, reads the map's level 0 exactly as the tracer's escaping rays do
// (src/trace/environment_light.cpp). Coverage: the background.
#include "lighting.glsl"
#include "frame.glsl"
#include "cube_face.glsl"

uniform sampler2D t_iblCube;
vec3 iblTexel(int x, int y) { return texelFetch(t_iblCube, ivec2(x, y), 0).rgb; }
vec2 dfgTexel(int x, int y) { return vec2(0.0f); }  // no DFG lookups here
#include "ibl.glsl"

layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_coverage;

void main() {
    vec3 dir = cameraRayDirection(u_forward.xyz, u_right.xyz, u_up.xyz, u_viewport.z, u_viewport.x, u_viewport.y,
                                  gl_FragCoord.x, u_viewport.y - (gl_FragCoord.y + u_viewport.w));
    vec3 d = iblRotate(dir, u_iblParams.y, u_iblParams.z);
    o_color = vec4(u_iblParams.x * iblPrefiltered(u_iblInfo.y, u_iblInfo.z, d, 0.0f), 1.0f);
    o_coverage = 0u;
}
