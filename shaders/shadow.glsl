// Shadow visibility vis_l for the colour passes (design.md §1): planes occlude analytically, exactly as the
// tracer's shadow ray; meshes and spheres through shadow maps (Williams 1978) with a depth bias and a
// normal-offset bias (Holbert 2011). Mirrored by src/raster/shadow_block.h (std140). Not the lighting sum.
layout(std140) uniform Shadows {
    mat4 u_layerViewProj[SL_MAX_SHADOW_LAYERS];
    ivec4 u_shadowLight[SL_MAX_SHADOWED];       // x: kind (0 none, 1 ortho, 2 perspective, 3 cube), y: first layer
    vec4 u_shadowRange[SL_MAX_SHADOWED];        // x: texel footprint (ortho: world; else per unit depth), y: near, z: far
    vec4 u_shadowPlanes[SL_MAX_SHADOW_PLANES];  // xyz: unit normal, w: offset
    ivec4 u_shadowInfo;                         // x: plane count, y: pcf, z: map size (texels)
    vec4 u_shadowBias;                          // x: depth bias (texels), y: normal bias (texels), z: scene epsilon
};

uniform sampler2DArray t_shadowMaps;

// The tracer's shadow ray against every plane: from P + ε·Nf toward the light, blocked when 0 < t < tMax.
float planeVisibility(vec3 origin, vec3 Ldir, float tMax) {
    for (int k = 0; k < u_shadowInfo.x; ++k) {
        float t = intersectPlane(origin, Ldir, u_shadowPlanes[k].xyz, u_shadowPlanes[k].w, 0.0f);
        if (t > 0.0f && t < tMax) return 0.0f;
    }
    return 1.0f;
}

// Stored window depth back to light-space distance along the layer's axis.
float linearShadowDepth(float d, bool ortho, float zNear, float zFar) {
    if (ortho) return zNear + d * (zFar - zNear);
    float ndc = 2.0f * d - 1.0f;
    return 2.0f * zNear * zFar / ((zFar + zNear) - ndc * (zFar - zNear));
}

// 1 lit, 0 shadowed (fractions with PCF) by light i's shadow map.
float mapVisibility(int i, vec3 P, vec3 Nf, vec3 lightPos) {
    ivec4 s = u_shadowLight[i];
    if (s.x == 0) return 1.0f;
    bool ortho = s.x == 1;
    // Holbert 2011: move the receiver along its normal by a number of texels of the map at P.
    float texel = ortho ? u_shadowRange[i].x : u_shadowRange[i].x * length(P - lightPos);
    vec3 Pn = P + (u_shadowBias.y * texel + u_shadowBias.z) * Nf;
    int layer = s.y;
    if (s.x == 3) {
        vec3 d = Pn - lightPos;
        vec3 a = abs(d);
        layer += a.x >= a.y && a.x >= a.z ? (d.x > 0.0f ? 0 : 1) : a.y >= a.z ? (d.y > 0.0f ? 2 : 3) : (d.z > 0.0f ? 4 : 5);
    }
    vec4 clip = u_layerViewProj[layer] * vec4(Pn, 1.0f);
    if (clip.w <= 0.0f) return 1.0f;
    vec3 ndc = clip.xyz / clip.w;
    if (abs(ndc.x) > 1.0f || abs(ndc.y) > 1.0f) return 1.0f;   // outside every caster's footprint
    float zNear = u_shadowRange[i].y, zFar = u_shadowRange[i].z;
    float receiver = (ortho ? zNear + (0.5f * ndc.z + 0.5f) * (zFar - zNear) : clip.w) - u_shadowBias.x * texel;
    int size = u_shadowInfo.z;
    ivec2 texelAt = clamp(ivec2((0.5f * ndc.xy + 0.5f) * float(size)), ivec2(0), ivec2(size - 1));
    int radius = u_shadowInfo.y != 0 ? 1 : 0;
    float lit = 0.0f, taps = 0.0f;
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x) {
            ivec2 q = clamp(texelAt + ivec2(x, y), ivec2(0), ivec2(size - 1));
            float d = texelFetch(t_shadowMaps, ivec3(q, layer), 0).r;
            lit += (d >= 1.0f || receiver <= linearShadowDepth(d, ortho, zNear, zFar)) ? 1.0f : 0.0f;
            taps += 1.0f;
        }
    return lit / taps;
}

// vis_l for light i at P (Nf: the unit normal facing the viewer), as the tracer's one shadow ray.
float shadowVisibility(int i, vec3 P, vec3 Nf) {
    if (i >= SL_MAX_SHADOWED) return 1.0f;
    bool isPoint = u_lightPos[i].w != 0.0f;
    vec3 origin = P + u_shadowBias.z * Nf;
    vec3 toLight = isPoint ? u_lightPos[i].xyz - origin : -u_lightPos[i].xyz;
    float tMax = isPoint ? length(toLight) : 3.4e38f;
    if (planeVisibility(origin, normalize(toLight), tMax) == 0.0f) return 0.0f;
    return mapVisibility(i, P, Nf, u_lightPos[i].xyz);
}
