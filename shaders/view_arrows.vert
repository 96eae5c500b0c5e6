// Probe arrows (src/app/arrow_overlay.cpp): each vertex lies on a 3D segment base→tip and is pushed
// sideways and back by a fixed number of pixels in screen space, so arrows keep their width at any zoom.
layout(location = 0) in vec3 a_base;     // world units
layout(location = 1) in vec3 a_tip;      // world units
layout(location = 2) in vec3 a_where;    // x: 0 at base, 1 at tip; yz: offset in pixels along, across
layout(location = 3) in vec3 a_color;

uniform mat4 u_viewProj;
uniform vec2 u_viewport;                 // pixels

out vec3 v2f_color;

void main() {
    vec4 b = u_viewProj * vec4(a_base, 1.0f);
    vec4 t = u_viewProj * vec4(a_tip, 1.0f);
    vec2 bs = (b.xy / b.w * 0.5f + 0.5f) * u_viewport;
    vec2 ts = (t.xy / t.w * 0.5f + 0.5f) * u_viewport;
    vec2 along = ts - bs;
    along = length(along) > 1e-3f ? normalize(along) : vec2(1.0f, 0.0f);
    vec2 across = vec2(-along.y, along.x);
    vec2 p = mix(bs, ts, a_where.x) + a_where.y * along + a_where.z * across;
    gl_Position = vec4(p / u_viewport * 2.0f - 1.0f, 0.0f, 1.0f);
    v2f_color = a_color;
}
