// Sphere impostor proxy. sphere.frag shades every fragment it gets, and llvmpipe runs the whole shader even
// for the fragments it discards (a miss), so the proxy should cover little more than the sphere's outline.
// Seen from outside, it is an octagon around the silhouette: the cone from the eye tangent to the sphere
// touches it along a circle, and any polygon in that circle's plane that contains the circle covers every
// pixel whose ray hits the sphere (the octagon covers about 1.1 times the outline's area; the bounding cube
// about 2 to 2.5 times). Where that cannot be trusted (the eye inside or near the sphere, the sphere not wholly
// between the near and far planes) it is the sphere's bounding cube, back faces only, as before: it covers
// the footprint from outside and inside alike. Either way the fragments are the same ray casts, so the image
// does not change; only the fragments that miss are fewer.
#include "frame.glsl"

layout(location = 0) in vec3 a_position;   // unit cube corner in [-1, 1]^3 (36 vertices)

uniform vec3 u_center;
uniform float u_radius;

const float SL_OCTAGON = 1.0823922f;   // 1 / cos(pi/8): an octagon's corner radius over its inradius
const float SL_PROXY_MARGIN = 1.02f;   // the octagon is this much wider than the silhouette

// Whether a point lies strictly in front of the eye and between the near and far planes.
bool insideDepthRange(vec3 p) {
    vec4 c = u_viewProj * vec4(p, 1.0f);
    return c.w > 0.0f && c.z >= -c.w && c.z <= c.w;
}

void main() {
    vec3 d = u_center - u_eye.xyz;
    float D2 = dot(d, d);
    float r2 = u_radius * u_radius;
    // The silhouette circle: centre and radius, and a basis of its plane (normal d).
    vec3 n = d * inversesqrt(max(D2, 1e-30f));
    vec3 c = u_eye.xyz + (1.0f - r2 / max(D2, 1e-30f)) * d;
    float rho = u_radius * sqrt(max(1.0f - r2 / max(D2, 1e-30f), 0.0f)) * SL_OCTAGON * SL_PROXY_MARGIN;
    vec3 a = normalize(abs(n.x) < 0.9f ? cross(n, vec3(1.0f, 0.0f, 0.0f)) : cross(n, vec3(0.0f, 1.0f, 0.0f)));
    vec3 b = cross(n, a);
    bool octagon = D2 > 1.21f * r2;  // the eye at least 1.1 radii from the centre
    for (int k = 0; k < 8 && octagon; ++k) {
        float angle = 0.78539816f * float(k);
        octagon = insideDepthRange(c + rho * (cos(angle) * a + sin(angle) * b));
    }
    for (int k = 0; k < 8 && octagon; ++k) {
        vec3 corner = vec3(k % 2 == 0 ? -1.0f : 1.0f, (k / 2) % 2 == 0 ? -1.0f : 1.0f, k / 4 == 0 ? -1.0f : 1.0f);
        octagon = insideDepthRange(u_center + u_radius * corner);
    }
    if (!octagon) {
        gl_Position = u_viewProj * vec4(u_center + u_radius * a_position, 1.0f);
        return;
    }
    // Six triangles fanned from corner 0 (vertices 0..17), wound to face away from the eye like the cube's
    // back faces, so front-face culling keeps them; vertices 18..35 collapse onto corner 0 (no area).
    int v = gl_VertexID;
    int corner = v >= 18 ? 0 : v % 3 == 0 ? 0 : (v / 3) + (v % 3);
    float angle = 0.78539816f * float(corner);
    gl_Position = u_viewProj * vec4(c + rho * (cos(angle) * a + sin(angle) * b), 1.0f);
}
