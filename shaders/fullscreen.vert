// One triangle covering the whole viewport, from gl_VertexID alone (no vertex buffer): used by the plane
// impostor and by full-screen passes.
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(2.0f * p - 1.0f, 0.0f, 1.0f);
}
