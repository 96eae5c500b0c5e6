// PlaneFootprint: the part of a viewport an infinite plane's pass must cover, as triangles. plane.frag casts every
// covered pixel's ray and discards those that miss; on llvmpipe a discarded fragment still costs its ray, and a
// fragment hidden behind a sphere drawn before the plane costs its whole shading (the plane writes its exact
// depth, so it is depth-tested after shading). So the pass covers the viewport clipped to where rays can hit the
// plane, less the inside of the silhouettes of spheres that stand wholly between the eye and the plane. Both are
// conservative, with margins for the GPU's rounding: every pixel whose fragment could show the plane is still
// covered, so the picture is the same bit for bit. Pure: no GL.
#pragma once

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace shadelab::raster {

// The camera as the frame block gives it to fragmentRay() (shaders/surface.glsl): position, basis (forward
// already moved by the jitter), `viewport` = (full image width, height, tan(fovY/2), GL row of this band's
// bottom in the full image), and the view-projection the impostors' depth comes from (depthOf).
struct PlaneCamera {
    glm::vec3 eye, forward, right, up;
    glm::vec4 viewport;
    glm::mat4 viewProj{1.0f};
};

struct PlaneFootprint {
    int count = 0;           // corners: 0 (no pixel can hit the plane), else 3 to 5
    glm::vec2 corners[5]{};  // normalised device coordinates, convex, counter-clockwise
};

// The footprint on a viewport of `width` x `height` pixels of the plane dot(n, P) = offset (n unit), grown by
// `marginPixels` beyond the pixels whose rays hit it. Where the camera lies (nearly) on the plane, the whole
// viewport.
PlaneFootprint planeFootprint(const PlaneCamera& camera, int width, int height, const glm::vec3& n, float offset,
                              float marginPixels = 2.0f);

// A convex polygon of the viewport (normalised device coordinates, counter-clockwise) the plane need not cover.
struct FootprintHole {
    int count = 0;
    glm::vec2 corners[8]{};
};

// The hole a sphere (centre, radius) makes in the plane's footprint: where the sphere stands on the eye's side of
// the plane (resting on it at most), every ray through its silhouette meets the sphere first, with a depth the
// plane's cannot tie. The octagon inscribed in the silhouette, moved `insetPixels` inward; none (count 0) where
// that cannot be trusted (the eye near the sphere, the sphere crossing the plane or the near or far plane, too
// small, or its depth too close to the plane's) or where it is not inside `footprint`.
FootprintHole sphereHole(const PlaneCamera& camera, int width, int height, const glm::vec3& n, float offset,
                         const glm::vec3& centre, float radius, const PlaneFootprint& footprint,
                         float insetPixels = 3.0f);

// Triangles (three corners each, normalised device coordinates) covering `footprint` less the holes. Holes that
// overlap another's bounding box are left out (the larger kept), so the pieces never cross, and so are all but
// the kMaxFootprintHoles largest (a scene of many small spheres would otherwise cut thousands of slabs).
inline constexpr size_t kMaxFootprintHoles = 32;
std::vector<glm::vec2> footprintTriangles(const PlaneFootprint& footprint, std::vector<FootprintHole> holes);

}  // namespace shadelab::raster
