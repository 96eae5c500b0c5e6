#include "app/probe_window_place.h"

#include <algorithm>
#include <glm/common.hpp>

namespace shadelab::app {

namespace {

ProbeWindowPlace place(const ProbeWindowSpace& space, glm::vec2 size, float c) {
    const glm::vec2 lo = space.visibleMin, hi = space.visibleMax, p = space.point;
    // Where a window of `size` may start so as to lie inside, per axis (max < min: it does not fit that axis).
    const glm::vec2 firstTopLeft = lo, lastTopLeft = hi - size;
    auto inside = [&](glm::vec2 at) {
        return at.x >= lo.x && at.y >= lo.y && at.x + size.x <= hi.x && at.y + size.y <= hi.y;
    };
    // Along the free axis, centred on the point as far as the image allows.
    const float alongY = std::clamp(p.y - 0.5f * size.y, firstTopLeft.y, std::max(firstTopLeft.y, lastTopLeft.y));
    const float alongX = std::clamp(p.x - 0.5f * size.x, firstTopLeft.x, std::max(firstTopLeft.x, lastTopLeft.x));
    const glm::vec2 candidates[] = {
        {p.x + c, alongY},           // right
        {p.x - c - size.x, alongY},  // left
        {alongX, p.y + c},           // below
        {alongX, p.y - c - size.y},  // above
    };
    for (const glm::vec2& at : candidates)
        if (inside(at)) return {at, true};
    // No side has room: the side with most of it, pulled inside as far as the size allows.
    const float room[] = {hi.x - (p.x + c), (p.x - c) - lo.x, hi.y - (p.y + c), (p.y - c) - lo.y};
    const int best = int(std::max_element(room, room + 4) - room);
    glm::vec2 at = candidates[best];
    at = glm::max(glm::min(at, lastTopLeft), firstTopLeft);
    return {at, false};
}

}  // namespace

ProbeWindowPlace placeProbeWindow(const ProbeWindowSpace& space, glm::vec2 size) {
    const ProbeWindowPlace clear = place(space, size, space.clearance);
    if (clear.fits || space.minClearance >= space.clearance) return clear;
    const ProbeWindowPlace near = place(space, size, space.minClearance);
    return near.fits ? near : clear;
}

}  // namespace shadelab::app
