// Image-based lighting lookups (split sum, Karis 2013), written once in the subset of GLSL that is also C++
// with GLM (the rules of lighting.glsl): the prefiltered specular cube, the SH9 irradiance, the DFG table.
// The includer provides two texel hooks, iblTexel(x, y) (prefiltered atlas, RGB) and dfgTexel(x, y) (DFG
// table, (A, B)), and cube_face.glsl; GLSL reads them with texelFetch (surface.glsl), C++ from the arrays of
// src/shading/environment_map.h (ibl_lookup.h). Every filter is done here, by hand, so both renderers
// interpolate the same texels with the same weights. Atlas layout: environment_map.h.

// Texels per face side of prefilter level `level` of a cube of `size`: level 0 (the environment itself) at
// full size, the rough levels, which hold a blurred signal, from a quarter of it down, never below 8.
SL_FN int iblFaceSize(int size, int level) {
    return level == 0 ? size : max(size >> (level + 1), 8);
}

// First atlas row of level `level`: the levels above it, each a face plus its one-texel border.
SL_FN int iblLevelRow(int size, int level) {
    int row = 0;
    for (int k = 0; k < level; ++k) row += iblFaceSize(size, k) + 2;
    return row;
}

// Bilinear filter inside one face of one level at face coordinates (x, y) in [-1, 1] (cubeFaceCoords). The
// border texels hold the neighbouring faces' radiance, so no lookup crosses a face and none has a seam.
SL_FN vec3 iblSampleFace(int size, int level, int face, float x, float y) {
    int n = iblFaceSize(size, level);
    float fx = clamp((0.5f * x + 0.5f) * float(n) - 0.5f, -1.0f, float(n));
    float fy = clamp((0.5f * y + 0.5f) * float(n) - 0.5f, -1.0f, float(n));
    int ix = clamp(int(floor(fx)), -1, n - 1);
    int iy = clamp(int(floor(fy)), -1, n - 1);
    float tx = fx - float(ix);
    float ty = fy - float(iy);
    int col = face * (n + 2) + ix + 1;
    int row = iblLevelRow(size, level) + iy + 1;
    vec3 a = mix(iblTexel(col, row), iblTexel(col + 1, row), tx);
    vec3 b = mix(iblTexel(col, row + 1), iblTexel(col + 1, row + 1), tx);
    return mix(a, b, ty);
}

// The environment's rotation about +y (Environment::rotation): world direction d → map direction.
SL_FN vec3 iblRotate(vec3 d, float cosRot, float sinRot) {
    return vec3(cosRot * d.x - sinRot * d.z, d.y, sinRot * d.x + cosRot * d.z);
}

// Prefiltered radiance along map direction R at `roughness`: level roughness·(levels − 1), trilinear between
// the two nearest levels (level l was prefiltered at roughness l / (levels − 1), src/shading/prefilter.h).
SL_FN vec3 iblPrefiltered(int size, int levels, vec3 R, float roughness) {
    int face = cubeFace(R);
    vec3 fc = cubeFaceCoords(R, face);
    float lod = clamp(roughness, 0.0f, 1.0f) * float(levels - 1);
    int l0 = min(int(floor(lod)), levels - 1);
    int l1 = min(l0 + 1, levels - 1);
    vec3 c0 = iblSampleFace(size, l0, face, fc.x, fc.y);
    vec3 c1 = iblSampleFace(size, l1, face, fc.x, fc.y);
    return mix(c0, c1, lod - float(l0));
}

// Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps": the nine
// SH coefficients sh[] already convolved with the clamped cosine and divided by π, so this is E(n)/π, the
// radiance a white Lambertian surface reflects (a uniform environment L gives L).
SL_FN vec3 iblIrradianceSH(vec3 sh[9], vec3 n) {
    vec3 e = sh[0] * 0.282095f;
    e = e + sh[1] * (0.488603f * n.y) + sh[2] * (0.488603f * n.z) + sh[3] * (0.488603f * n.x);
    e = e + sh[4] * (1.092548f * n.x * n.y) + sh[5] * (1.092548f * n.y * n.z);
    e = e + sh[6] * (0.315392f * (3.0f * n.z * n.z - 1.0f)) + sh[7] * (1.092548f * n.x * n.z);
    e = e + sh[8] * (0.546274f * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0f));
}

// DFG table (A, B) at (N·V, roughness), bilinear, clamped at the edges; `size` texels per side, texel (i, j)
// computed at N·V = i/(size − 1) and roughness j/(size − 1), so both ends are nodes (dfg_lut.h).
SL_FN vec2 iblDFG(int size, float NoV, float roughness) {
    float fx = clamp(NoV, 0.0f, 1.0f) * float(size - 1);
    float fy = clamp(roughness, 0.0f, 1.0f) * float(size - 1);
    int ix = min(int(floor(fx)), size - 2);
    int iy = min(int(floor(fy)), size - 2);
    float tx = fx - float(ix);
    float ty = fy - float(iy);
    vec2 a = mix(dfgTexel(ix, iy), dfgTexel(ix + 1, iy), tx);
    vec2 b = mix(dfgTexel(ix, iy + 1), dfgTexel(ix + 1, iy + 1), tx);
    return mix(a, b, ty);
}

// The direction a pbr surface's specular environment lookup reads: V mirrored about N, 2N(N·V) − V
// (design.md §1's reflected direction), from raw N and V normalised here in one order for both renderers.
SL_FN vec3 iblReflect(vec3 N, vec3 V) {
    vec3 n = normalize(N);
    vec3 v = normalize(V);
    return normalize(2.0f * dot(n, v) * n - v);
}

// N·V for the DFG lookups (IBL and energy compensation), from raw N and V, kept above 0 as specularGGX does.
SL_FN float iblNoV(vec3 N, vec3 V) {
    return max(dot(normalize(N), normalize(V)), 1e-4f);
}
