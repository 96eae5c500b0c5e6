// trace_bench's scale model: a grid of n x n UV spheres of 4,096 triangles each, built in memory
// (tools/make_sphere_grid_glb.py writes a grid like it as a .glb for the CLI).
#pragma once

#include "scene/scene.h"

#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <utility>

namespace shadelab::bench {

// A UV sphere of 64 slices and 33 stacks: 2 x 64 cap triangles + 31 x 64 x 2 band triangles = 4,096.
inline MeshGeometry uvSphere(glm::vec3 c, float radius) {
    constexpr int kSlices = 64, kStacks = 33;
    MeshGeometry g;
    g.positions.push_back(c + glm::vec3(0, radius, 0));
    g.normals.emplace_back(0, 1, 0);
    for (int i = 1; i < kStacks; ++i) {
        const float theta = 3.14159265358979f * float(i) / float(kStacks);
        for (int j = 0; j < kSlices; ++j) {
            const float phi = 6.28318530718f * float(j) / float(kSlices);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            g.positions.push_back(c + radius * n);
            g.normals.push_back(n);
        }
    }
    g.positions.push_back(c - glm::vec3(0, radius, 0));
    g.normals.emplace_back(0, -1, 0);
    const uint32_t south = uint32_t(g.positions.size() - 1);
    auto ring = [](int i, int j) { return uint32_t(1 + (i - 1) * kSlices + (j % kSlices)); };
    for (int j = 0; j < kSlices; ++j) g.indices.insert(g.indices.end(), {0u, ring(1, j + 1), ring(1, j)});
    for (int i = 1; i < kStacks - 1; ++i)
        for (int j = 0; j < kSlices; ++j) {
            const uint32_t a = ring(i, j), b = ring(i, j + 1), cc = ring(i + 1, j), d = ring(i + 1, j + 1);
            g.indices.insert(g.indices.end(), {a, b, d, a, d, cc});
        }
    for (int j = 0; j < kSlices; ++j)
        g.indices.insert(g.indices.end(), {south, ring(kStacks - 1, j), ring(kStacks - 1, j + 1)});
    return g;
}

// n x n spheres of radius 0.45 on a unit grid in the z = 0 plane, each its own mesh (as a glTF file with one
// mesh per sphere imports), seen from the front with one point light beside the camera.
inline Scene sphereGrid(int n) {
    Scene s;
    const float mid = 0.5f * float(n - 1);
    s.camera.position = glm::vec3(mid, mid, 1.3f * float(n));
    s.camera.target = glm::vec3(mid, mid, 0.0f);
    s.camera.fovY = 45.0f;
    Light l;
    l.position = s.camera.position + glm::vec3(0.3f * float(n), 0.4f * float(n), 0.0f);
    s.lights.push_back(l);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Mesh m;
            m.name = "sphere";
            m.parts.push_back(MeshPart{shareGeometry(uvSphere(glm::vec3(float(j), float(i), 0.0f), 0.45f)), {}});
            s.meshes.push_back(std::move(m));
        }
    return s;
}

}  // namespace shadelab::bench
