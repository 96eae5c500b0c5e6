// Reflective spheres and meshes in the rasterizer (SL_ENVIRONMENT programs): kr ⊙ env(R), where env is the
// cube of the scene rendered from the object's centre (src/raster/environment_cubes.h) and R the mirror
// direction of V about N. An approximation of the tracer's kr ⊙ I(reflected ray): the cube is seen from
// the centre, not from the surface point, so nearby objects are misplaced (docs/lighting.md).
uniform vec3 u_kr;  // t_environment is surface.glsl's (glTF's transmission reads the cube too)

vec3 environmentReflection(vec3 N, vec3 V) {
    vec3 n = normalize(N);
    vec3 v = normalize(V);
    vec3 R = 2.0f * dot(n, v) * n - v;
    return u_kr * texture(t_environment, R).rgb;
}
