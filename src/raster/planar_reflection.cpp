// Planar reflection: mirror matrix and mirrored frame block.
#include "raster/planar_reflection.h"

#include <glm/geometric.hpp>

namespace shadelab::raster {

glm::mat4 mirrorMatrix(const glm::vec3& n, float offset) {
    glm::mat4 m(1.0f);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] -= 2.0f * n[r] * n[c];
    m[3] = glm::vec4(2.0f * offset * n, 1.0f);
    return m;
}

std::optional<FrameBlock> mirroredFrame(const FrameBlock& frame, const Plane& plane) {
    const glm::vec3 n = plane.normal;
    const float side = glm::dot(n, glm::vec3(frame.eye)) - plane.offset;
    if (side == 0.0f) return std::nullopt;
    const glm::mat4 m = mirrorMatrix(n, plane.offset);
    FrameBlock f = frame;
    f.viewProj = frame.viewProj * m;
    f.eye = m * frame.eye;
    f.forward = m * frame.forward;  // w = 0: directions are mirrored without the translation
    f.right = m * frame.right;
    f.up = m * frame.up;
    const float s = side > 0.0f ? 1.0f : -1.0f;
    f.clipPlane = glm::vec4(s * n, -s * plane.offset);
    f.flags.w &= ~kPassMirrors;
    return f;
}

bool isMirror(const Scene& scene, const Plane& plane) {
    const glm::vec3& kr = plane.material.kr;
    return scene.terms.reflections && (kr.x > 0.0f || kr.y > 0.0f || kr.z > 0.0f);
}

}  // namespace shadelab::raster
