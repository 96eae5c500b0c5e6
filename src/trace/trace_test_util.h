// Shared helpers of the tracer tests: plain materials, meshes built in code (cube, icosphere, fan), the
// assimp-testmodels folder, and where a failing test leaves its images. Test-only; not part of the library.
#pragma once

#include "image/encode.h"
#include "image/image.h"
#include "image/png.h"
#include "scene/scene.h"
#include "trace/ray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace shadelab::trace::test {

// A material with only the given coefficients; kr = kt = 0.
inline Material plainMaterial(glm::vec3 ma, glm::vec3 md = glm::vec3(0.0f), glm::vec3 ms = glm::vec3(0.0f),
                              float s = 1.0f) {
    Material m;
    m.ma = ma;
    m.md = md;
    m.ms = ms;
    m.s = s;
    return m;
}

inline Ray rayTowards(glm::vec3 origin, glm::vec3 target) { return Ray{origin, glm::normalize(target - origin)}; }

// Builds a part from shared vertices (so neighbouring triangles see bit-identical positions); normals are
// the directions from `centre`, as a smooth closed surface would have.
inline MeshPart makePart(std::vector<glm::vec3> positions, std::vector<uint32_t> indices, glm::vec3 centre,
                         const Material& m = Material{}) {
    MeshGeometry g;
    for (const glm::vec3& v : positions) {
        const glm::vec3 d = v - centre;
        g.normals.push_back(glm::length(d) > 0.0f ? glm::normalize(d) : glm::vec3(0.0f, 0.0f, 1.0f));
    }
    g.positions = std::move(positions);
    g.indices = std::move(indices);
    MeshPart p;
    p.geometry = shareGeometry(std::move(g));
    p.material = m;
    return p;
}

// The box [lo, hi] as 12 counter-clockwise (outward) triangles over 8 shared corners.
inline MeshPart cubePart(glm::vec3 lo, glm::vec3 hi, const Material& m = Material{}) {
    std::vector<glm::vec3> v;
    for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    std::vector<uint32_t> idx = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    return makePart(std::move(v), std::move(idx), 0.5f * (lo + hi), m);
}

// An icosahedron subdivided `levels` times, vertices pushed onto the sphere; counter-clockwise outward.
inline MeshPart icospherePart(glm::vec3 c, float r, int levels, const Material& m = Material{}) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> unit = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (glm::vec3& u : unit) u = glm::normalize(u);
    std::vector<uint32_t> idx = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                 6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const std::pair<uint32_t, uint32_t> key(std::min(a, b), std::max(a, b));
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            unit.push_back(glm::normalize(unit[a] + unit[b]));
            return mid[key] = uint32_t(unit.size() - 1);
        };
        std::vector<uint32_t> next;
        for (size_t f = 0; f < idx.size(); f += 3) {
            const uint32_t a = idx[f], b = idx[f + 1], cc = idx[f + 2];
            const uint32_t ab = midpoint(a, b), bc = midpoint(b, cc), ca = midpoint(cc, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, cc, ca, bc, ab, bc, ca});
        }
        idx = std::move(next);
    }
    std::vector<glm::vec3> pos;
    for (const glm::vec3& u : unit) pos.push_back(c + r * u);
    return makePart(std::move(pos), std::move(idx), c, m);
}

// `n` triangles around the vertex `apex`, over a ring of radius r at height z = ringZ (apex.z = ringZ gives
// a flat fan). Counter-clockwise seen from +z.
inline MeshPart fanPart(glm::vec3 apex, float r, float ringZ, int n) {
    std::vector<glm::vec3> v = {apex};
    std::vector<uint32_t> idx;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * 3.14159265358979323846 * double(k) / double(n);
        v.emplace_back(apex.x + r * float(std::cos(a)), apex.y + r * float(std::sin(a)), ringZ);
        idx.insert(idx.end(), {0u, uint32_t(1 + k), uint32_t(1 + (k + 1) % n)});
    }
    return makePart(std::move(v), std::move(idx), apex - glm::vec3(0.0f, 0.0f, 1.0f));
}

// Where the Debian package assimp-testmodels puts its glTF 2.0 files.
inline std::string modelPath(const std::string& relative) { return "/usr/share/assimp/models/glTF2/" + relative; }

// A failing case's evidence: build/test-output/trace_test/<name>.png, path printed.
inline std::string writeEvidence(const std::string& name, const ImageF& img) {
    const std::filesystem::path dir(SHADELAB_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / (name + ".png")).string();
    writePng(path, toImage8(img, Encoding::Srgb, DisplaySettings{}, nullptr));
    std::printf("evidence: %s\n", path.c_str());
    return path;
}

}  // namespace shadelab::trace::test
