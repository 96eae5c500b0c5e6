// The SAH BVH (bvh.h) and its traversals (mesh_bvh.h, sphere_set.h) against brute force: same nearest hit (t
// bit-equal, same triangle) and any-hit answers for random rays over real assimp-testmodels meshes.
// Sections: brute force | real models | degenerate inputs | random triangle soups (the 8-wide tree:
// sizes around the parallel-build threshold, ties, empty scenes) | spheres. The builder's own properties are
// bvh_build_test.cpp; the AVX2 walks and the 8-wide slab tests against the baseline are bvh_isa_test.cpp.
#include "trace/accel/bvh.h"
#include "scene/scene_load.h"
#include "shading/lighting.h"
#include "trace/accel/bvh_invariants.h"
#include "trace/accel/bvh_test_util.h"
#include "trace/accel/mesh_bvh.h"
#include "trace/accel/sphere_set.h"
#include "trace/accel/watertight.h"
#include "trace/trace_scene.h"
#include "trace/trace_test_util.h"

#include <gtest/gtest.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <random>
#include <sstream>
#include <thread>

using namespace shadelab;
using namespace shadelab::trace;
using namespace shadelab::trace::test;

namespace {

// ---- Brute force over the scene's own triangles ---------------------------------------------------

struct Nearest {
    float t = INFINITY;
    uint32_t source = UINT32_MAX;  // UINT32_MAX: miss
};

// Nearest hit over all triangles with the same watertight test; a tie keeps the earlier (lower) source.
// Any hit below tMax exists exactly when the nearest hit is below tMax, so one pass answers both queries.
// For speed (121k triangles × 10k rays), a triangle whose bounding sphere, grown by 1e-3 of the model's
// size (about 10^4 times the test's rounding), lies off the ray is skipped: a hit there is impossible.
// Triangles go in cache-sized blocks in scene order, so the answer is exactly that of the plain loop.
std::vector<Nearest> bruteForceAll(const std::vector<SceneTri>& tris, const std::vector<Ray>& rays) {
    Bounds all;
    for (const SceneTri& t : tris)
        for (int k = 0; k < 3; ++k) all.extend(glm::make_vec3(t.v + 3 * k));
    const float margin = 1e-3f * glm::length(all.hi - all.lo) + 1e-6f;
    std::vector<float> sphere(4 * tris.size());  // centre and squared radius with margin; plain floats, fast at -O0
    for (size_t i = 0; i < tris.size(); ++i) {
        const glm::vec3 a = glm::make_vec3(tris[i].v), b = glm::make_vec3(tris[i].v + 3),
                        c = glm::make_vec3(tris[i].v + 6);
        const glm::vec3 m = (a + b + c) / 3.0f;
        const float r = std::max({glm::length(a - m), glm::length(b - m), glm::length(c - m)}) + margin;
        sphere[4 * i] = m.x, sphere[4 * i + 1] = m.y, sphere[4 * i + 2] = m.z, sphere[4 * i + 3] = r * r;
    }
    std::vector<Nearest> out(rays.size());
    const size_t n = std::max(2u, std::thread::hardware_concurrency()), block = 1024;
    std::vector<std::thread> workers;
    for (size_t w = 0; w < n; ++w)
        workers.emplace_back([&, w] {
            std::vector<uint8_t> near(block);
            for (size_t first = 0; first < tris.size(); first += block) {
                const size_t count = std::min(block, tris.size() - first);
                for (size_t i = w; i < rays.size(); i += n) {
                    const float ox = rays[i].origin.x, oy = rays[i].origin.y, oz = rays[i].origin.z;
                    const float dx = rays[i].dir.x, dy = rays[i].dir.y, dz = rays[i].dir.z;
                    const float* sp = &sphere[4 * first];
                    for (size_t k = 0; k < count; ++k, sp += 4) {  // branch-free, so it vectorizes
                        const float cx = sp[0] - ox, cy = sp[1] - oy, cz = sp[2] - oz;
                        const float along = cx * dx + cy * dy + cz * dz;
                        const float px = cx - along * dx, py = cy - along * dy, pz = cz - along * dz;
                        near[k] = (px * px + py * py + pz * pz <= sp[3]) & (along >= 0.0f || along * along <= sp[3]);
                    }
                    const WatertightRay wr = makeWatertightRay(rays[i]);
                    Nearest best = out[i];
                    for (size_t k = 0; k < count; ++k) {
                        if (!near[k]) continue;
                        const float* v = tris[first + k].v;
                        const std::optional<TriangleHit> h = intersectTriangle(wr, v, v + 3, v + 6, INFINITY);
                        if (h && h->t < best.t) best = {h->t, tris[first + k].source};
                    }
                    out[i] = best;
                }
            }
        });
    for (std::thread& t : workers) t.join();
    return out;
}

struct Disagreement {
    size_t rays = 0, hits = 0, closest = 0, any = 0;
    std::string first, firstAny;
};

// MeshBvh against the brute-force answers: nearest hit (t bit-equal and the same source triangle, or both
// miss) and anyHit at tMax = ∞, the brute-force t itself (strict, so false), half and twice it, and a
// spread of fixed values. (tMax one float above a hit: MeshBvhRobustness below.)
Disagreement compare(const MeshBvh& bvh, const std::vector<Ray>& rays, const std::vector<Nearest>& brute) {
    Disagreement d;
    d.rays = rays.size();
    const float tScale = glm::length(bvh.bounds().hi - bvh.bounds().lo);
    for (size_t i = 0; i < rays.size(); ++i) {
        const Nearest& b = brute[i];
        const std::optional<MeshHit> h = bvh.closestHit(rays[i], INFINITY);
        d.hits += b.source != UINT32_MAX;
        const bool same = h ? (b.source != UINT32_MAX && h->t == b.t && bvh.sourceTriangle(h->slot) == b.source)
                            : b.source == UINT32_MAX;
        if (!same && d.closest++ == 0) {
            std::ostringstream s;
            s << std::setprecision(9) << describe(i, rays[i]) << ": bvh t " << (h ? h->t : -1.0f) << " tri "
              << (h ? int64_t(bvh.sourceTriangle(h->slot)) : -1) << ", brute t " << b.t << " tri " << int64_t(b.source);
            d.first = s.str();
        }
        const float tMaxes[] = {INFINITY, b.t, 0.5f * b.t, 2.0f * b.t, float(i % 97) * 0.05f * tScale};
        for (const float tMax : tMaxes)
            if (bvh.anyHit(rays[i], tMax) != (b.t < tMax) && d.any++ == 0)
                d.firstAny =
                    describe(i, rays[i]) + ", tMax " + std::to_string(tMax) + ", brute t " + std::to_string(b.t);
    }
    return d;
}

// ---- Real models ---------------------------------------------------------------------------------

struct ModelCase {
    const char* path;  // under /usr/share/assimp/models/glTF2
    int rays;
};

class BvhModel : public ::testing::TestWithParam<ModelCase> {};

TEST_P(BvhModel, MatchesBruteForce) {
    const std::string path = test::modelPath(GetParam().path);
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing (install assimp-testmodels)";
    const Scene scene = loadScene(path);
    const std::vector<SceneTri> tris = sceneTriangles(scene);
    ASSERT_FALSE(tris.empty());
    const MeshBvh bvh(scene);
    ASSERT_EQ(bvh.triangleCount(), tris.size());
    EXPECT_TRUE(meshBvhIsValid(bvh, tris, BvhBuildOptions{}.maxLeafSize));

    const std::vector<Ray> rays = randomRays(tris, bvh.bounds(), GetParam().rays, 20240611u);
    ASSERT_GE(rays.size(), size_t(GetParam().rays) - 50);
    const std::vector<Nearest> brute = bruteForceAll(tris, rays);
    const Disagreement d = compare(bvh, rays, brute);
    std::printf("%s: %zu triangles, %zu rays, %zu hits\n", GetParam().path, tris.size(), d.rays, d.hits);
    EXPECT_GT(d.hits, d.rays / 4) << "too few hits to test anything";
    EXPECT_EQ(d.closest, 0u) << "nearest-hit disagreements; first: " << d.first;
    EXPECT_EQ(d.any, 0u) << "any-hit disagreements; first: " << d.firstAny;

    // Negative control: brute force that lost every 7th triangle must disagree with the BVH.
    std::vector<SceneTri> fewer;
    for (size_t i = 0; i < tris.size(); ++i)
        if (i % 7 != 1) fewer.push_back(tris[i]);
    const std::vector<Ray> some(rays.begin(),
                                rays.begin() + std::min<std::ptrdiff_t>(2000, std::ptrdiff_t(rays.size())));
    EXPECT_GT(compare(bvh, some, bruteForceAll(fewer, some)).closest, 0u)
        << "the comparison cannot see a lost triangle";
}

INSTANTIATE_TEST_SUITE_P(
    AssimpTestModels, BvhModel,
    ::testing::Values(ModelCase{"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 10000},
                      ModelCase{"BoxTextured-glTF-Binary/BoxTextured.glb", 20000},
                      ModelCase{"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 10000},
                      ModelCase{"glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", 10000},
                      ModelCase{"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", 10000},
                      ModelCase{"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", 10000},
                      ModelCase{"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf", 10000}),
    [](const ::testing::TestParamInfo<ModelCase>& modelInfo) {
        std::string n = std::filesystem::path(modelInfo.param.path).stem().string();
        std::replace_if(
            n.begin(), n.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
        return n;
    });

// ---- Degenerate inputs -----------------------------------------------------------------------------

// Zero-area triangles: points (i % 3 == 0), collinear slivers a, a + d/2, a + d (1), and one segment with a
// repeated vertex (2); among them 200 small real triangles and 200 copies of one big triangle on top.
Scene degenerateScene() {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    MeshGeometry p;
    auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (const glm::vec3& v : {a, b, c}) {
            p.indices.push_back(uint32_t(p.positions.size()));
            p.positions.push_back(v);
            p.normals.push_back({0, 0, 1});
        }
    };
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 a(u(rng), u(rng), u(rng)), d(u(rng), u(rng), u(rng));
        if (i % 3 == 0)
            add(a, a, a);
        else if (i % 3 == 1)
            add(a, a + 0.5f * d, a + d);
        else
            add({0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {1, 1, 1});
        if (i % 20 == 0) add(a, a + glm::vec3(u(rng), u(rng), 0.0f) * 0.3f, a + glm::vec3(0.0f, u(rng), u(rng)) * 0.3f);
        if (i % 20 == 10) add({-3, -3, 3}, {3, -3, 3}, {0, 3, 3});  // above everything else
    }
    Scene sc;
    sc.meshes.push_back(Mesh{});
    sc.meshes[0].parts.push_back(MeshPart{shareGeometry(std::move(p)), Material{}});
    return sc;
}

TEST(BvhBuild, ZeroAreaAndDuplicateTrianglesMatchBruteForce) {
    // The builder copes with thousands of zero-area boxes, the traversal agrees with brute force, points and
    // repeated-vertex segments are never hit, and 200 identical triangles tie to the first one.
    const Scene sc = degenerateScene();
    const std::vector<SceneTri> tris = sceneTriangles(sc);
    const MeshBvh bvh(sc);
    EXPECT_TRUE(meshBvhIsValid(bvh, tris, 4));
    std::vector<Ray> rays = randomRays(tris, bvh.bounds(), 10000, 99u);
    rays.push_back(Ray{{0.1f, 0.1f, 5.0f}, {0, 0, -1}});
    const std::vector<Nearest> brute = bruteForceAll(tris, rays);
    const Disagreement d = compare(bvh, rays, brute);
    EXPECT_EQ(d.closest, 0u) << d.first;
    EXPECT_EQ(d.any, 0u) << d.firstAny;
    for (const Nearest& n : brute) {
        if (n.source == UINT32_MAX) continue;
        // Degenerate triangles are left out of `tris` (and of the BVH), so look the hit up by source number.
        const auto it = std::lower_bound(tris.begin(), tris.end(), n.source,
                                         [](const SceneTri& t, uint32_t src) { return t.source < src; });
        ASSERT_TRUE(it != tris.end() && it->source == n.source);
        const float* v = it->v;
        const bool point = v[0] == v[3] && v[1] == v[4] && v[2] == v[5] && v[0] == v[6] && v[1] == v[7] && v[2] == v[8];
        EXPECT_FALSE(point || (v[0] == 0.5f && v[3] == 0.5f && v[6] == 1.0f)) << "triangle " << n.source << " was hit";
    }
    const std::optional<MeshHit> copy = bvh.closestHit(rays.back(), INFINITY);
    ASSERT_TRUE(copy);
    uint32_t firstCopy = 0;
    while (tris[firstCopy].v[0] != -3.0f) ++firstCopy;
    EXPECT_EQ(bvh.sourceTriangle(copy->slot), tris[firstCopy].source) << "a tie must go to the first copy";
}

// ---- Random triangle soups (the 8-wide tree) --------------------------------------------------------

TEST(BvhSoup, RandomSoupsMatchBruteForce) {
    // Sizes below and above the parallel build's queue threshold (4,096) and the parallel binning one.
    for (const int n : {1, 2, 5, 37, 1000, 6000, 70000}) {
        const Scene sc = soupScene(n, 1000u + uint32_t(n));
        const std::vector<SceneTri> tris = sceneTriangles(sc);
        BvhBuildOptions o;
        o.threads = 2;
        const MeshBvh bvh(sc, o);
        ASSERT_EQ(bvh.triangleCount(), tris.size());
        EXPECT_TRUE(meshBvhIsValid(bvh, tris, o.maxLeafSize)) << n << " triangles";
        const std::vector<Ray> rays = randomRays(tris, bvh.bounds(), n < 10000 ? 4000 : 1500, 7u + uint32_t(n));
        const std::vector<Nearest> brute = bruteForceAll(tris, rays);
        const Disagreement d = compare(bvh, rays, brute);
        EXPECT_GT(d.hits, d.rays / 10) << n << " triangles: too few hits to test anything";
        EXPECT_EQ(d.closest, 0u) << n << " triangles: " << d.first;
        EXPECT_EQ(d.any, 0u) << n << " triangles: " << d.firstAny;
        if (n == 6000) {
            // Negative control: brute force that lost every 7th triangle must disagree with the BVH.
            std::vector<SceneTri> fewer;
            for (size_t i = 0; i < tris.size(); ++i)
                if (i % 7 != 3) fewer.push_back(tris[i]);
            EXPECT_GT(compare(bvh, rays, bruteForceAll(fewer, rays)).closest, 0u) << "cannot see a lost triangle";
        }
    }
}

TEST(BvhSoup, LargerLeavesAskedForAreCappedAtWhatTheLeafTestTakes) {
    // The AVX2 leaf test takes up to kMaxMeshLeafSize triangles in one step, so MeshBvh caps the option; asked for
    // leaves of 12, the tree must still hold at most 4 per leaf and find every hit brute force finds.
    const Scene sc = soupScene(3000, 77u);
    const std::vector<SceneTri> tris = sceneTriangles(sc);
    BvhBuildOptions o;
    o.maxLeafSize = 12;
    o.traversalCost = 4.0f;  // makes large leaves cheap, so an uncapped build would use them
    const MeshBvh bvh(sc, o);
    EXPECT_TRUE(meshBvhIsValid(bvh, tris, kMaxMeshLeafSize));
    const std::vector<Ray> rays = randomRays(tris, bvh.bounds(), 3000, 78u);
    const Disagreement d = compare(bvh, rays, bruteForceAll(tris, rays));
    EXPECT_GT(d.hits, d.rays / 10) << "too few hits to test anything";
    EXPECT_EQ(d.closest, 0u) << d.first;
    EXPECT_EQ(d.any, 0u) << d.firstAny;
    // Negative control: the same options on the same boxes without the cap make leaves of more than 4.
    std::vector<Bounds> boxes = boxesOf(tris);
    EXPECT_FALSE(bvhIsValid(buildBvh(boxes, o), boxes, kMaxMeshLeafSize)) << "the options would not make large leaves";
}

TEST(BvhSoup, ExactTiesGoToTheLowerSourceTriangle) {
    // A strip of quads in z = 0 (two triangles each, sharing the diagonal and the edges between quads), the
    // whole strip repeated three times (exact copies in later parts), and rays straight down through the
    // shared edges and vertices: every hit is a tie, which must go to the lowest source triangle.
    Scene sc;
    sc.meshes.push_back(Mesh{});
    const int quads = 3000;  // 6,000 triangles per copy: the queued parallel build
    for (int copy = 0; copy < 3; ++copy) {
        MeshGeometry p;
        for (int q = 0; q <= quads; ++q) {
            p.positions.push_back({float(q), 0.0f, 0.0f});
            p.positions.push_back({float(q), 1.0f, 0.0f});
        }
        for (uint32_t q = 0; q < uint32_t(quads); ++q) {
            const uint32_t a = 2 * q, b = 2 * q + 2, c = 2 * q + 3, d = 2 * q + 1;
            p.indices.insert(p.indices.end(), {a, b, c, a, c, d});
        }
        sc.meshes[0].parts.push_back(MeshPart{shareGeometry(std::move(p)), Material{}});
    }
    const std::vector<SceneTri> tris = sceneTriangles(sc);
    const MeshBvh bvh(sc);
    std::mt19937 rng(31);
    std::uniform_int_distribution<int> pick(1, quads - 1);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) {
        const float x = float(pick(rng));
        const float y = i % 3 == 0 ? 0.5f : (i % 3 == 1 ? 0.0f : 1.0f);  // a shared edge, or a shared vertex
        const float xo = i % 2 ? x : x + 0.5f;                           // a diagonal's midpoint every other ray
        rays.push_back(Ray{{xo, i % 2 ? y : 0.5f, 2.0f}, {0.0f, 0.0f, -1.0f}});
    }
    const std::vector<Nearest> brute = bruteForceAll(tris, rays);
    const Disagreement d = compare(bvh, rays, brute);
    EXPECT_EQ(d.hits, rays.size());
    EXPECT_EQ(d.closest, 0u) << d.first;
    EXPECT_EQ(d.any, 0u) << d.firstAny;
    // Negative control: the rays really are ties: brute force keeping the highest source instead disagrees
    // (checked on every 10th ray, which keeps the test quick under the sanitizers).
    size_t ties = 0, checked = 0;
    for (size_t i = 0; i < rays.size(); i += 10, ++checked) {
        const WatertightRay wr = makeWatertightRay(rays[i]);
        uint32_t last = UINT32_MAX;
        for (const SceneTri& t : tris) {
            const std::optional<TriangleHit> h = intersectTriangle(wr, t.v, t.v + 3, t.v + 6, INFINITY);
            if (h && h->t == brute[i].t) last = t.source;
        }
        ties += last != brute[i].source;
    }
    EXPECT_EQ(ties, checked) << "some rays were not ties, so they test nothing about tie-breaking";
}

TEST(BvhSoup, EmptySceneAndOnlyDegenerateTrianglesAreNeverHit) {
    const Ray down{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    auto check = [&](const Scene& sc, size_t triangles, bool hit) {
        const MeshBvh bvh(sc);
        EXPECT_EQ(bvh.triangleCount(), triangles);
        EXPECT_EQ(bvh.bvh().empty(), triangles == 0);
        EXPECT_EQ(bvh.closestHit(down, INFINITY).has_value(), hit);
        EXPECT_EQ(bvh.anyHit(down, INFINITY), hit);
        const TraceScene ts(sc);
        EXPECT_EQ(ts.intersect(down).has_value(), hit);
        EXPECT_EQ(ts.occluded(down, 10.0f), hit);
    };
    check(Scene{}, 0, false);
    // Points, a repeated vertex and collinear corners, all in the ray's way.
    MeshGeometry p;
    p.positions = {{0.25f, 0.25f, 0.0f}, {0.25f, 0.25f, 0.0f}, {0.25f, 0.25f, 0.0f},
                   {0.0f, 0.0f, 0.0f},   {0.5f, 0.5f, 0.0f},   {1.0f, 1.0f, 0.0f}};
    p.indices = {0, 1, 2, 3, 4, 5, 0, 0, 5, 3, 5, 3};
    Scene degenerate;
    degenerate.meshes.push_back(Mesh{});
    degenerate.meshes[0].parts.push_back(MeshPart{shareGeometry(p), Material{}});
    check(degenerate, 0, false);
    // Negative control: one real triangle under the ray is found.
    p.positions.push_back({1.0f, 0.0f, 0.0f});
    p.indices.insert(p.indices.end(), {3, 6, 5});
    Scene real;
    real.meshes.push_back(Mesh{});
    real.meshes[0].parts.push_back(MeshPart{shareGeometry(p), Material{}});
    check(real, 1, true);
}

TEST(SphereSetBvh, MatchesBruteForce) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f), r(0.05f, 0.6f);
    std::normal_distribution<float> g;
    std::vector<Sphere> spheres;
    for (int i = 0; i < 400; ++i) spheres.push_back(Sphere{"", {u(rng), u(rng), u(rng)}, r(rng), Material{}});
    spheres.push_back(spheres[7]);  // an exact duplicate: ties go to the lower index
    std::vector<Ray> rays;
    for (int i = 0; i < 20000; ++i)
        rays.push_back(
            {{u(rng) * 1.3f, u(rng) * 1.3f, u(rng) * 1.3f}, glm::normalize(glm::vec3(g(rng), g(rng), g(rng)))});
    size_t hits = 0;
    auto mismatches = [&](const SphereSet& set) {
        size_t bad = 0;
        hits = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            const Ray& ray = rays[i];
            const float tMin = i % 2 ? 0.0f : 1e-3f;
            float best = INFINITY;
            uint32_t index = UINT32_MAX;
            for (size_t k = 0; k < spheres.size(); ++k) {
                const float t =
                    shading::intersectSphere(ray.origin, ray.dir, spheres[k].center, spheres[k].radius, tMin);
                if (t > tMin && t < best) best = t, index = uint32_t(k);
            }
            const std::optional<SphereHit> h = set.closestHit(ray, tMin, INFINITY);
            hits += index != UINT32_MAX;
            bad += h ? !(h->t == best && h->index == index) : index != UINT32_MAX;
            for (const float tMax : {INFINITY, best, std::nextafter(best, INFINITY), 0.5f * best})
                bad += set.anyHit(ray, tMin, tMax) != (best < tMax);
        }
        return bad;
    };
    EXPECT_EQ(mismatches(SphereSet(spheres)), 0u);
    EXPECT_GT(hits, 2000u);
    // Negative control: a set of spheres 1 % smaller disagrees.
    std::vector<Sphere> smaller(spheres);
    for (Sphere& sp : smaller) sp.radius *= 0.99f;
    EXPECT_GT(mismatches(SphereSet(smaller)), 100u);
}

}  // namespace
