// Shadow visibility vis_l for the colour passes (design.md §1): planes occlude analytically, exactly as the
// tracer's shadow ray; meshes and spheres through shadow maps (Williams 1978) with a depth bias and a
// normal-offset bias (Holbert 2011). Mirrored by src/raster/shadow_block.h (std140). Not the lighting sum.
// Each light's map kind and blocking planes are compile-time constants of the variant
// (src/raster/shader_variant.h), so only the code a light needs runs.
#include "cube_face.glsl"

const int SL_SHADOW_NONE = 0;
const int SL_SHADOW_ORTHO = 1;
const int SL_SHADOW_PERSPECTIVE = 2;
const int SL_SHADOW_CUBE = 3;

layout(std140) uniform Shadows {
    mat4 u_layerViewProj[SL_MAX_SHADOW_LAYERS];
    ivec4 u_shadowLight[SL_MAX_SHADOWED];       // x: kind, y: first layer, z: blocking planes (bits)
    vec4 u_shadowRange[SL_MAX_SHADOWED];        // x: texel footprint (ortho: world; else per unit distance), y: near, z: far
    vec4 u_shadowDepth[SL_MAX_SHADOWED];        // x, y: A, B of the perspective test; z: ortho depth bias (window units)
    vec4 u_shadowPlanes[SL_MAX_SHADOW_PLANES];  // xyz: unit normal, w: offset
    ivec4 u_shadowInfo;                         // x: plane count, y: pcf, z: map size (texels)
    vec4 u_shadowBias;                          // x: depth bias (texels), y: normal bias (texels), z: scene epsilon
};

uniform sampler2DArray t_shadowMaps;

// The tracer's shadow ray from `origin` against the planes in `mask`: blocked exactly when the origin and
// the light lie strictly on opposite sides of a plane (intersectPlane's 0 < t < tMax, without the division).
bool planesBlock(int i, bool isPoint, int mask, vec3 origin) {
    bool blocked = false;
    for (int k = 0; k < SL_SHADOW_PLANES; ++k) {
        if ((mask & (1 << k)) == 0) continue;
        vec4 plane = u_shadowPlanes[k];
        float a = dot(plane.xyz, origin) - plane.w;
        float b = isPoint ? dot(plane.xyz, u_lightPos[i].xyz) - plane.w : -dot(plane.xyz, u_lightPos[i].xyz);
        blocked = blocked || (a < 0.0f && b > 0.0f) || (a > 0.0f && b < 0.0f);
    }
    return blocked;
}

// One map texel against the receiver: lit when nothing was drawn there (d = 1) or the receiver is not
// behind the stored depth. Ortho: r is the receiver's window depth; otherwise its distance along the axis.
bool texelLit(ivec2 q, int layer, float r, vec4 test, bool ortho) {
    float d = texelFetch(t_shadowMaps, ivec3(q, layer), 0).r;
    return d >= 1.0f || (ortho ? r <= d : (test.x - d) * r <= test.y);
}

// 1 lit, 0 shadowed (fractions with PCF) by light i's shadow map of the given kind, from its first layer on.
float mapVisibility(int i, int kind, int layer, vec3 P, vec3 Nf) {
    bool ortho = kind == SL_SHADOW_ORTHO;
    vec3 lightPos = u_lightPos[i].xyz;
    // Holbert 2011: move the receiver along its normal by a number of texels of the map at P.
    float texel = ortho ? u_shadowRange[i].x : u_shadowRange[i].x * length(P - lightPos);
    vec3 Pn = P + (u_shadowBias.y * texel + u_shadowBias.z) * Nf;
    vec3 c;  // xy: the receiver in the layer's NDC; z: ortho its window depth, else its distance along the axis
    bool inside = true;
    if (kind == SL_SHADOW_CUBE) {
        int face = cubeFace(Pn - lightPos);
        c = cubeFaceCoords(Pn - lightPos, face);
        layer += face;
    } else {
        vec4 clip = u_layerViewProj[layer] * vec4(Pn, 1.0f);
        inside = clip.w > 0.0f && abs(clip.x) <= clip.w && abs(clip.y) <= clip.w;  // else no caster covers it
        c = ortho ? vec3(clip.xy, 0.5f * clip.z + 0.5f) : vec3(clip.xy / clip.w, clip.w);
    }
    vec4 test = u_shadowDepth[i];
    float r = ortho ? c.z - test.z : c.z - u_shadowBias.x * texel;
    int size = u_shadowInfo.z;
    ivec2 q = clamp(ivec2((0.5f * c.xy + 0.5f) * float(size)), ivec2(0), ivec2(size - 1));
#if SL_PCF
    float lit = 0.0f;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            lit += texelLit(clamp(q + ivec2(x, y), ivec2(0), ivec2(size - 1)), layer, r, test, ortho) ? 1.0f : 0.0f;
    lit *= 1.0f / 9.0f;
#else
    float lit = texelLit(q, layer, r, test, ortho) ? 1.0f : 0.0f;
#endif
    return inside ? lit : 1.0f;
}

// vis_l for light i at P (Nf: the unit normal facing the viewer), as the tracer's one shadow ray.
float shadowVisibility(int i, bool isPoint, int kind, int planeMask, int layer, vec3 P, vec3 Nf) {
    if (planeMask != 0 && planesBlock(i, isPoint, planeMask, P + u_shadowBias.z * Nf)) return 0.0f;
    return kind == SL_SHADOW_NONE ? 1.0f : mapVisibility(i, kind, layer, P, Nf);
}
