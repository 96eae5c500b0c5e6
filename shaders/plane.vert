// Infinite plane: its footprint is the part of the viewport where the camera's rays can hit it
// (src/raster/plane_footprint.h: the viewport clipped at the horizon, with a margin), a convex polygon drawn
// as a fan from gl_VertexID alone; plane.frag casts each pixel's ray, discards the rays that miss the plane
// and writes the hit's depth. No vertex lies on the plane, so none is clipped: the scene-fitted near plane
// (scene/view.cpp) would cut away the floor under a low camera, and vertices at infinity (w = 0) rasterize
// differently from one implementation to the next.
uniform vec2 u_planeFan[5];  // normalised device coordinates; triangle k is corners 0, k + 1, k + 2

void main() {
    int k = gl_VertexID / 3, corner = gl_VertexID - 3 * k;
    gl_Position = vec4(u_planeFan[corner == 0 ? 0 : k + corner], 0.0f, 1.0f);
}
