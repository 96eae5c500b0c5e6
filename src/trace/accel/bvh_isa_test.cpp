// The BVH walks of each instruction set against each other (bvh_isa.h): the AVX2 walks find the SSE2 ones'
// hits bit for bit, on real and random meshes and on leaves built to hit edges, vertices and exact ties; the
// SSE2 slab test against its scalar formula, and both slab tests against exact geometry on grazing rays.
#include "trace/accel/bvh_isa.h"
#include "scene/scene_load.h"
#include "trace/accel/bvh_test_util.h"
#include "trace/accel/bvh_traverse_avx2.h"
#include "trace/accel/mesh_bvh.h"
#include "trace/accel/slab_test.h"

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

// The AVX2 walks against the SSE2 ones: the same hit (t, triangle, barycentrics, bit for bit) and the same
// any-hit answer for every ray, on the engine model, on a random soup, and on a soup far from the world origin
// (where the AVX2 box test's fused form is off by the most, absolutely), with tMax both open and cut short.
TEST(BvhIsa, Avx2WalksMatchTheBaselineBitForBit) {
    if (!bvhIsaAvailable(BvhIsa::Avx2)) GTEST_SKIP() << "this CPU or build has no AVX2 walks";
    const std::string path = test::modelPath("2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    std::vector<Scene> scenes;
    scenes.push_back(soupScene(20000, 99u));
    Scene far = soupScene(20000, 98u);
    for (MeshPart& part : far.meshes[0].parts) {
        MeshGeometry g = *part.geometry;
        for (glm::vec3& v : g.positions) v += glm::vec3(30000.0f, -12000.0f, 50000.0f);
        part.geometry = shareGeometry(std::move(g));
    }
    scenes.push_back(std::move(far));
    if (std::filesystem::exists(path)) scenes.push_back(loadScene(path));
    for (const Scene& sc : scenes) {
        const std::vector<SceneTri> tris = sceneTriangles(sc);
        const MeshBvh bvh(sc);
        // The same triangle (a triangle cut by spatial splits has several slots, and the two walks may reach it
        // through different ones), the same t and barycentrics, bit for bit.
        auto same = [&bvh](const std::optional<MeshHit>& a, const std::optional<MeshHit>& b) {
            if (a.has_value() != b.has_value()) return false;
            return !a ||
                   (std::memcmp(&a->t, &b->t, 4) == 0 && bvh.sourceTriangle(a->slot) == bvh.sourceTriangle(b->slot) &&
                    std::memcmp(&a->b0, &b->b0, 4) == 0 && std::memcmp(&a->b1, &b->b1, 4) == 0 &&
                    std::memcmp(&a->b2, &b->b2, 4) == 0);
        };
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
            (!base || (std::memcmp(&base->t, &wide->t, 4) == 0 &&
                       bvh.sourceTriangle(base->slot) == bvh.sourceTriangle(wide->slot) &&
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

TEST(BvhIsa, Avx2RayConstantsMatchTheScalarOnes) {
    // The AVX2 walks set up each ray without branches (rayConstantsAvx2); every constant must be makeBoxRay's and
    // makeWatertightRay's bits: random directions, and ones with equal magnitudes (the axis choice's ties),
    // zero and negative-zero components, tiny components (the reciprocal's clamp), axis-parallel rays.
    if (!bvhIsaAvailable(BvhIsa::Avx2)) GTEST_SKIP() << "this CPU or build has no AVX2 walks";
    std::mt19937 rng(5);
    std::normal_distribution<float> g;
    const float special[] = {0.0f, -0.0f, 1e-31f, -1e-31f, 1e-30f, 0.5f, -0.5f, 1.0f, -1.0f};
    auto same = [](const BoxRay& a, const WatertightRay& wa, const BoxRay& b, const WatertightRay& wb) {
        return std::memcmp(a.org, b.org, sizeof a.org) == 0 && std::memcmp(a.invDir, b.invDir, sizeof a.invDir) == 0 &&
               std::memcmp(a.nearIdx, b.nearIdx, sizeof a.nearIdx) == 0 &&
               std::memcmp(a.farIdx, b.farIdx, sizeof a.farIdx) == 0 && std::memcmp(&wa, &wb, sizeof wa) == 0;
    };
    size_t bad = 0, control = 0;
    const int kRays = 20000;
    for (int i = 0; i < kRays; ++i) {
        glm::vec3 d(g(rng), g(rng), g(rng));
        if (i % 4 == 1) d = glm::vec3(special[rng() % 9], special[rng() % 9], special[rng() % 9]);
        if (i % 4 == 2) d = glm::vec3(float(int(rng() % 5) - 2), float(int(rng() % 5) - 2), float(int(rng() % 5) - 2));
        if (d == glm::vec3(0.0f)) d.z = -1.0f;
        const Ray ray{{g(rng), g(rng), g(rng)}, d};
        BoxRay box;
        WatertightRay wt;
        rayConstantsAvx2(ray, box, wt);
        WatertightRay expected = makeWatertightRay(ray);
        bad += !same(box, wt, makeBoxRay(ray), expected);
        if (bad && bad <= 3 && !same(box, wt, makeBoxRay(ray), expected))
            ADD_FAILURE() << "dir " << d.x << " " << d.y << " " << d.z;
        // Negative control: the reversed ray's constants differ, and the comparison sees it.
        const Ray back{ray.origin, -ray.dir};
        control += !same(box, wt, makeBoxRay(back), makeWatertightRay(back));
    }
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(control, size_t(kRays));
}

// Random boxes (every 13th inverted: an unused child), origins inside and outside, axis-parallel directions,
// tMax spread; rays i % 3 == 0 graze: they aim at a point on an edge of box i % 8, so the exact entry and exit
// nearly meet and rounding decides.
struct SlabCase {
    alignas(32) float b[6][8];
    Ray ray;
    float tMax;
};

SlabCase slabCase(int i, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-2.0f, 2.0f), s(0.0f, 1.5f), w(0.0f, 1.0f);
    std::normal_distribution<float> g;
    SlabCase c;
    for (int k = 0; k < 8; ++k) {
        const bool inverted = (i + k) % 13 == 0;
        for (int a = 0; a < 3; ++a) {
            const float lo = u(rng), ext = 2.0f * s(rng);
            c.b[a][k] = inverted ? INFINITY : lo;
            c.b[3 + a][k] = inverted ? -INFINITY : lo + ext;
        }
    }
    glm::vec3 d(g(rng), g(rng), g(rng));
    if (i % 5 == 0) d[i % 3] = 0.0f;
    if (i % 7 == 0) d = glm::vec3(0.0f), d[i % 3] = i % 2 ? 1.0f : -1.0f;
    glm::vec3 o(0.5f * u(rng), 0.5f * u(rng), 0.5f * u(rng));
    const int k = i % 8;
    if (i % 3 == 0 && c.b[0][k] <= c.b[3][k]) {
        // A point on an edge of box k (two coordinates on its faces), seen from 3 to 6 units away.
        const int free = (i / 3) % 3;
        glm::vec3 e;
        for (int a = 0; a < 3; ++a)
            e[a] = a == free ? c.b[a][k] + w(rng) * (c.b[3 + a][k] - c.b[a][k]) : c.b[(rng() & 1) ? a : 3 + a][k];
        d = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        o = e - (3.0f + 3.0f * w(rng)) * d;
    }
    c.ray = Ray{o, glm::normalize(d)};
    c.tMax = i % 4 == 0 ? INFINITY : s(rng) * 3.0f;
    return c;
}

// The slab test in double precision on the float ray and box: entry and exit of the exact geometry.
struct ExactSlab {
    double tNear, tFar;
};
ExactSlab exactSlab(const SlabCase& c, int k) {
    double tn = 0.0, tf = INFINITY;
    for (int a = 0; a < 3; ++a) {
        const double o = c.ray.origin[a], d = c.ray.dir[a], lo = c.b[a][k], hi = c.b[3 + a][k];
        if (!(lo <= hi)) return {INFINITY, -INFINITY};
        if (d == 0.0) {
            if (o < lo || o > hi) return {INFINITY, -INFINITY};
            continue;
        }
        const double t0 = (lo - o) / d, t1 = (hi - o) / d;
        tn = std::max(tn, std::min(t0, t1));
        tf = std::min(tf, std::max(t0, t1));
    }
    return {tn, tf};
}

TEST(SlabTest, EightBoxesAgreeWithTheScalarFormula) {
    // slabHits8 (SSE2, two groups of four) against the per-lane formula it documents, computed here in plain
    // floats: the same bits.
    std::mt19937 rng(3);
    size_t hits = 0, bad = 0, badControl = 0;
    const int kRays = 10000;
    for (int i = 0; i < kRays; ++i) {
        const SlabCase c = slabCase(i, rng);
        const BoxRay br = makeBoxRay(c.ray);
        float tNear[8];
        const int mask = slabHits8(makeBoxRay4(br), c.b, c.tMax, tNear);
        for (int k = 0; k < 8; ++k) {
            float tn = 0.0f, tf = INFINITY;
            for (int a = 0; a < 3; ++a) {
                const float t0 = (c.b[br.nearIdx[a]][k] - br.org[a]) * br.invDir[a];
                const float t1 = (c.b[br.farIdx[a]][k] - br.org[a]) * br.invDir[a] * kSlabFarScale;
                tn = std::max(tn, t0);
                tf = std::min(tf, t1);
            }
            const bool hit = tn <= std::min(tf, c.tMax);
            hits += hit;
            bad += hit != bool(mask & (1 << k)) || (hit && tn != tNear[k]);
            const bool control = tn <= std::min(tf, 0.5f * c.tMax);  // a wrong bound must be noticed
            badControl += control != bool(mask & (1 << k));
        }
    }
    std::printf("%zu of %d box tests hit\n", hits, 8 * kRays);
    EXPECT_GT(hits, 3000u);
    EXPECT_EQ(bad, 0u);
    EXPECT_GT(badControl, 100u);
}

TEST(SlabTest, BoxTestsAreConservativeOnGrazingRays) {
    // Both box tests against the exact geometry (double precision): a box the ray meets within tMax must be hit
    // (else the walk could lose a triangle inside it), and a box hit must be met or missed only by rounding
    // (relative 1e-5; for the AVX2 test's fused form, also a few ulps of org·invDir absolutely), with tNear that
    // close to the exact entry. The fused form rounds differently from slabHits8, so only this holds between
    // them, not equal bits. Negative control: the float formula without the far scale loses boxes the exact test
    // meets.
    const bool avx2 = bvhIsaAvailable(BvhIsa::Avx2);
    std::mt19937 rng(11);
    size_t exactHits = 0, lost = 0, lostAvx2 = 0, loose = 0, looseAvx2 = 0, lostNaive = 0, grazing = 0;
    const int kRays = 30000;
    for (int i = 0; i < kRays; ++i) {
        const SlabCase c = slabCase(i, rng);
        const BoxRay br = makeBoxRay(c.ray);
        float tNear[8], tNearAvx2[8];
        const int mask = slabHits8(makeBoxRay4(br), c.b, c.tMax, tNear);
        const int maskAvx2 = avx2 ? slabHits8Avx2(br, c.b, c.tMax, tNearAvx2) : mask;
        if (!avx2) std::memcpy(tNearAvx2, tNear, sizeof tNear);
        // The fused form's distances are off by up to about two ulps of org·invDir, absolutely: the price of
        // rounding bound·invDir − org·invDir once, larger than slabHits8's relative error where the origin is
        // far from the world origin compared with the distance (or a direction component is 0).
        double fusedSlack = 0.0;
        for (int a = 0; a < 3; ++a)
            fusedSlack = std::max(fusedSlack, 4.0 * 0x1p-23 * std::fabs(br.org[a] * br.invDir[a]));
        for (int k = 0; k < 8; ++k) {
            const ExactSlab e = exactSlab(c, k);
            const double far = std::min(e.tFar, double(c.tMax));
            const bool hit = e.tNear <= far;
            const double tol = 1e-5 * std::max({std::fabs(e.tNear), std::fabs(far), 1e-30});
            exactHits += hit;
            grazing += hit && far - e.tNear <= tol;
            auto check = [&](int m, const float* t, double slack, size_t& lostCount, size_t& looseCount) {
                const bool got = m & (1 << k);
                lostCount += hit && !got;
                // Met, or missed by rounding only; tNear that close to the exact entry.
                looseCount += got && (e.tNear > far + slack || std::fabs(double(t[k]) - e.tNear) > slack);
            };
            check(mask, tNear, tol, lost, loose);
            check(maskAvx2, tNearAvx2, tol + fusedSlack, lostAvx2, looseAvx2);
            float tn = 0.0f, tf = INFINITY;
            for (int a = 0; a < 3; ++a) {
                tn = std::max(tn, (c.b[br.nearIdx[a]][k] - br.org[a]) * br.invDir[a]);
                tf = std::min(tf, (c.b[br.farIdx[a]][k] - br.org[a]) * br.invDir[a]);
            }
            lostNaive += hit && !(tn <= std::min(tf, c.tMax));
        }
    }
    std::printf("%zu of %d boxes met (%zu grazing); lost: SSE2 %zu, AVX2 %zu (%s), naive %zu\n", exactHits, 8 * kRays,
                grazing, lost, lostAvx2, avx2 ? "compared" : "not available", lostNaive);
    EXPECT_GT(grazing, 500u) << "too few grazing rays to test anything";
    EXPECT_EQ(lost, 0u);
    EXPECT_EQ(lostAvx2, 0u);
    EXPECT_EQ(loose, 0u);
    EXPECT_EQ(looseAvx2, 0u);
    EXPECT_GT(lostNaive, 0u) << "the grazing rays cannot tell a conservative test from a naive one";
}

}  // namespace
