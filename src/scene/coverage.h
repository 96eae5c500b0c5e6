// Coverage ids (design.md §4): which object a pixel shows. 0 is the background; then spheres, planes and
// meshes in scene order, counting from 1. Both renderers write these ids.
#pragma once

#include "scene/scene.h"

#include <cstdint>

namespace shadelab {

inline constexpr uint32_t kBackgroundId = 0;

inline uint32_t sphereCoverageId(const Scene&, size_t i) { return uint32_t(1 + i); }
inline uint32_t planeCoverageId(const Scene& s, size_t i) { return uint32_t(1 + s.spheres.size() + i); }
inline uint32_t meshCoverageId(const Scene& s, size_t i) {
    return uint32_t(1 + s.spheres.size() + s.planes.size() + i);
}

}  // namespace shadelab
