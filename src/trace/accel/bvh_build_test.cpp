// The BVH builder's own properties (bvh.h, mesh_bvh.h): empty and single inputs, identical boxes within the
// depth limit, the options and the SAH cost, and the same tree and gathered triangles for any thread count.
// Traversal against brute force is bvh_test.cpp.
#include "trace/accel/bvh.h"
#include "trace/accel/bvh_invariants.h"
#include "trace/accel/bvh_test_util.h"
#include "trace/accel/mesh_bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace shadelab;
using namespace shadelab::trace;
using namespace shadelab::trace::test;

namespace {

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

uint32_t leavesOf(const Bvh& b) {
    uint32_t leaves = 0;
    for (const BvhNode& nd : b.nodes)
        for (int k = 0; k < kBvhWidth; ++k)
            if (nd.used(k) && isLeafRef(nd.child[k])) ++leaves;
    return leaves;
}

TEST(BvhBuild, RangesTheLeafTestTakesWholeAreLeaves) {
    // Clusters of four boxes in a row, far apart: the SAH with one test per primitive splits a cluster into
    // leaves of two or one, which saves nothing when one leaf test takes four.
    std::vector<Bounds> boxes;
    for (int c = 0; c < 400; ++c)
        for (int i = 0; i < 4; ++i) {
            const glm::vec3 p(float(c % 20) * 10.0f + float(i) * 1.5f, float(c / 20) * 10.0f, 0.0f);
            boxes.push_back(box(p, p + glm::vec3(1.0f)));
        }
    BvhBuildOptions o;
    o.leafTestWidth = 4;
    const Bvh wide = buildBvh(boxes, o);
    EXPECT_TRUE(bvhIsValid(wide, boxes, o.maxLeafSize));
    EXPECT_EQ(leavesOf(wide), 400u) << "one leaf per cluster";
    // Negative control: with the default (one primitive per test) the SAH splits the clusters.
    const Bvh narrow = buildBvh(boxes);
    EXPECT_TRUE(bvhIsValid(narrow, boxes, o.maxLeafSize));
    EXPECT_GT(leavesOf(narrow), 400u);
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

TEST(MeshBvhBuild, SameForAnyThreadCount) {
    // MeshBvh gathers its triangles and their leaf-order positions on the build's threads (above 100,000
    // triangles): any thread count must give the same slots, positions, ids, nodes and bounds. A soup of many
    // parts (ranges split inside parts) plus a part of degenerate and non-finite triangles (left out).
    Scene sc = soupScene(120000, 7u);
    MeshGeometry odd;
    for (int i = 0; i < 3000; ++i) {
        const float x = float(i) * 1e-3f;
        glm::vec3 v[3] = {{x, 0.0f, 0.0f}, {x, 1.0f, 0.0f}, {x + 0.5f, 0.0f, 1.0f}};
        if (i % 3 == 0) v[2] = v[1];        // degenerate
        if (i % 5 == 0) v[1].y = INFINITY;  // not finite
        for (const glm::vec3& q : v) {
            odd.indices.push_back(uint32_t(odd.positions.size()));
            odd.positions.push_back(q);
        }
    }
    sc.meshes[0].parts.push_back(MeshPart{shareGeometry(std::move(odd)), Material{}});
    auto same = [](const MeshBvh& a, const MeshBvh& b) {
        if (a.slotCount() != b.slotCount() || a.bvh().nodes.size() != b.bvh().nodes.size()) return false;
        for (uint32_t s = 0; s < a.slotCount(); ++s)
            if (a.vertices(s) != b.vertices(s) || a.sourceTriangle(s) != b.sourceTriangle(s) || a.part(s) != b.part(s))
                return false;
        return std::memcmp(a.bvh().nodes.data(), b.bvh().nodes.data(), a.bvh().nodes.size() * sizeof(BvhNode)) == 0 &&
               a.bounds().lo == b.bounds().lo && a.bounds().hi == b.bounds().hi;
    };
    BvhBuildOptions o;
    o.threads = 1;
    const MeshBvh one(sc, o);
    // 120,000 soup triangles and the 3000 - 1000 - 600 + 200 = 1,600 sound ones of the odd part.
    EXPECT_EQ(one.triangleCount(), 121600u);
    for (const int t : {2, 3}) {
        o.threads = t;
        EXPECT_TRUE(same(one, MeshBvh(sc, o))) << t << " threads gathered differently";
    }
    // Negative control: a different bin count builds a different tree, and the comparison sees it.
    o.bins = 8;
    EXPECT_FALSE(same(one, MeshBvh(sc, o)));
}

}  // namespace
