// Frustum culling of world boxes against a clip space (colour, mirror and shadow-map passes).
#include "raster/draw_range.h"

#include <glm/vec4.hpp>

namespace shadelab::raster {

bool outsideClip(const glm::mat4& viewProj, const glm::vec3& lo, const glm::vec3& hi) {
    int outside[5] = {0, 0, 0, 0, 0};
    for (int c = 0; c < 8; ++c) {
        glm::vec4 p = viewProj * glm::vec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0f);
        outside[0] += p.x < -p.w;
        outside[1] += p.x > p.w;
        outside[2] += p.y < -p.w;
        outside[3] += p.y > p.w;
        outside[4] += p.z < -p.w;
    }
    for (int n : outside)
        if (n == 8) return true;
    return false;
}

}  // namespace shadelab::raster
