// Texture sampling for glTF materials (design.md §9), written once in the subset of GLSL that is also C++
// with GLM (the rules of lighting.glsl). The includer provides three hooks: texTexel(map, level, x, y), the
// linear RGBA texel (x, y) of mip level `level` of map `map` (GLSL: texelFetch), and texWidth(map, level),
// texHeight(map, level). C++ reads the scene's texel arrays (src/shading/texture_sample.h). Every filter is
// done here by hand, so both renderers weigh the same texels with the same weights.
//
// Coordinates: glTF's (u, v), v = 0 at the image's top row, which is texel row 0 of level 0.
// Wrap modes: 0 repeat, 1 mirrored repeat, 2 clamp to edge (TextureWrap in src/scene/texture.h, in order).
// Level selection: lod = log2 of the larger footprint axis in level-0 texels (the OpenGL 4.6 spec's ρ,
// §8.14.1, without anisotropy); then texSample's rules, which are OpenGL's.

// The level-of-detail for footprint derivatives dx, dy of (u, v) per pixel step, at level-0 size w × h.
SL_FN float texLod(int w, int h, vec2 dx, vec2 dy) {
    vec2 a = dx * vec2(float(w), float(h));
    vec2 b = dy * vec2(float(w), float(h));
    float rho2 = max(dot(a, a), dot(b, b));
    return 0.5f * log2(max(rho2, 1e-20f));
}

// KHR_texture_transform: uv' = R·S·uv + offset, m = (R·S) row by row (TextureBinding::uvMatrix). Affine, so
// transforming the interpolated coordinate equals interpolating transformed ones, derivatives included.
SL_FN vec2 texTransform(vec2 uv, vec4 m, vec2 offset) {
    return vec2(m.x * uv.x + m.y * uv.y, m.z * uv.x + m.w * uv.y) + offset;
}

// Folds coordinate c (in units of the texture's extent) into the wrap mode's base period: [0, 1) for repeat,
// [0, 2) for mirrored repeat, [0, 1] for clamp. Done in float so no integer % sees a negative operand. A
// coordinate that is not finite (a texture transform that overflows, or inf − inf) folds to 0: NaN fails
// every comparison, so the range test below, not the arithmetic, decides, and the texel index that follows
// can never leave the image.
SL_FN float texFold(float c, int mode) {
    if (mode == 2) return c >= 1.0f ? 1.0f : (c > 0.0f ? c : 0.0f);
    float period = mode == 1 ? 2.0f : 1.0f;
    float f = mode == 1 ? c - 2.0f * floor(0.5f * c) : c - floor(c);
    return f >= 0.0f && f < period ? f : 0.0f;
}

// Texel index i (which texFold's coordinate puts in [-1, n] for repeat and clamp, [-1, 2n] for mirrored)
// mapped into [0, n).
SL_FN int texIndex(int i, int n, int mode) {
    if (mode == 0) return i < 0 ? i + n : (i >= n ? i - n : i);
    if (mode == 1) {
        int m = i < 0 ? i + 2 * n : (i >= 2 * n ? i - 2 * n : i);
        return m < n ? m : 2 * n - 1 - m;
    }
    return clamp(i, 0, n - 1);
}

SL_FN vec4 texFetchWrapped(int map, int level, int x, int y, int w, int h, int wrapS, int wrapT) {
    return texTexel(map, level, texIndex(x, w, wrapS), texIndex(y, h, wrapT));
}

// One level, nearest or bilinear (texel centres at half-integers, as OpenGL). One code path for both:
// nearest is the bilinear form with weights 0 (mix(a, b, 0) is a exactly), since llvmpipe runs every branch
// of non-uniform control flow, and two paths would fetch twice as many texels.
SL_FN vec4 texSampleLevel(int map, int level, bool linear, int wrapS, int wrapT, vec2 uv) {
    int w = texWidth(map, level);
    int h = texHeight(map, level);
    float shift = linear ? 0.5f : 0.0f;
    float fx = texFold(uv.x, wrapS) * float(w) - shift;
    float fy = texFold(uv.y, wrapT) * float(h) - shift;
    int ix = int(floor(fx));
    int iy = int(floor(fy));
    float tx = linear ? fx - float(ix) : 0.0f;
    float ty = linear ? fy - float(iy) : 0.0f;
    vec4 a = mix(texFetchWrapped(map, level, ix, iy, w, h, wrapS, wrapT),
                 texFetchWrapped(map, level, ix + 1, iy, w, h, wrapS, wrapT), tx);
    vec4 b = mix(texFetchWrapped(map, level, ix, iy + 1, w, h, wrapS, wrapT),
                 texFetchWrapped(map, level, ix + 1, iy + 1, w, h, wrapS, wrapT), tx);
    return mix(a, b, ty);
}

// The filtered texel at `uv` for level-of-detail `lod` (texLod), under the sampler's modes, as the OpenGL 4.6
// spec §8.14 states them: minification from lod > c, c = 0.5 when the mag filter is bilinear and the min filter
// nearest (else 0); between levels the nearest level (ceil(lod + 0.5) − 1) or a linear blend of levels
// floor(lod) and floor(lod) + 1 (mipLinear), each clamped to the chain. Always two level reads blended by t
// (t = 0 and one level twice where a single level is meant), for the reason texSampleLevel gives.
SL_FN vec4 texSample(int map, int levels, int wrapS, int wrapT, bool magLinear, bool minLinear, bool mipmaps,
                     bool mipLinear, vec2 uv, float lod) {
    float c = magLinear && !minLinear ? 0.5f : 0.0f;
    bool minify = lod > c;
    int l0 = 0;
    int l1 = 0;
    float t = 0.0f;
    if (minify && mipmaps) {
        float top = float(levels - 1);
        if (!mipLinear) {
            l0 = lod <= 0.5f ? 0 : int(min(ceil(lod + 0.5f) - 1.0f, top));
            l1 = l0;
        } else {
            float l = min(lod, top);
            l0 = int(floor(l));
            l1 = min(l0 + 1, levels - 1);
            t = l - float(l0);
        }
    }
    bool linear = minify ? minLinear : magLinear;
    vec4 a = texSampleLevel(map, l0, linear, wrapS, wrapT, uv);
    vec4 b = texSampleLevel(map, l1, linear, wrapS, wrapT, uv);
    return mix(a, b, t);
}
