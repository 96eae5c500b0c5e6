// Partial redraw (src/raster/raster_renderer.cpp redrawPart): copies the redrawn objects' pixels into the image
// where its coverage shows one of them, and keeps every other pixel. Not a blend: a copy, bit for bit.
uniform sampler2D t_partial;    // RGBA32F, the redrawn objects over a copy of the image's depth
uniform usampler2D t_coverage;  // R32UI, the image's coverage ids
uniform uint u_ids[8];          // raster_limits.h kMaxPartialIds
uniform int u_idCount;

layout(location = 0) out vec4 o_color;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    uint id = texelFetch(t_coverage, texel, 0).r;
    bool redrawn = false;
    for (int i = 0; i < 8; ++i) redrawn = redrawn || (i < u_idCount && id == u_ids[i]);
    if (!redrawn) discard;
    o_color = texelFetch(t_partial, texel, 0);
}
