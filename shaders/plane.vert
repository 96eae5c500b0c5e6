// Infinite plane: its footprint is the whole viewport, one triangle; plane.frag casts each pixel's ray, discards
// the rays that miss the plane (above the horizon) and writes the hit's depth. No vertex lies on the plane, so
// none is clipped: the scene-fitted near plane (scene/view.cpp) would cut away the floor under a low camera,
// and vertices at infinity (w = 0) rasterize differently from one implementation to the next.
#include "fullscreen.vert"
