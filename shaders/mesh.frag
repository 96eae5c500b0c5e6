// Triangle meshes: interpolated normal, renormalised in shadeLight, flipped to face the viewer by winding.
#include "surface.glsl"
#if SL_ENVIRONMENT
#include "environment.glsl"
#endif

in vec3 v2f_position;
in vec3 v2f_normal;
in vec2 v2f_texcoord;

// The material's base-colour texture (src/raster/mesh_textures.h): its mip chain as RGBA32F levels, filtered by
// hand in texture_sample.glsl exactly as the tracer filters it. u_baseTex: x the level count (0: no texture),
// y, z the wrap modes of u and v, w the flags 1 mag bilinear, 2 min bilinear, 4 mipmaps, 8 linear between levels.
uniform sampler2D t_baseColor;
uniform ivec4 u_baseTex;
uniform vec4 u_baseTexMatrix;  // KHR_texture_transform (texTransform)
uniform vec2 u_baseTexOffset;
vec4 texTexel(int map, int level, int x, int y) { return texelFetch(t_baseColor, ivec2(x, y), level); }
int texWidth(int map, int level) { return textureSize(t_baseColor, level).x; }
int texHeight(int map, int level) { return textureSize(t_baseColor, level).y; }
#include "texture_sample.glsl"

void main() {
    vec3 N = gl_FrontFacing ? v2f_normal : -v2f_normal;
    vec3 V = u_eye.xyz - v2f_position;
    if (u_baseTex.x > 0) {
        // The footprint from screen-space derivatives (uniform control flow: u_baseTex is a uniform).
        vec2 uv = texTransform(v2f_texcoord, u_baseTexMatrix, u_baseTexOffset);
        float lod = texLod(texWidth(0, 0), texHeight(0, 0), dFdx(uv), dFdy(uv));
        s_tex = texSample(0, u_baseTex.x, u_baseTex.y, u_baseTex.z, (u_baseTex.w & 1) != 0, (u_baseTex.w & 2) != 0,
                          (u_baseTex.w & 4) != 0, (u_baseTex.w & 8) != 0, uv, lod).rgb;
    }
    vec3 I = shadeSurface(v2f_position, N, V, u_md * s_tex);
#if SL_ENVIRONMENT
    I += environmentReflection(N, V);
#endif
    o_color = vec4(I, 1.0f);
    o_coverage = u_objectId;
}
