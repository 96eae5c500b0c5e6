// Shared helpers of the BVH tests (bvh_test.cpp, bvh_isa_test.cpp): a scene's triangles for brute force,
// random rays over them, a replayable description of a ray, and random triangle soups. Test-only; not part
// of the library.
#pragma once

#include "scene/scene.h"
#include "shading/lighting.h"
#include "trace/accel/mesh_bvh.h"
#include "trace/accel/watertight.h"
#include "trace/ray.h"
#include "trace/trace_test_util.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab::trace::test {

struct SceneTri {
    float v[9];
    uint32_t source;  // scene order over all triangles, as MeshBvh::sourceTriangle numbers them
};

inline bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Every triangle with finite vertices, in scene order (mesh, part, triangle), read from the Scene itself.
inline std::vector<SceneTri> sceneTriangles(const Scene& scene) {
    std::vector<SceneTri> out;
    uint32_t source = 0;
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& part : m.parts)
            for (size_t t = 0, n = part.triangleCount(); t < n; ++t, ++source) {
                const MeshGeometry& p = *part.geometry;
                const glm::vec3 a = p.positions[p.indices[3 * t]], b = p.positions[p.indices[3 * t + 1]],
                                c = p.positions[p.indices[3 * t + 2]];
                if (finite(a) && finite(b) && finite(c) && !isDegenerateTriangle(a, b, c))
                    out.push_back({{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z}, source});
            }
    return out;
}

// Half the rays start anywhere in or around the bounds with a random direction; half aim at a random point
// of a random triangle, so that most of those hit and probe the tree's interior.
inline std::vector<Ray> randomRays(const std::vector<SceneTri>& tris, const Bounds& b, int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::normal_distribution<float> g;
    const glm::vec3 ext = b.hi - b.lo;
    const float pad = 0.25f * std::max({ext.x, ext.y, ext.z, 1e-3f});
    const glm::vec3 lo = b.lo - glm::vec3(pad), size = ext + glm::vec3(2.0f * pad);
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 o = lo + glm::vec3(u01(rng), u01(rng), u01(rng)) * size;
        if (i % 2 == 0) {
            rays.push_back(Ray{o, glm::normalize(glm::vec3(g(rng), g(rng), g(rng)))});
            continue;
        }
        const SceneTri& t = tris[std::min(size_t(u01(rng) * float(tris.size())), tris.size() - 1)];
        float w0 = u01(rng), w1 = u01(rng);
        if (w0 + w1 > 1.0f) w0 = 1.0f - w0, w1 = 1.0f - w1;
        const glm::vec3 a(t.v[0], t.v[1], t.v[2]), bb(t.v[3], t.v[4], t.v[5]), c(t.v[6], t.v[7], t.v[8]);
        const glm::vec3 target = a + w0 * (bb - a) + w1 * (c - a);
        if (glm::length(target - o) > 0.0f) rays.push_back(test::rayTowards(o, target));
    }
    return rays;
}

// `n` random triangles in [-1, 1]^3, sizes from 1e-4 to 1 (log-uniform), a new part every 97 triangles, and
// every 11th triangle an exact copy of an earlier one (exact ties in t).
inline Scene soupScene(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), e(-4.0f, 0.0f);
    std::normal_distribution<float> g;
    Scene sc;
    sc.meshes.push_back(Mesh{});
    MeshGeometry p;
    std::vector<glm::vec3> all;
    auto flush = [&] {
        if (!p.indices.empty()) sc.meshes[0].parts.push_back(MeshPart{shareGeometry(std::move(p)), Material{}});
        p = MeshGeometry{};
    };
    for (int i = 0; i < n; ++i) {
        glm::vec3 v[3];
        if (i % 11 == 10 && !all.empty()) {
            const size_t k = 3 * size_t(std::uniform_int_distribution<size_t>(0, all.size() / 3 - 1)(rng));
            v[0] = all[k], v[1] = all[k + 1], v[2] = all[k + 2];
        } else {
            const glm::vec3 c(u(rng), u(rng), u(rng));
            const float size = std::pow(10.0f, e(rng));
            for (glm::vec3& q : v) q = c + size * glm::vec3(g(rng), g(rng), g(rng));
        }
        for (const glm::vec3& q : v) {
            p.indices.push_back(uint32_t(p.positions.size()));
            p.positions.push_back(q);
            all.push_back(q);
        }
        if (i % 97 == 96) flush();
    }
    flush();
    return sc;
}

// "ray i o=(...) d=(...)" with every float digit, so a failing ray can be replayed.
inline std::string describe(size_t i, const Ray& r) {
    std::ostringstream s;
    s << std::setprecision(9) << "ray " << i << " o=(" << r.origin.x << "f, " << r.origin.y << "f, " << r.origin.z
      << "f) d=(" << r.dir.x << "f, " << r.dir.y << "f, " << r.dir.z << "f)";
    return s.str();
}

}  // namespace shadelab::trace::test
