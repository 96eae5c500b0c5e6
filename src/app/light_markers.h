// Lights in the view: where each light's marker is drawn on the image, which marker the pointer
// is on, and where a light goes when its marker is dragged. Plain geometry over the scene's camera (the
// same ViewSetup both renderers use), with no GL or ImGui, so tests check it without a window.
//   point light:        a disc at its position.
//   directional light:  a disc at its "source", a point up-light of the scene's centre at 1.2 times the
//                       scene's radius (-direction side), with an arrow toward the centre.
// Dragging moves a point light in the plane through it that faces the camera. A directional light's source
// slides over its sphere (centre, 1.2 R) to the point under the pointer nearest its last place, and the
// light then points from there to the scene's centre.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace shadelab::app {

struct LightMarker {
    int light = 0;             // index into scene.lights
    bool visible = false;      // drawn: always, a light behind the camera at the edge toward it
    glm::vec3 anchor{0.0f};    // world point the marker stands for
    glm::vec2 pixel{0.0f};     // image pixels (x right, y down, pixel centres at .5)
    glm::vec2 arrowTip{0.0f};  // directional and spot lights: where the arrow points (image pixels)
    // Where the marker is drawn and grabbed: `pixel`, or for a light outside the image (the default scene's
    // lights are above the frame), the nearest point kMarkerInset pixels inside the image's edge.
    glm::vec2 shown{0.0f};
    bool clamped = false;
    // Spot lights: the rim of the outer cone where the arrow ends (image pixels, a closed loop), so the class
    // sees where the light falls; empty for other lights, a light off the image, or a rim partly behind the eye.
    std::vector<glm::vec2> coneRim;
};

inline constexpr float kMarkerInset = 14.0f;

std::vector<LightMarker> lightMarkers(const Scene& scene, int width, int height);
// The light whose visible marker (as shown) lies within `radius` pixels of `pixel`, the nearest; -1 when none.
int markerAt(const std::vector<LightMarker>& markers, glm::vec2 pixel, float radius);
// Light `index` after its marker is dragged to `pixel` of a width x height image.
Light draggedLight(const Scene& scene, int width, int height, int index, glm::vec2 pixel);
// The spot light whose arrow tip (a marker in the frame) lies within `radius` pixels of `pixel`, the nearest; -1
// when none. Grabbing the tip aims the spot, grabbing the disc moves it.
int aimHandleAt(const Scene& scene, const std::vector<LightMarker>& markers, glm::vec2 pixel, float radius);
// Spot light `index` aimed at the point under `pixel` in the plane through its arrow's tip that faces the camera.
Light aimedSpot(const Scene& scene, int width, int height, int index, glm::vec2 pixel);

}  // namespace shadelab::app
