// The SAH BVH (bvh.h) and its traversals (mesh_bvh.h, sphere_set.h) against brute force: same nearest hit (t
// bit-equal, same triangle) and any-hit answers for random rays over real assimp-testmodels meshes.
// Sections: brute force | structural invariants | real models | degenerate inputs | random triangle soups
// (issue 14's 8-wide tree: sizes around the parallel-build threshold, ties, empty scenes, thread counts,
// the 8-wide slab test, AVX2 against SSE2 walks) | spheres.
#include "trace/bvh.h"
#include "scene/scene_load.h"
#include "shading/lighting.h"
#include "trace/bvh_isa.h"
#include "trace/bvh_traverse_avx2.h"
#include "trace/mesh_bvh.h"
#include "trace/slab_test.h"
#include "trace/sphere_set.h"
#include "trace/trace_scene.h"
#include "trace/trace_test_util.h"
#include "trace/watertight.h"

#include <gtest/gtest.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <random>
#include <sstream>
#include <thread>

using namespace shadelab;
using namespace shadelab::trace;

namespace {

// ---- Brute force over the scene's own triangles ---------------------------------------------------

struct SceneTri {
    float v[9];
    uint32_t source;  // scene order over all triangles, as MeshBvh::sourceTriangle numbers them
};

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Every triangle with finite vertices, in scene order (mesh, part, triangle), read from the Scene itself.
std::vector<SceneTri> sceneTriangles(const Scene& scene) {
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

// Half the rays start anywhere in or around the bounds with a random direction; half aim at a random point
// of a random triangle, so that most of those hit and probe the tree's interior.
std::vector<Ray> randomRays(const std::vector<SceneTri>& tris, const Bounds& b, int n, uint32_t seed) {
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

// "ray i o=(...) d=(...)" with every float digit, so a failing ray can be replayed.
std::string describe(size_t i, const Ray& r) {
    std::ostringstream s;
    s << std::setprecision(9) << "ray " << i << " o=(" << r.origin.x << "f, " << r.origin.y << "f, " << r.origin.z
      << "f) d=(" << r.dir.x << "f, " << r.dir.y << "f, " << r.dir.z << "f)";
    return s.str();
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

std::vector<Bounds> boxesOf(const std::vector<SceneTri>& tris) {
    std::vector<Bounds> boxes(tris.size());
    for (size_t i = 0; i < tris.size(); ++i)
        for (int k = 0; k < 3; ++k) boxes[i].extend(glm::make_vec3(tris[i].v + 3 * k));
    return boxes;
}

// ---- Structural invariants ------------------------------------------------------------------------

Bounds box(glm::vec3 lo, glm::vec3 hi) { return Bounds{lo, hi}; }

Bounds childBox(const BvhNode& n, int k) {
    return box({n.bounds[0][k], n.bounds[1][k], n.bounds[2][k]}, {n.bounds[3][k], n.bounds[4][k], n.bounds[5][k]});
}

bool contains(const Bounds& outer, const Bounds& b) {
    for (int a = 0; a < 3; ++a)
        if (b.lo[a] < outer.lo[a] || b.hi[a] > outer.hi[a]) return false;
    return true;
}

// Every primitive in exactly one leaf, leaves of 1..maxLeaf primitives inside their boxes, interior children's
// boxes inside their parent's box for them, unused children inverted and empty, every node reached once, and
// at most depth + 1 levels. `order[k]` is the primitive (index into boxes) at leaf slot k.
::testing::AssertionResult bvhIsValid(const Bvh& bvh, const std::vector<Bounds>& boxes, int maxLeaf,
                                      const std::vector<uint32_t>& order) {
    if (boxes.empty())
        return bvh.empty() ? ::testing::AssertionSuccess() : ::testing::AssertionFailure() << "not empty";
    if (order.size() != boxes.size() || bvh.primitives != boxes.size())
        return ::testing::AssertionFailure() << "order has " << order.size();
    std::vector<int> seen(boxes.size(), 0);
    std::vector<int> reached(bvh.nodes.size(), 0);
    int levels = 0;
    struct Item {
        uint32_t node;
        Bounds box;
        int level;
    };
    std::vector<Item> stack{{0u, bvh.bounds, 1}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        if (it.node >= bvh.nodes.size() || reached[it.node]++)
            return ::testing::AssertionFailure() << "node " << it.node << " out of range or reached twice";
        levels = std::max(levels, it.level);
        const BvhNode& n = bvh.nodes[it.node];
        int used = 0;
        for (int k = 0; k < kBvhWidth; ++k) {
            const uint32_t ref = n.child[k];
            if (!n.used(k)) {
                if (ref != kLeafBit) return ::testing::AssertionFailure() << "unused child " << k << " has a reference";
                continue;
            }
            ++used;
            const Bounds b = childBox(n, k);
            if (!contains(it.box, b))
                return ::testing::AssertionFailure() << "node " << it.node << " child " << k << " outside its parent";
            if (!isLeafRef(ref)) {
                stack.push_back({ref, b, it.level + 1});
                continue;
            }
            const uint32_t first = leafFirst(ref), count = leafCount(ref);
            if (count == 0 || count > uint32_t(maxLeaf))
                return ::testing::AssertionFailure() << "leaf in node " << it.node << " holds " << count;
            if (size_t(first) + count > order.size()) return ::testing::AssertionFailure() << "leaf range";
            for (uint32_t s = first; s < first + count; ++s) {
                const uint32_t p = order[s];
                if (p >= boxes.size() || seen[p]++)
                    return ::testing::AssertionFailure() << "primitive " << p << " twice";
                if (!contains(b, boxes[p]))
                    return ::testing::AssertionFailure() << "leaf in node " << it.node << " misses box " << p;
            }
        }
        if (used == 0) return ::testing::AssertionFailure() << "node " << it.node << " has no children";
    }
    for (size_t i = 0; i < reached.size(); ++i)
        if (!reached[i]) return ::testing::AssertionFailure() << "node " << i << " unreachable";
    if (levels > bvh.depth + 1 || bvh.depth >= kMaxBvhDepth)
        return ::testing::AssertionFailure() << levels << " levels vs reported depth " << bvh.depth;
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult bvhIsValid(const Bvh& bvh, const std::vector<Bounds>& boxes, int maxLeaf) {
    return bvhIsValid(bvh, boxes, maxLeaf, bvh.order);
}

// A MeshBvh's leaf order as indices into sceneTriangles() (which lists the kept triangles by source).
::testing::AssertionResult meshBvhIsValid(const MeshBvh& bvh, const std::vector<SceneTri>& tris, int maxLeaf) {
    std::vector<uint32_t> order(bvh.triangleCount());
    for (uint32_t s = 0; s < order.size(); ++s) {
        const auto it = std::lower_bound(tris.begin(), tris.end(), bvh.sourceTriangle(s),
                                         [](const SceneTri& t, uint32_t src) { return t.source < src; });
        order[s] = it != tris.end() && it->source == bvh.sourceTriangle(s) ? uint32_t(it - tris.begin()) : UINT32_MAX;
    }
    return bvhIsValid(bvh.bvh(), boxesOf(tris), maxLeaf, order);
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

TEST(BvhBuild, EmptyAndSinglePrimitive) {
    EXPECT_TRUE(buildBvh({}).empty());
    const std::vector<Bounds> one = {box({1, 2, 3}, {4, 5, 6})};
    const Bvh b = buildBvh(one);
    EXPECT_TRUE(bvhIsValid(b, one, 4));
    ASSERT_EQ(b.nodes.size(), 1u);
    EXPECT_EQ(b.nodes[0].child[0], makeLeafRef(0, 1));
    EXPECT_FALSE(b.nodes[0].used(1));
    EXPECT_EQ(b.depth, 0);
}

TEST(BvhBuild, IdenticalBoxesSplitByCountWithinTheDepthLimit) {
    for (const size_t n : {size_t(5), size_t(1000), size_t(100000)})
        for (const int leaf : {1, 4}) {
            const std::vector<Bounds> same(n, box({-1, 0, 2}, {1, 0.5f, 3}));
            BvhBuildOptions o;
            o.maxLeafSize = leaf;
            const Bvh b = buildBvh(same, o);
            EXPECT_TRUE(bvhIsValid(b, same, leaf)) << n << " boxes, leaf " << leaf;
            EXPECT_LE(b.depth, int(std::ceil(std::log2(double(n)))) + 1) << "object-median fallback should halve";
        }
    // Points and flat boxes: zero area everywhere.
    std::vector<Bounds> flat;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 p(u(rng), u(rng), 0.0f);
        flat.push_back(i % 2 ? box(p, p) : box(p, p + glm::vec3(0.1f, 0.0f, 0.0f)));
    }
    EXPECT_TRUE(bvhIsValid(buildBvh(flat), flat, 4));
}

TEST(BvhBuild, OptionsAndSahCostOnRandomBoxes) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f), s(0.0f, 0.3f);
    std::vector<Bounds> boxes;
    for (int i = 0; i < 5000; ++i) {
        const glm::vec3 p(u(rng), u(rng), u(rng));
        boxes.push_back(box(p, p + glm::vec3(s(rng), s(rng), s(rng))));
    }
    for (const int bins : {2, 16, 100})
        for (const int leaf : {0, 1, 8}) {
            BvhBuildOptions o;
            o.bins = bins;
            o.maxLeafSize = leaf;
            const Bvh b = buildBvh(boxes, o);
            EXPECT_TRUE(bvhIsValid(b, boxes, std::max(leaf, 1))) << "bins " << bins << " leaf " << leaf;
            EXPECT_LT(sahCost(b, o), 0.02f * float(boxes.size())) << "far worse than SAH should give";
        }
    // Negative control: the validator notices a shrunken leaf and a lost primitive.
    Bvh broken = buildBvh(boxes);
    size_t leafNode = 0;
    while (!isLeafRef(broken.nodes[leafNode].child[0])) ++leafNode;
    broken.nodes[leafNode].bounds[3][0] = broken.nodes[leafNode].bounds[0][0];
    EXPECT_FALSE(bvhIsValid(broken, boxes, 4));
    broken = buildBvh(boxes);
    broken.order[0] = broken.order[1];
    EXPECT_FALSE(bvhIsValid(broken, boxes, 4));
}

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

// `n` random triangles in [-1, 1]^3, sizes from 1e-4 to 1 (log-uniform), a new part every 97 triangles, and
// every 11th triangle an exact copy of an earlier one (exact ties in t).
Scene soupScene(int n, uint32_t seed) {
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

TEST(BvhBuild, SameTreeForAnyThreadCount) {
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f), s(0.0f, 0.5f);
    std::vector<Bounds> boxes;
    for (int i = 0; i < 80000; ++i) {  // above the parallel binning threshold (65,536)
        const glm::vec3 p(u(rng), u(rng) * 0.1f, u(rng));
        boxes.push_back(box(p, p + glm::vec3(s(rng), s(rng), s(rng))));
    }
    auto same = [](const Bvh& a, const Bvh& b) {
        return a.nodes.size() == b.nodes.size() && a.order == b.order && a.depth == b.depth &&
               std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)) == 0;
    };
    BvhBuildOptions o;
    o.threads = 1;
    const Bvh one = buildBvh(boxes, o);
    EXPECT_TRUE(bvhIsValid(one, boxes, o.maxLeafSize));
    for (const int t : {2, 3}) {
        o.threads = t;
        const Bvh many = buildBvh(boxes, o);
        EXPECT_TRUE(same(one, many)) << t << " threads built a different tree";
    }
    // Negative control: a different bin count builds a different tree, and the comparison sees it.
    o.bins = 8;
    EXPECT_FALSE(same(one, buildBvh(boxes, o)));
}

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
