// Texel-decoding test kernel (tests/texel_decode_test.cpp): level u_level of t_texel at this pixel, read with
// texelFetch as mesh.frag reads material maps, so the floats can be compared with the tracer's.
uniform sampler2D t_texel;
uniform int u_level;

layout(location = 0) out vec4 o_result;

void main() { o_result = texelFetch(t_texel, ivec2(gl_FragCoord.xy), u_level); }
