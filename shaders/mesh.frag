// Triangle meshes: interpolated normal, renormalised in shadeLight, flipped to face the viewer by winding;
// with SL_MATERIAL_MAPS (a textured or non-opaque part; RasterRenderer::programsFor), the material's glTF
// maps (base colour, metallic-roughness, normal, occlusion, emissive, and pbr's clear coat maps) and its alpha
// mode. Its value has bit 1 << k set when the part has map k (k = 4, emissive: bit 32), bit 16 for a
// non-opaque alpha mode and bit 128 for any of the clear coat's three maps (5–7): each
// part's program holds the code of its own maps only, since llvmpipe's compile time grows with every inlined
// sampler and it runs the code of every branch, taken or not.
#if SL_ENVIRONMENT
#define SL_CUBE 1  // this object's environment cube (surface.glsl)
#endif
#include "surface.glsl"
#ifdef SL_MATERIAL_MAPS
#include "material_maps.glsl"
#endif
#if SL_ENVIRONMENT
#include "environment.glsl"
#endif

in vec3 v2f_position;
in vec3 v2f_normal;
in vec2 v2f_texcoord;
in vec2 v2f_texcoord1;
in vec4 v2f_tangent;

#ifdef SL_MATERIAL_MAPS
// The material's textures (src/raster/mesh_textures.h), map 0 base colour, 1 metallic-roughness, 2 normal,
// 3 occlusion, 4 emissive: each 8-bit mip chain uploaded as its codes (GL_SRGB8_ALPHA8 or GL_RGBA8; GL decodes
// them, within 2e-3 of the tracer's tables in shading/texel_decode.h), read with texelFetch and filtered by
// hand in texture_sample.glsl as the tracer filters it. u_tex[map]: x the level count (0: no texture), y, z
// the wrap modes of u and v, w the flags 1 mag bilinear, 2 min bilinear, 4 mipmaps, 8 linear between levels.
// u_texMatrix[map]: KHR_texture_transform's linear part (texTransform); u_texOffset[map]: xy its offset, z
// the TEXCOORD set (0 or 1), w the strength (normal scale, occlusion strength).
uniform sampler2D t_baseColor;
uniform sampler2D t_metalRough;
uniform sampler2D t_normal;
uniform sampler2D t_occlusion;
uniform sampler2D t_emissive;
uniform sampler2D t_clearcoat;
uniform sampler2D t_clearcoatRoughness;
uniform sampler2D t_clearcoatNormal;
uniform ivec4 u_tex[8];
uniform vec4 u_texMatrix[8];
uniform vec4 u_texOffset[8];
uniform vec4 u_mapFactors;  // x metallic, y roughness (factors), z 1 when Phong's ms is normalised
uniform vec4 u_alpha;       // x the base colour factor's alpha, y the MASK cutoff, z alphaMode (0 opaque, 1 mask, 2 blend)
// `map` is a literal at every call, so each branch folds away once the functions are inlined.
vec4 texTexel(int map, int level, int x, int y) {
    if (map == 1) return texelFetch(t_metalRough, ivec2(x, y), level);
    if (map == 2) return texelFetch(t_normal, ivec2(x, y), level);
    if (map == 3) return texelFetch(t_occlusion, ivec2(x, y), level);
    if (map == 4) return texelFetch(t_emissive, ivec2(x, y), level);
    if (map == 5) return texelFetch(t_clearcoat, ivec2(x, y), level);
    if (map == 6) return texelFetch(t_clearcoatRoughness, ivec2(x, y), level);
    if (map == 7) return texelFetch(t_clearcoatNormal, ivec2(x, y), level);
    return texelFetch(t_baseColor, ivec2(x, y), level);
}
ivec2 texSize(int map, int level) {
    if (map == 1) return textureSize(t_metalRough, level);
    if (map == 2) return textureSize(t_normal, level);
    if (map == 3) return textureSize(t_occlusion, level);
    if (map == 4) return textureSize(t_emissive, level);
    if (map == 5) return textureSize(t_clearcoat, level);
    if (map == 6) return textureSize(t_clearcoatRoughness, level);
    if (map == 7) return textureSize(t_clearcoatNormal, level);
    return textureSize(t_baseColor, level);
}
int texWidth(int map, int level) { return texSize(map, level).x; }
int texHeight(int map, int level) { return texSize(map, level).y; }
#include "texture_sample.glsl"

// Map `map` at this fragment, its footprint from screen-space derivatives. Call in uniform control flow only
// (behind a test of u_tex, a uniform).
vec4 sampleMap(int map) {
    vec2 uv = texTransform(u_texOffset[map].z > 0.5f ? v2f_texcoord1 : v2f_texcoord, u_texMatrix[map], u_texOffset[map].xy);
    float lod = texLod(texWidth(map, 0), texHeight(map, 0), dFdx(uv), dFdy(uv));
    ivec4 t = u_tex[map];
    return texSample(map, t.x, t.y, t.z, (t.w & 1) != 0, (t.w & 2) != 0, (t.w & 4) != 0, (t.w & 8) != 0, uv, lod);
}

#endif

void main() {
#if !SL_CLIP_DISTANCE
    // The same plane gl_ClipDistance clips against, tested per fragment (u_clipPlane keeps all outside
    // mirror passes).
    if (clippedByMirror(v2f_position)) discard;
#endif
    vec3 N = gl_FrontFacing ? v2f_normal : -v2f_normal;
    vec3 V = u_eye.xyz - v2f_position;
    s_tangent = v2f_tangent;  // anisotropy's direction turns from it (surface.glsl)
#ifdef SL_MATERIAL_MAPS
    float alpha = u_alpha.x;
#if (SL_MATERIAL_MAPS & 1) != 0
    if (u_tex[0].x > 0) {
        vec4 base = sampleMap(0);
        s_tex = base.rgb;
        alpha *= base.a;
    }
#endif
#if (SL_MATERIAL_MAPS & 16) != 0
    // glTF alphaMode MASK: what falls below the cutoff is not there (the tracer passes through it).
    if (u_alpha.z == 1.0f && alpha < u_alpha.y) discard;
#endif
    vec3 md = u_md * s_tex;
#if (SL_MATERIAL_MAPS & 2) != 0
    if (u_tex[1].x > 0) {
        vec4 mr = sampleMap(1);
        float metallic = mapMetallic(u_mapFactors.x, mr);
        s_s = mapExponent(SL_MODEL, mapRoughness(u_mapFactors.y, mr));
        vec3 base = u_baseColor * s_tex;
        md = mapDiffuse(base, metallic);
        s_metallic = metallic;
        s_ma = md;
        s_ms = mapSpecular(SL_MODEL, u_mapFactors.z != 0.0f, base, metallic, s_s);
        s_mapped = true;
    }
#endif
#if (SL_MATERIAL_MAPS & 4) != 0
    if (u_tex[2].x > 0) {
#if SL_COATED
        s_coatN = N;  // the coat follows the geometry, not the base's normal map
#endif
        vec3 n = mapNormal(v2f_normal, v2f_tangent, sampleMap(2), u_texOffset[2].w);
        N = gl_FrontFacing ? n : -n;
    }
#endif
#if (SL_MATERIAL_MAPS & 128) != 0 && SL_COATED
    // KHR_materials_clearcoat's maps (maps 5–7): red times the factor, green times the roughness, the coat's
    // own normal map (WhittedIntegrator reads them through SurfaceSetup::at).
    s_coat = u_coat;
    if (u_tex[5].x > 0) s_coat.x *= sampleMap(5).r;
    if (u_tex[6].x > 0) s_coat.y *= sampleMap(6).g;
    if (u_tex[7].x > 0) {
        vec3 n = mapNormal(v2f_normal, v2f_tangent, sampleMap(7), u_texOffset[7].w);
        s_coatN = gl_FrontFacing ? n : -n;
    }
#endif
#if (SL_MATERIAL_MAPS & 8) != 0
    if (u_tex[3].x > 0) s_ao = mapOcclusion(u_texOffset[3].w, sampleMap(3));
#endif
#if (SL_MATERIAL_MAPS & 32) != 0
    if (u_tex[4].x > 0) s_emissive = sampleMap(4).rgb;
#endif
#else
    float alpha = 1.0f;
    vec3 md = u_md;
#endif
#ifdef SL_MATERIAL_MAPS
    vec3 I = shadeSurface(v2f_position, N, V, md, u_baseColor * s_tex);
#else
    vec3 I = shadeSurface(v2f_position, N, V, md, u_baseColor);
#endif
#if SL_ENVIRONMENT
    I += environmentReflection(N, V);
#endif
    // BLEND: the colour is composited over what is behind by the blend state (raster_passes.cpp).
#ifdef SL_MATERIAL_MAPS
    if (u_alpha.z != 2.0f) alpha = 1.0f;
#endif
    o_color = vec4(I, clamp(alpha, 0.0f, 1.0f));
    o_coverage = u_objectId;
}
