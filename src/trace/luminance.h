// Relative luminance of linear RGB (Rec. 709 / sRGB primaries, ITU-R BT.709 weights): the path tracer's
// one measure of "how much light" for picking lobes and emitters and for Russian roulette.
#pragma once

#include <glm/vec3.hpp>

namespace shadelab::trace {

inline float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

}  // namespace shadelab::trace
