// Node transforms and primitive topology for the glTF importer (gltf_import.cpp): see gltf_geometry.h.
#include "scene/gltf/gltf_geometry.h"

#include "util/input_error.h"

#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace shadelab {

// ---------------------------------------------------------------------------------------------------------
// 1. Node transforms (glTF 2.0 spec, "Transformations": matrix, or T * R * S)
// ---------------------------------------------------------------------------------------------------------

namespace {

const glm::vec3 kFallbackNormal{0.0f, 1.0f, 0.0f};  // for vertices whose faces have no area

bool allFinite(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

glm::dmat4 localMatrix(const tinygltf::Node& node, const std::string& place, const std::string& file,
                       std::vector<std::string>& warnings) {
    auto check = [&](const std::vector<double>& v, size_t n, const char* name) {
        if (!v.empty() && v.size() != n)
            throw InputError(file, place, std::string(name) + " must have " + std::to_string(n) + " numbers");
        if (!allFinite(v)) throw InputError(file, place, std::string(name) + " has a non-finite value");
    };
    check(node.matrix, 16, "matrix");
    check(node.translation, 3, "translation");
    check(node.rotation, 4, "rotation");
    check(node.scale, 3, "scale");
    if (!node.matrix.empty()) return glm::make_mat4(node.matrix.data());  // column-major, as glTF stores it

    glm::dmat4 m(1.0);
    if (!node.translation.empty())
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (!node.rotation.empty()) {
        const auto& r = node.rotation;  // glTF order x, y, z, w; glm's constructor takes w first
        glm::dquat q(r[3], r[0], r[1], r[2]);
        const double len = glm::length(q);
        if (len > 1e-12)
            m *= glm::mat4_cast(q / len);
        else
            warnings.push_back(place + ": zero rotation quaternion treated as identity");
    }
    if (!node.scale.empty()) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// Normals transform by the inverse transpose (Turkowski 1990, "Properties of surface-normal transformations").
// The cofactor matrix is det(M)·M^-T; scaling it by sign(det) keeps the inverse transpose's orientation
// and stays defined when M is singular (a zero scale flattens normals instead of failing).
glm::mat3 normalMatrix(const glm::dmat3& m) {
    const glm::dmat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
    return glm::mat3(glm::determinant(m) < 0.0 ? -cofactor : cofactor);
}

// ---------------------------------------------------------------------------------------------------------
// 2. Primitives
// ---------------------------------------------------------------------------------------------------------

// glTF 2.0 spec, "Meshes" (primitive topology): strip triangle i is (i, i+1+i%2, i+2-i%2); fan triangle i is
// (i+1, i+2, 0). Returns how many trailing indices of a TRIANGLES list formed no whole triangle.
size_t triangulate(int mode, const std::vector<uint32_t>& v, std::vector<uint32_t>& out) {
    const size_t n = v.size();
    out.clear();
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        if (n < 3) return n;
        out.reserve(3 * (n - 2));
        for (size_t i = 0; i + 2 < n; ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
                out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
            else
                out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
        }
        return 0;
    }
    out.assign(v.begin(), v.begin() + std::ptrdiff_t(n / 3 * 3));
    return n % 3;
}

// Area-weighted vertex normals: each triangle adds its unnormalised cross product (twice its area) to its
// three vertices. Unshared vertices (non-indexed data) therefore get flat face normals.
void generateNormals(const MeshGeometry& g, std::vector<glm::vec3>& out) {
    out.assign(g.positions.size(), glm::vec3(0.0f));
    const auto& p = g.positions;
    for (size_t t = 0; t + 2 < g.indices.size(); t += 3) {
        const uint32_t a = g.indices[t], b = g.indices[t + 1], c = g.indices[t + 2];
        const glm::vec3 n = glm::cross(p[b] - p[a], p[c] - p[a]);
        out[a] += n;
        out[b] += n;
        out[c] += n;
    }
    for (glm::vec3& n : out) {
        const float len2 = glm::dot(n, n);
        n = len2 > 0.0f && std::isfinite(len2) ? n / std::sqrt(len2) : kFallbackNormal;
    }
}

}  // namespace shadelab
