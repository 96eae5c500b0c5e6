// One triangle covering the whole viewport, from gl_VertexID alone (no vertex buffer): the full-screen passes
// (display, accumulation, partial-redraw merge, environment backdrop).
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(2.0f * p - 1.0f, 0.0f, 1.0f);
}
