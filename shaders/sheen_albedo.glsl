// The sheen's directional albedo E(N·V, roughness) (shading/sheen_lut.h), bilinear in a table read texel by
// texel through the includer's sheenTexel(x, y), so that the rasterizer filters it exactly as the tracers do.
// Texel (i, j) is computed at N·V = i/(size − 1) and roughness j/(size − 1); clamped at the edges.
SL_FN float sheenAlbedo(int size, float NoV, float roughness) {
    float fx = clamp(NoV, 0.0f, 1.0f) * float(size - 1);
    float fy = clamp(roughness, 0.0f, 1.0f) * float(size - 1);
    int ix = min(int(floor(fx)), size - 2);
    int iy = min(int(floor(fy)), size - 2);
    float tx = fx - float(ix);
    float ty = fy - float(iy);
    float a = mix(sheenTexel(ix, iy), sheenTexel(ix + 1, iy), tx);
    float b = mix(sheenTexel(ix, iy + 1), sheenTexel(ix + 1, iy + 1), tx);
    return mix(a, b, ty);
}

// The cosine the sheen's albedo is read at, from raw N and a direction (V or L): N·D clamped to [0, 1].
SL_FN float sheenCos(vec3 N, vec3 D) {
    return clamp(dot(normalize(N), normalize(D)), 0.0f, 1.0f);
}
