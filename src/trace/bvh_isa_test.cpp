// The BVH walks of each instruction set against each other (bvh_isa.h): the AVX2 walks find the SSE2 ones'
// hits bit for bit, on real and random meshes and on leaves built to hit edges, vertices and exact ties; and
// the 8-wide slab tests against their scalar formula.
#include "trace/bvh_isa.h"
#include "scene/scene_load.h"
#include "trace/bvh_test_util.h"
#include "trace/bvh_traverse_avx2.h"
#include "trace/mesh_bvh.h"
#include "trace/slab_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <random>

using namespace shadelab;
using namespace shadelab::trace;
using namespace shadelab::trace::test;

namespace {

// The AVX2 walks against the SSE2 ones: the same hit (t, slot, barycentrics, bit for bit) and the same
// any-hit answer for every ray, on the engine model and on a random soup, with tMax both open and cut short.
TEST(BvhIsa, Avx2WalksMatchTheBaselineBitForBit) {
    if (!bvhIsaAvailable(BvhIsa::Avx2)) GTEST_SKIP() << "this CPU or build has no AVX2 walks";
    const std::string path = test::modelPath("2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    std::vector<Scene> scenes;
    scenes.push_back(soupScene(20000, 99u));
    if (std::filesystem::exists(path)) scenes.push_back(loadScene(path));
    auto same = [](const std::optional<MeshHit>& a, const std::optional<MeshHit>& b) {
        if (a.has_value() != b.has_value()) return false;
        return !a || (std::memcmp(&a->t, &b->t, 4) == 0 && a->slot == b->slot && std::memcmp(&a->b0, &b->b0, 4) == 0 &&
                      std::memcmp(&a->b1, &b->b1, 4) == 0 && std::memcmp(&a->b2, &b->b2, 4) == 0);
    };
    for (const Scene& sc : scenes) {
        const std::vector<SceneTri> tris = sceneTriangles(sc);
        const MeshBvh bvh(sc);
        const std::vector<Ray> rays = randomRays(tris, bvh.bounds(), 20000, 31u);
        size_t hits = 0, badClosest = 0, badAny = 0, control = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            const float tMax = i % 3 == 0 ? INFINITY : 0.05f * float(i % 40);
            const std::optional<MeshHit> base = bvh.closestHit(rays[i], tMax, BvhIsa::Sse2);
            const std::optional<MeshHit> wide = bvh.closestHit(rays[i], tMax, BvhIsa::Avx2);
            hits += base.has_value();
            badClosest += !same(base, wide);
            badAny += bvh.anyHit(rays[i], tMax, BvhIsa::Sse2) != bvh.anyHit(rays[i], tMax, BvhIsa::Avx2);
            // Negative control: the baseline with a bound cut to just past the AVX2 hit must not always agree.
            if (wide) control += !same(bvh.closestHit(rays[i], std::nextafter(wide->t, 0.0f), BvhIsa::Sse2), wide);
        }
        std::printf("%zu triangles, %zu rays, %zu hits\n", tris.size(), rays.size(), hits);
        EXPECT_GT(hits, rays.size() / 10) << "too few hits to test anything";
        EXPECT_EQ(badClosest, 0u);
        EXPECT_EQ(badAny, 0u);
        EXPECT_EQ(control, hits) << "the comparison cannot see a changed hit";
    }
}

TEST(BvhIsa, Avx2FourTriangleLeavesMatchOnEdgesVerticesAndTies) {
    // The AVX2 walk tests a leaf's triangles four at a time and hands a leaf with an edge function of exactly 0
    // to the scalar test. A tilted integer grid of quads (two triangles each, every fourth quad doubled in a
    // later part so exact ties meet in one leaf), hit by rays through its vertices, edge midpoints and cell
    // interiors, axis-parallel and oblique, from both sides: both walks must give the same bits.
    if (!bvhIsaAvailable(BvhIsa::Avx2)) GTEST_SKIP() << "this CPU or build has no AVX2 walks";
    Scene sc;
    sc.meshes.push_back(Mesh{});
    const int kN = 24;
    auto z = [](int x, int y) { return 0.25f * float(x) - 0.125f * float(y); };
    auto vertex = [&](int x, int y) { return glm::vec3(float(x), float(y), z(x, y)); };
    for (int copy = 0; copy < 2; ++copy) {
        MeshGeometry p;
        for (int y = 0; y < kN; ++y)
            for (int x = 0; x < kN; ++x) {
                if (copy == 1 && (x + y) % 4 != 0) continue;
                const glm::vec3 q[4] = {vertex(x, y), vertex(x + 1, y), vertex(x + 1, y + 1), vertex(x, y + 1)};
                for (int k : {0, 1, 2, 0, 2, 3}) {
                    p.indices.push_back(uint32_t(p.positions.size()));
                    p.positions.push_back(q[k]);
                }
            }
        sc.meshes[0].parts.push_back(MeshPart{shareGeometry(std::move(p)), Material{}});
    }
    const MeshBvh bvh(sc);
    std::mt19937 rng(17);
    std::uniform_int_distribution<int> cell(1, kN - 1), half(0, 2);
    std::normal_distribution<float> g;
    size_t rays = 0, hits = 0, badClosest = 0, badAny = 0, control = 0;
    for (int i = 0; i < 20000; ++i) {
        // Targets on the grid: a vertex (2·k), an edge midpoint or a cell centre (odd halves).
        const float tx = float(cell(rng)) + 0.5f * float(half(rng) % 2), ty = float(cell(rng)) + 0.5f * float(i % 2);
        const glm::vec3 target(tx, ty, 0.25f * tx - 0.125f * ty);
        glm::vec3 d(0.0f, 0.0f, i % 4 < 2 ? -1.0f : 1.0f);
        if (i % 3 == 1) d = glm::normalize(glm::vec3(0.25f * g(rng), 0.25f * g(rng), d.z));
        if (i % 3 == 2) d = glm::normalize(glm::vec3(d.z, 0.0f, 0.0f) + glm::vec3(0.0f, 0.0f, 0.5f * d.z));
        const Ray ray{target - 3.0f * d, d};
        const float tMax = i % 5 == 0 ? 3.0f : INFINITY;
        const std::optional<MeshHit> base = bvh.closestHit(ray, tMax, BvhIsa::Sse2);
        const std::optional<MeshHit> wide = bvh.closestHit(ray, tMax, BvhIsa::Avx2);
        ++rays;
        hits += base.has_value();
        const bool same =
            base.has_value() == wide.has_value() &&
            (!base || (std::memcmp(&base->t, &wide->t, 4) == 0 && base->slot == wide->slot &&
                       std::memcmp(&base->b0, &wide->b0, 4) == 0 && std::memcmp(&base->b1, &wide->b1, 4) == 0 &&
                       std::memcmp(&base->b2, &wide->b2, 4) == 0));
        badClosest += !same;
        if (!same && badClosest <= 3) ADD_FAILURE() << describe(size_t(i), ray);
        badAny += bvh.anyHit(ray, tMax, BvhIsa::Sse2) != bvh.anyHit(ray, tMax, BvhIsa::Avx2);
        // Negative control: a bound just short of the hit must lose it.
        if (wide)
            control += !bvh.closestHit(ray, std::nextafter(wide->t, 0.0f), BvhIsa::Avx2).has_value() ||
                       bvh.closestHit(ray, std::nextafter(wide->t, 0.0f), BvhIsa::Avx2)->t != wide->t;
    }
    std::printf("%zu triangles, %zu rays, %zu hits\n", bvh.triangleCount(), rays, hits);
    EXPECT_GT(hits, rays / 2) << "too few hits to test anything";
    EXPECT_EQ(badClosest, 0u);
    EXPECT_EQ(badAny, 0u);
    EXPECT_EQ(control, hits) << "the comparison cannot see a changed hit";
}

TEST(SlabTest, EightBoxesAgreeWithTheScalarFormula) {
    // slabHits8 (SSE2, two groups of four) and, where the CPU has it, slabHits8Avx2 against the per-lane formula
    // they document, computed here in plain floats: random boxes (some inverted: unused children), origins
    // inside and outside, axis-parallel directions, tMax spread. Both must give the same bits.
    const bool avx2 = bvhIsaAvailable(BvhIsa::Avx2);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f), s(0.0f, 1.5f);
    std::normal_distribution<float> g;
    size_t hits = 0, bad = 0, badAvx2 = 0, badControl = 0;
    const int kRays = 10000;
    for (int i = 0; i < kRays; ++i) {
        alignas(32) float b[6][8];
        for (int k = 0; k < 8; ++k) {
            const bool inverted = (i + k) % 13 == 0;
            for (int a = 0; a < 3; ++a) {
                const float lo = u(rng), ext = 2.0f * s(rng);
                b[a][k] = inverted ? INFINITY : lo;
                b[3 + a][k] = inverted ? -INFINITY : lo + ext;
            }
        }
        glm::vec3 d(g(rng), g(rng), g(rng));
        if (i % 5 == 0) d[i % 3] = 0.0f;
        if (i % 7 == 0) d = glm::vec3(0.0f), d[i % 3] = i % 2 ? 1.0f : -1.0f;
        const Ray ray{{0.5f * u(rng), 0.5f * u(rng), 0.5f * u(rng)}, glm::normalize(d)};
        const float tMax = i % 4 == 0 ? INFINITY : s(rng) * 3.0f;
        const BoxRay br = makeBoxRay(ray);
        float tNear[8], tNearAvx2[8];
        const int mask = slabHits8(makeBoxRay4(br), b, tMax, tNear);
        const int maskAvx2 = avx2 ? slabHits8Avx2(br, b, tMax, tNearAvx2) : mask;
        if (!avx2) std::memcpy(tNearAvx2, tNear, sizeof tNear);
        badAvx2 += maskAvx2 != mask || std::memcmp(tNear, tNearAvx2, sizeof tNear) != 0;
        for (int k = 0; k < 8; ++k) {
            float tn = 0.0f, tf = INFINITY;
            for (int a = 0; a < 3; ++a) {
                const float t0 = (b[br.nearIdx[a]][k] - br.org[a]) * br.invDir[a];
                const float t1 = (b[br.farIdx[a]][k] - br.org[a]) * br.invDir[a] * kSlabFarScale;
                tn = std::max(tn, t0);
                tf = std::min(tf, t1);
            }
            const bool hit = tn <= std::min(tf, tMax);
            hits += hit;
            bad += hit != bool(mask & (1 << k)) || (hit && tn != tNear[k]);
            const bool control = tn <= std::min(tf, 0.5f * tMax);  // a wrong bound must be noticed
            badControl += control != bool(mask & (1 << k));
        }
    }
    std::printf("%zu of %d box tests hit; AVX2 %s\n", hits, 8 * kRays, avx2 ? "compared" : "not available");
    EXPECT_GT(hits, 3000u);
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(badAvx2, 0u);
    EXPECT_GT(badControl, 100u);
}

}  // namespace
