// Viewer display pass (src/app/image_view.cpp): shows the raster image, the progressive reference, a wipe
// between them, or an amplified difference, encoding linear colour with the sRGB curve (IEC 61966-2-1:
// exact, as src/image/encode.cpp, where 8-bit values are compared; a close fit for display) or not at
// all. The images (not the difference, which compares the raw values) first go through the display's
// exposure and view transform, view_transform.glsl, the text src/image/encode.cpp compiles for the PNGs.
// Draws into the window; never into captures.
// One program per VIEW_MODE (0 raster, 1 traced, 2 split, 3 difference), SRGB (1 or 0) and VIEW_TRANSFORM
// (SL_VIEW_STANDARD or SL_VIEW_FILMIC): llvmpipe runs every branch of a uniform `if`, and this pass covers the
// whole image every frame.
#include "view_transform.glsl"

uniform sampler2D t_raster;     // RGBA32F linear, GL row order
uniform sampler2D t_traced;     // RGBA32F linear, GL row order
uniform sampler2D t_tiles;      // R8, one texel per reference tile (row 0 = top tiles): 1 = rendered
uniform sampler2D t_ramp;       // 256 x 1 RGB8 heat ramp (src/compare/compare_report.h heatRamp)
uniform vec2 u_origin;          // image rectangle in window framebuffer pixels: lower-left corner (GL)
uniform vec2 u_scale;           // image pixels per window pixel
uniform float u_split;          // wipe position in window pixels from u_origin.x
uniform float u_gain;           // difference amplification
uniform float u_tileSize;       // reference tile edge, pixels
uniform float u_exposure;       // 2^stops, DisplaySettings::scale() (1: no exposure)
#if OUTLINE
uniform usampler2D t_coverage;  // R32UI coverage ids of the raster image, GL row order
uniform uint u_selected;        // the selected object's id
#endif

layout(location = 0) out vec4 o_color;

// The exact sRGB curve, as the PNGs (and the difference view, which compares 8-bit values) use.
vec3 encodeExact(vec3 c) {
    c = clamp(c, vec3(0.0f), vec3(1.0f));
#if SRGB
    return mix(12.92f * c, 1.055f * pow(c, vec3(1.0f / 2.4f)) - 0.055f, step(vec3(0.0031308f), c));
#else
    return c;
#endif
}

// The display's exposure and view transform, per channel, as toImage8 applies them.
vec3 display(vec3 c) {
    return vec3(viewChannel(c.r, u_exposure, VIEW_TRANSFORM), viewChannel(c.g, u_exposure, VIEW_TRANSFORM),
                viewChannel(c.b, u_exposure, VIEW_TRANSFORM));
}

// For showing an image: c^(1/2.4) from three square roots (Ian Taylor's fit, chilliant.com), within
// 0.40/255 of the exact curve (one 8-bit step at most, in 12 % of values), about 1 ms less per 720p
// frame on llvmpipe. Screenshots never come from here (they encode the float image exactly).
vec3 encode(vec3 c) {
    c = clamp(c, vec3(0.0f), vec3(1.0f));
#if SRGB
    vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
    return mix(12.92f * c, 0.585122381f * s1 + 0.783140355f * s2 - 0.368262736f * s3, step(vec3(0.0031308f), c));
#else
    return c;
#endif
}

// Whether this texel's reference tile is traced for the current state. A pending tile shows the raster
// image in its place, so the reference refines tile by tile from the raster's picture instead of flashing
// a dimmed stale result on every change.
bool tileDone(ivec2 texel) {
    ivec2 tile = ivec2(vec2(texel.x, textureSize(t_traced, 0).y - 1 - texel.y) / u_tileSize);
    return texelFetch(t_tiles, tile, 0).r > 0.5f;
}

void main() {
    vec2 local = gl_FragCoord.xy - u_origin;
    ivec2 texel = ivec2(local * u_scale);
#if VIEW_MODE == 0
    vec3 c = encode(display(texelFetch(t_raster, texel, 0).rgb));
#elif VIEW_MODE == 1
    vec3 linear = tileDone(texel) ? texelFetch(t_traced, texel, 0).rgb : texelFetch(t_raster, texel, 0).rgb;
    vec3 c = encode(display(linear));
#elif VIEW_MODE == 2
    // One fetch and one encode per pixel: pick the source first (llvmpipe evaluates both sides of a ?:).
    bool traced = local.x >= u_split && tileDone(texel);
    vec3 linear = traced ? texelFetch(t_traced, texel, 0).rgb : texelFetch(t_raster, texel, 0).rgb;
    vec3 c = encode(display(linear));
    if (abs(local.x - u_split) < 1.5f) c = vec3(1.0f, 0.85f, 0.2f);
#else
    vec3 a = floor(encodeExact(texelFetch(t_raster, texel, 0).rgb) * 255.0f + 0.5f);
    vec3 b = floor(encodeExact(texelFetch(t_traced, texel, 0).rgb) * 255.0f + 0.5f);
    vec3 d = abs(a - b);
    float v = min(max(d.r, max(d.g, d.b)) * u_gain, 255.0f);
    vec3 c = texelFetch(t_ramp, ivec2(int(v), 0), 0).rgb;
#endif
#if OUTLINE
    // The selected object's outline: pixels just outside it (2 image pixels), from the raster's coverage.
    ivec2 last = textureSize(t_coverage, 0) - 1;
    if (texelFetch(t_coverage, texel, 0).r != u_selected) {
        bool near = false;
        for (int k = 0; k < 4; ++k) {
            ivec2 offset = k == 0 ? ivec2(2, 0) : k == 1 ? ivec2(-2, 0) : k == 2 ? ivec2(0, 2) : ivec2(0, -2);
            near = near || texelFetch(t_coverage, clamp(texel + offset, ivec2(0), last), 0).r == u_selected;
        }
        if (near) c = vec3(1.0f, 0.55f, 0.1f);
    }
#endif
    o_color = vec4(c, 1.0f);
}
