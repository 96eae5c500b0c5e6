// Spatial splits (the builder, bvh.h, with spatial_splits.h's TriangleSplitter): the references cover their
// triangles, stay inside the triangles' boxes, respect the room they are given, do not depend on the thread
// count, and a MeshBvh built with them finds exactly the hits of one built without them.
#include "trace/accel/spatial_splits.h"
#include "trace/accel/bvh_invariants.h"
#include "trace/accel/bvh_test_util.h"
#include "trace/accel/mesh_bvh.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cstring>
#include <random>
#include <vector>

namespace shadelab::trace {
namespace {

using test::SceneTri;

// Small triangles scattered through a cube and, one in `sliverEvery`, long thin ones lying across the axes
// through it, like 2CylinderEngine's cylinder walls among its bolts: the long ones' boxes take in many small
// ones, so no object split separates them well. The case spatial splits are for.
Scene sliverScene(int n, uint32_t seed, int sliverEvery = 8) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    MeshGeometry g;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 c(u(rng), u(rng), u(rng));
        const glm::vec3 along = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        const glm::vec3 across = glm::normalize(glm::cross(along, glm::vec3(u(rng), u(rng), u(rng))));
        const bool sliver = i % sliverEvery == 0;
        const float length = sliver ? 1.0f : 0.02f, width = sliver ? 0.01f : 0.02f;
        const glm::vec3 v[3] = {c - length * along, c + length * along, c + width * across};
        for (const glm::vec3& q : v) {
            g.indices.push_back(uint32_t(g.positions.size()));
            g.positions.push_back(q);
        }
    }
    Scene sc;
    sc.meshes.push_back(Mesh{});
    sc.meshes[0].parts.push_back(MeshPart{shareGeometry(std::move(g)), Material{}});
    return sc;
}

struct Input {
    std::vector<SceneTri> tris;
    std::vector<BvhPrim> prims;  // one per triangle: its box, id = its index in `tris`
};

Input inputOf(const Scene& sc) {
    Input in;
    in.tris = test::sceneTriangles(sc);
    for (uint32_t i = 0; i < in.tris.size(); ++i) {
        Bounds b;
        for (int k = 0; k < 3; ++k) b.extend(glm::make_vec3(in.tris[i].v + 3 * k));
        in.prims.push_back(BvhPrim{{b.lo.x, b.lo.y, b.lo.z}, i, {b.hi.x, b.hi.y, b.hi.z}, 0});
    }
    return in;
}

struct Built {
    Bvh bvh;
    std::vector<BvhPrim> refs;  // in leaf order
};

// The tree over `in`'s triangles with room for `budget` extra references per triangle.
Built build(const Input& in, float budget, int threads) {
    const TriangleSplitter splitter(
        [&in](const BvhPrim& ref, glm::vec3 c[3]) {
            for (int k = 0; k < 3; ++k) c[k] = glm::make_vec3(in.tris[ref.id].v + 3 * k);
        },
        1e-6f);
    std::vector<BvhPrim> refs = in.prims;
    const size_t n = refs.size();
    refs.resize(n + size_t(double(budget) * double(n)));
    BvhBuildOptions o;
    o.threads = threads;
    o.maxLeafSize = o.leafTestWidth = 4;
    Built b;
    b.bvh = buildBvh(refs.data(), n, refs.size(), splitter, o);
    refs.resize(b.bvh.primitives);
    b.refs = std::move(refs);
    return b;
}

std::vector<BvhPrim> split(const Input& in, float budget, int threads) { return build(in, budget, threads).refs; }

std::vector<test::TrianglePiece> piecesOf(const std::vector<BvhPrim>& refs) {
    std::vector<test::TrianglePiece> pieces;
    for (const BvhPrim& r : refs) pieces.push_back({r.id, Bounds{glm::make_vec3(r.lo), glm::make_vec3(r.hi)}});
    return pieces;
}

TEST(SpatialSplits, PiecesCoverTheirTrianglesInsideTheirBoxes) {
    const Input in = inputOf(sliverScene(3000, 5u));
    const std::vector<BvhPrim> refs = split(in, 1.0f, 2);
    std::printf("%zu triangles, %zu references\n", in.tris.size(), refs.size());
    EXPECT_GT(refs.size(), in.tris.size() + in.tris.size() / 10) << "slivers this long should be split";
    EXPECT_LE(refs.size(), 2 * in.tris.size()) << "the budget allows one extra reference per triangle";
    EXPECT_TRUE(test::piecesCover(in.tris, piecesOf(refs), 1e-5f));
    size_t outside = 0;
    for (const BvhPrim& r : refs) {
        const BvhPrim& whole = in.prims[r.id];
        for (int a = 0; a < 3; ++a) outside += r.lo[a] < whole.lo[a] - 1e-5f || r.hi[a] > whole.hi[a] + 1e-5f;
    }
    EXPECT_EQ(outside, 0u) << "a piece reaches outside its triangle's box";
    // The tree over them: every reference in one leaf inside the leaf's box.
    const Built built = build(in, 1.0f, 2);
    std::vector<Bounds> boxes;
    std::vector<uint32_t> order;
    for (const BvhPrim& r : built.refs) {
        boxes.push_back(Bounds{glm::make_vec3(r.lo), glm::make_vec3(r.hi)});
        order.push_back(uint32_t(order.size()));
    }
    EXPECT_TRUE(test::bvhIsValid(built.bvh, boxes, 4, order));

    // Negative control: without one piece of a triangle cut in several, the check must see the hole.
    std::vector<test::TrianglePiece> pieces = piecesOf(refs);
    std::vector<int> count(in.tris.size(), 0);
    for (const test::TrianglePiece& p : pieces) ++count[p.tri];
    size_t drop = 0;
    while (drop < pieces.size() && count[pieces[drop].tri] < 3) ++drop;
    ASSERT_LT(drop, pieces.size()) << "no triangle was cut in three";
    pieces.erase(pieces.begin() + std::ptrdiff_t(drop));
    EXPECT_FALSE(test::piecesCover(in.tris, pieces, 1e-5f)) << "the coverage check cannot see a lost piece";
}

TEST(SpatialSplits, BudgetAndThreadsDecideNothingElse) {
    const Input in = inputOf(sliverScene(40000, 9u));  // above the size at which subtrees go to threads
    EXPECT_EQ(split(in, 0.0f, 2).size(), in.tris.size()) << "a budget of 0 splits nothing";
    const std::vector<BvhPrim> small = split(in, 0.05f, 2);
    EXPECT_LE(small.size(), in.tris.size() + in.tris.size() / 20);
    const Built one = build(in, 1.0f, 1);
    for (const int threads : {2, 3}) {
        const Built many = build(in, 1.0f, threads);
        ASSERT_EQ(many.refs.size(), one.refs.size()) << threads << " threads";
        EXPECT_EQ(std::memcmp(many.refs.data(), one.refs.data(), one.refs.size() * sizeof(BvhPrim)), 0)
            << threads << " threads";
        ASSERT_EQ(many.bvh.nodes.size(), one.bvh.nodes.size()) << threads << " threads";
        EXPECT_EQ(std::memcmp(many.bvh.nodes.data(), one.bvh.nodes.data(), one.bvh.nodes.size() * sizeof(BvhNode)), 0)
            << threads << " threads";
    }
    // Negative control: another budget gives other references, and the comparison sees it.
    const std::vector<BvhPrim> other = split(in, 0.5f, 1);
    EXPECT_TRUE(other.size() != one.refs.size() ||
                std::memcmp(other.data(), one.refs.data(), one.refs.size() * sizeof(BvhPrim)) != 0);
}

// A MeshBvh built with `options` finds exactly the hits of one built without spatial splits, closest and any,
// with a negative control; returns the slots of the one with splits.
uint32_t expectSameHits(const Scene& sc, const BvhBuildOptions& options, uint32_t seed) {
    const std::vector<SceneTri> tris = test::sceneTriangles(sc);
    BvhBuildOptions off;
    off.spatialSplitBudget = 0.0f;
    const MeshBvh plain(sc, off), split(sc, options);
    EXPECT_EQ(plain.slotCount(), plain.triangleCount());
    EXPECT_TRUE(test::meshBvhIsValid(split, tris, kMaxMeshLeafSize));
    const std::vector<Ray> rays = test::randomRays(tris, split.bounds(), 20000, seed);
    size_t hits = 0, differ = 0, anyDiffer = 0, control = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const float tMax = i % 3 == 0 ? INFINITY : 0.1f * float(i % 30);
        const std::optional<MeshHit> a = plain.closestHit(rays[i], tMax), b = split.closestHit(rays[i], tMax);
        hits += a.has_value();
        differ += a.has_value() != b.has_value() ||
                  (a && (a->t != b->t || plain.sourceTriangle(a->slot) != split.sourceTriangle(b->slot) ||
                         a->b0 != b->b0 || a->b1 != b->b1 || a->b2 != b->b2));
        anyDiffer += plain.anyHit(rays[i], tMax) != split.anyHit(rays[i], tMax);
        // Negative control: with the bound cut to just before the hit, the split tree must not find it.
        if (a)
            control += !split.closestHit(rays[i], std::nextafter(a->t, 0.0f)).has_value() ||
                       split.closestHit(rays[i], std::nextafter(a->t, 0.0f))->t != a->t;
    }
    EXPECT_GT(hits, rays.size() / 10) << "too few hits to test anything";
    EXPECT_EQ(differ, 0u);
    EXPECT_EQ(anyDiffer, 0u);
    EXPECT_EQ(control, hits) << "the comparison cannot see a changed hit";
    return split.slotCount();
}

TEST(SpatialSplits, MeshBvhFindsTheSameHitsWithAndWithout) {
    const Scene sc = sliverScene(6000, 13u);
    const uint32_t slots = expectSameHits(sc, BvhBuildOptions{}, 14u);
    EXPECT_GT(slots, 6000u + 600u) << "nothing was split";
}

// Room for a fiftieth more references, where splits would take far more: they stop where the room runs out and
// the tree stays whole. Every triangle long and thin: every plane cuts many, and by SAH none pays (the same tree
// as without splits, or nearly).
TEST(SpatialSplits, TheRoomRunsOutAndEveryTriangleLong) {
    BvhBuildOptions fiftieth;
    fiftieth.spatialSplitBudget = 0.02f;
    const uint32_t few = expectSameHits(sliverScene(8000, 21u), fiftieth, 22u);
    EXPECT_GT(few, 8000u) << "no split at all";
    EXPECT_LE(few, 8000u + 160u) << "more references than the room allows";
    const uint32_t all = expectSameHits(sliverScene(8000, 23u, 1), BvhBuildOptions{}, 24u);
    EXPECT_GE(all, 8000u);
    EXPECT_LE(all, 2 * 8000u);
}

}  // namespace
}  // namespace shadelab::trace
