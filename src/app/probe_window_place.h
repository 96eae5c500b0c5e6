// Where the probe window goes: inside the part of the image the panel leaves visible, and never over the
// probed point or the arrows drawn around it. Plain geometry in window units, no ImGui, so tests check the
// rule without a window.
#pragma once

#include <glm/vec2.hpp>

namespace shadelab::app {

struct ProbeWindowSpace {
    glm::vec2 visibleMin{0.0f}, visibleMax{0.0f};  // the visible image, minus its margin
    glm::vec2 point{0.0f};                         // the probed point
    float clearance = 0.0f;     // half the side of the square kept clear around it: the point and its arrows
    float minClearance = 0.0f;  // when no side has room for that: the point alone
};

struct ProbeWindowPlace {
    glm::vec2 topLeft{0.0f};
    // Whether the window fits beside the point inside the visible image. When it does not (a window larger
    // than any side of the point leaves), it goes on the side with most room, inside the image as far as its
    // size allows, and the caller folds it to its title bar.
    bool fits = false;
};

// Tries right of the point, left, below, then above (each as near the point's row or column as the image
// allows), and takes the first where the window lies inside the visible image clear of the point's square;
// then the same with the smaller square (the arrows may be covered, the point never).
ProbeWindowPlace placeProbeWindow(const ProbeWindowSpace& space, glm::vec2 size);

}  // namespace shadelab::app
