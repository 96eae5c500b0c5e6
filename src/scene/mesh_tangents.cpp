#include "scene/mesh_tangents.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace shadelab {
namespace {

// A unit vector perpendicular to unit n (Frisvad 2012's branch-free basis, its first vector).
glm::vec3 anyPerpendicular(const glm::vec3& n) {
    const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
    return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

}  // namespace

std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> t(positions.size(), glm::vec3(0.0f)), b(positions.size(), glm::vec3(0.0f));
    for (size_t k = 0; k + 2 < indices.size(); k += 3) {
        const uint32_t i0 = indices[k], i1 = indices[k + 1], i2 = indices[k + 2];
        const glm::vec3 e1 = positions[i1] - positions[i0], e2 = positions[i2] - positions[i0];
        const glm::vec2 d1 = uvs[i1] - uvs[i0], d2 = uvs[i2] - uvs[i0];
        // Lengyel 2001: [e1 e2] = [T B'] · [d1 d2], B' = ∂P/∂v; solved with the (u, v) determinant.
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (!(std::fabs(det) > 1e-20f) || !std::isfinite(det)) continue;
        const float r = 1.0f / det;
        const glm::vec3 T = (e1 * d2.y - e2 * d1.y) * r;
        const glm::vec3 B = -(e2 * d1.x - e1 * d2.x) * r;  // −∂P/∂v: the image's up
        if (!std::isfinite(T.x + T.y + T.z + B.x + B.y + B.z)) continue;
        for (uint32_t i : {i0, i1, i2}) {
            t[i] += T;
            b[i] += B;
        }
    }
    std::vector<glm::vec4> out(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3 n = i < normals.size() ? normals[i] : glm::vec3(0.0f, 0.0f, 1.0f);
        glm::vec3 T = t[i] - n * glm::dot(n, t[i]);  // Gram-Schmidt against the normal
        const float len2 = glm::dot(T, T);
        if (!(len2 > 1e-30f) || !std::isfinite(len2)) {
            out[i] = glm::vec4(anyPerpendicular(n), 1.0f);
            continue;
        }
        T /= std::sqrt(len2);
        out[i] = glm::vec4(T, glm::dot(glm::cross(n, T), b[i]) < 0.0f ? -1.0f : 1.0f);
    }
    return out;
}

}  // namespace shadelab
