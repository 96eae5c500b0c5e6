// Infinite plane: its footprint is the part of the viewport its pass must cover (src/raster/plane_footprint.h:
// the viewport clipped at the horizon, less the inside of spheres standing in front of the plane, with margins),
// triangles in normalised device coordinates; plane.frag casts each pixel's ray, discards the rays that miss
// the plane and writes the hit's depth. No vertex lies on the plane, so none is clipped: the scene-fitted near
// plane (scene/view.cpp) would cut away the floor under a low camera, and vertices at infinity (w = 0)
// rasterize differently from one implementation to the next.
layout(location = 0) in vec2 a_ndc;

void main() {
    gl_Position = vec4(a_ndc, 0.0f, 1.0f);
}
