// Per-frame uniform block shared by every raster pass. Mirrored by src/raster/frame_block.h (std140).

// 1 where the vertex stage can write gl_ClipDistance (desktop GLSL); GLSL ES 3.00 has no clip distances, and
// its prelude sets 0 (src/gl/shader_dialect.h): mesh fragments behind a mirror plane are discarded instead.
#ifndef SL_CLIP_DISTANCE
#define SL_CLIP_DISTANCE 1
#endif

layout(std140) uniform Frame {
    mat4 u_viewProj;
    vec4 u_eye;                         // xyz: camera position
    vec4 u_forward;                     // xyz: camera basis, unit
    vec4 u_right;
    vec4 u_up;
    vec4 u_viewport;                    // full image width, height (pixels), tan(fovY/2), GL row of this band's bottom
    vec4 u_ambient;                     // xyz: Ia
    ivec4 u_flags;                      // model, term bits (1 ambient, 2 diffuse, 4 specular), light count,
                                        // pass bits (1 shadows, 2 planar mirror lookups)
    vec4 u_lightPos[SL_MAX_LIGHTS];     // xyz: position (w = 1: point or spot) or direction of travel (w = 0)
    vec4 u_lightColor[SL_MAX_LIGHTS];   // xyz: Il
    vec4 u_lightAtten[SL_MAX_LIGHTS];   // xyz: kc, kl, kq
    vec4 u_lightSpot[SL_MAX_LIGHTS];    // xyz: a spot light's direction of travel
    vec4 u_lightCone[SL_MAX_LIGHTS];    // lightIntensityAt's cone: spot scale, offset, range (0: none), 1 for a spot
    vec4 u_clipPlane;                   // keep dot(xyz, P) + w >= 0; (0, 0, 0, 1) keeps all (mirror passes clip)
    vec4 u_iblParams;                   // environment: intensity, cos(rotation), sin(rotation)
    ivec4 u_iblInfo;                    // mode (0 none, 1 uniform, 2 map), cube size, levels, energy compensation
    vec4 u_iblRadiance;                 // xyz: a uniform environment's radiance
    vec4 u_iblSH[9];                    // xyz: a map's SH9 irradiance
};
