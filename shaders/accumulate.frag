// Viewer accumulation pass (src/app/accumulation.cpp): copies one jittered raster sample into the running
// average, which the fixed-function blend forms as src·(1/n) + dst·(1 − 1/n) with a constant alpha of 1/n.
uniform sampler2D t_sample;  // RGBA32F linear, the raster target, same size as the accumulation target

layout(location = 0) out vec4 o_color;

void main() {
    o_color = texelFetch(t_sample, ivec2(gl_FragCoord.xy), 0);
}
