// PlaneFootprint: the part of a viewport where the camera's rays can hit an infinite plane, so that the plane's
// pass covers that polygon instead of the whole viewport. plane.frag casts every covered pixel's ray and discards
// those that miss; on llvmpipe a discarded fragment still costs its ray, so the sky above a floor's horizon was
// shaded for nothing. The polygon is conservative: every pixel whose ray hits the plane lies inside it (with a
// margin for the GPU's rounding), so the picture is the same bit for bit. Pure: no GL.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab::raster {

// The camera as the frame block gives it to fragmentRay() (shaders/surface.glsl): position, basis (forward
// already moved by the jitter), and `viewport` = (full image width, height, tan(fovY/2), GL row of this band's
// bottom in the full image).
struct PlaneCamera {
    glm::vec3 eye, forward, right, up;
    glm::vec4 viewport;
};

struct PlaneFootprint {
    int count = 0;           // corners: 0 (no pixel can hit the plane), else 3 to 5
    glm::vec2 corners[5]{};  // normalised device coordinates, convex, in order (a triangle fan from corners[0])
};

// The footprint on a viewport of `width` x `height` pixels of the plane dot(n, P) = offset (n unit), grown by
// `marginPixels` beyond the pixels whose rays hit it. Where the camera lies (nearly) on the plane, the whole
// viewport.
PlaneFootprint planeFootprint(const PlaneCamera& camera, int width, int height, const glm::vec3& n, float offset,
                              float marginPixels = 2.0f);

}  // namespace shadelab::raster
