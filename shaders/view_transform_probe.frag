// Shader-unit test kernel (tests/shader_unit_test.cpp): runs the viewer's exposure and view transform
// (view_transform.glsl, as view_image.frag does) on the linear values stored one per texel channel, so the
// GPU's results can be read back and compared with the C++ of src/image/encode.cpp (displayValue).
#include "view_transform.glsl"

uniform sampler2D t_in;     // rgb: three linear values per texel
uniform float u_exposure;   // 2^stops, as image_view.cpp sets it
uniform int u_transform;    // SL_VIEW_STANDARD or SL_VIEW_FILMIC

layout(location = 0) out vec4 o_result;

void main() {
    vec3 c = texelFetch(t_in, ivec2(gl_FragCoord.xy), 0).rgb;
    o_result = vec4(viewChannel(c.r, u_exposure, u_transform), viewChannel(c.g, u_exposure, u_transform),
                    viewChannel(c.b, u_exposure, u_transform), 1.0f);
}
