// The sphere set's flat pass (SphereList) against its BVH walk and a scalar loop over shading::intersectSphere:
// the same nearest hit (t bit-equal, same index, the lower index on an exact tie) and the same any-hit answers,
// on random rays and on the rays that stress a sphere test (origins on a surface, grazing rays, duplicates,
// nested and touching spheres, NaN rays). The negative control moves one sphere by one float step.
#include "trace/accel/sphere_list.h"

#include "shading/lighting.h"
#include "trace/accel/sphere_set.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <vector>

using namespace shadelab;
using namespace shadelab::trace;

namespace {

// A failing case's evidence: build/test-output/trace_test/<name>.
std::string evidencePath(const std::string& name) {
    const std::filesystem::path dir(SHADELAB_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// spheres40-like: 40 spheres on a floor, then the awkward cases.
std::vector<Sphere> awkwardSpheres() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Sphere> s;
    for (int i = 0; i < 40; ++i) {
        const float r = 0.3f + 0.9f * u(rng);
        s.push_back(Sphere{"", {(u(rng) - 0.5f) * 20.0f, r, -u(rng) * 12.0f}, r, Material{}});
    }
    s.push_back(s[3]);                                             // an exact duplicate: ties go to the lower index
    s.push_back(Sphere{"", s[5].center, 0.5f * s[5].radius, {}});  // nested inside sphere 5
    s.push_back(Sphere{"", s[9].center + glm::vec3(2.0f * s[9].radius, 0, 0), s[9].radius, {}});  // touching 9
    s.push_back(Sphere{"", {1e4f, 0.0f, -1e4f}, 3.0f, {}});  // far out, where rounding is coarse
    return s;  // 44: eleven full groups of four, then one lane of padding when one is dropped
}

std::vector<Ray> awkwardRays(const std::vector<Sphere>& spheres, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::normal_distribution<float> g;
    auto unit = [&] { return glm::normalize(glm::vec3(g(rng), g(rng), g(rng))); };
    std::vector<Ray> rays;
    for (int i = 0; i < 20000; ++i)  // anywhere through the cluster
        rays.push_back(Ray{{u(rng) * 14.0f, 1.0f + u(rng) * 4.0f, -6.0f + u(rng) * 10.0f}, unit()});
    for (int i = 0; i < 20000; ++i) {  // from a point on a sphere, as secondary and shadow rays start
        const Sphere& s = spheres[size_t(i) % spheres.size()];
        rays.push_back(Ray{s.center + s.radius * unit(), unit()});
    }
    for (int i = 0; i < 5000; ++i) {  // grazing: aimed at the rim of a sphere, within a few float steps
        const Sphere& s = spheres[size_t(i) % spheres.size()];
        const glm::vec3 o(u(rng) * 20.0f, 6.0f, 14.0f), d = glm::normalize(s.center - o);
        glm::vec3 side = glm::normalize(glm::cross(d, unit()));
        const glm::vec3 rim = s.center + s.radius * (1.0f + 1e-6f * u(rng)) * side;
        rays.push_back(Ray{o, glm::normalize(rim - o)});
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    rays.push_back(Ray{{nan, 0, 0}, {0, 0, -1}});
    rays.push_back(Ray{{0, 1, 5}, {nan, nan, nan}});
    return rays;
}

// Counts the rays on which `a` and `b` disagree: nearest hit (t bits and index) for two tMin, any hit for
// several tMax. Writes the first disagreements to `evidence` when given.
template <typename A, typename B>
size_t disagreements(const A& a, const B& b, const std::vector<Ray>& rays, std::ofstream* evidence = nullptr) {
    size_t bad = 0;
    for (const Ray& ray : rays)
        for (const float tMin : {0.0f, 1e-3f}) {
            const std::optional<SphereHit> ha = a.closestHit(ray, tMin, INFINITY),
                                           hb = b.closestHit(ray, tMin, INFINITY);
            const bool same =
                ha.has_value() == hb.has_value() && (!ha || (sameBits(ha->t, hb->t) && ha->index == hb->index));
            const float t = ha ? ha->t : INFINITY;
            bool anySame = true;
            for (const float tMax : {INFINITY, t, std::nextafter(t, INFINITY), 0.5f * t, 1.0f})
                anySame = anySame && a.anyHit(ray, tMin, tMax) == b.anyHit(ray, tMin, tMax);
            if (same && anySame) continue;
            if (evidence && bad < 20)
                *evidence << "origin " << ray.origin.x << ' ' << ray.origin.y << ' ' << ray.origin.z << " dir "
                          << ray.dir.x << ' ' << ray.dir.y << ' ' << ray.dir.z << " tMin " << tMin << ": "
                          << (ha ? ha->t : -1.0f) << " #" << (ha ? int(ha->index) : -1) << " vs "
                          << (hb ? hb->t : -1.0f) << " #" << (hb ? int(hb->index) : -1) << "\n";
            ++bad;
        }
    return bad;
}

// The definition: every sphere in scene order, the first of the nearest.
struct ScalarLoop {
    const std::vector<Sphere>& spheres;
    std::optional<SphereHit> closestHit(const Ray& ray, float tMin, float tMax) const {
        SphereHit best{tMax, UINT32_MAX};
        for (size_t k = 0; k < spheres.size(); ++k) {
            const float t = shading::intersectSphere(ray.origin, ray.dir, spheres[k].center, spheres[k].radius, tMin);
            if (t > tMin && t < best.t) best = SphereHit{t, uint32_t(k)};
        }
        return best.index == UINT32_MAX ? std::nullopt : std::optional<SphereHit>(best);
    }
    bool anyHit(const Ray& ray, float tMin, float tMax) const {
        for (const Sphere& s : spheres) {
            const float t = shading::intersectSphere(ray.origin, ray.dir, s.center, s.radius, tMin);
            if (t > tMin && t < tMax) return true;
        }
        return false;
    }
};

// The flat pass's instruction sets this build and CPU can run: SSE2 always, AVX2 where available.
std::vector<BvhIsa> flatIsas() {
    std::vector<BvhIsa> isas{BvhIsa::Sse2};
    if (bvhIsaAvailable(BvhIsa::Avx2)) isas.push_back(BvhIsa::Avx2);
    return isas;
}

TEST(SphereList, FlatPassMatchesTheTreeAndTheScalarLoopBitForBit) {
    // Whole groups of eight, a padded last group, a padded half, one sphere.
    for (const BvhIsa isa : flatIsas())
        for (const size_t count : {40u, 44u, 43u, 1u}) {
            std::vector<Sphere> spheres = awkwardSpheres();
            spheres.resize(count);
            const std::vector<Ray> rays = awkwardRays(spheres, 11u + uint32_t(count));
            const SphereSet flat(spheres, spheres.size(), isa), tree(spheres, 0);
            ASSERT_TRUE(flat.flat());
            ASSERT_FALSE(tree.flat());
            const std::string name = std::string("sphere_list_") + bvhIsaName(isa) + "_" + std::to_string(count);
            std::ofstream evidence(evidencePath(name + ".txt"));
            const size_t vsTree = disagreements(flat, tree, rays, &evidence);
            const size_t vsLoop = disagreements(flat, ScalarLoop{spheres}, rays, &evidence);
            EXPECT_EQ(vsTree, 0u) << bvhIsaName(isa) << ", " << count << " spheres; first rays in "
                                  << evidencePath(name + ".txt");
            EXPECT_EQ(vsLoop, 0u) << bvhIsaName(isa) << ", " << count << " spheres";
            size_t hits = 0;
            for (const Ray& r : rays) hits += flat.closestHit(r, 0.0f, INFINITY).has_value();
            EXPECT_GT(hits, rays.size() / 4) << "the rays must hit often enough to test anything";
        }
}

TEST(SphereList, ExactTiesGoToTheLowerIndexAcrossLanes) {
    // The same sphere at indices 2, 5 (the other SSE half), 6 and 11 (the next group): the nearest is always 2.
    for (const BvhIsa isa : flatIsas()) {
        std::vector<Sphere> s(16, Sphere{"", {10, 10, 10}, 0.5f, {}});
        for (const int k : {2, 5, 6, 11}) s[size_t(k)] = Sphere{"", {0, 0, -3}, 1.0f, {}};
        const SphereList list(s, isa);
        const std::optional<SphereHit> h = list.closestHit(Ray{{0, 0, 0}, {0, 0, -1}}, 0.0f, INFINITY);
        ASSERT_TRUE(h) << bvhIsaName(isa);
        EXPECT_EQ(h->index, 2u) << bvhIsaName(isa);
        EXPECT_EQ(h->t, 2.0f);
        EXPECT_FALSE(list.closestHit(Ray{{0, 0, 0}, {0, 0, -1}}, 0.0f, 2.0f)) << "a hit at tMax itself is no hit";
        EXPECT_TRUE(list.anyHit(Ray{{0, 0, 0}, {0, 0, -1}}, 0.0f, 2.5f));
        EXPECT_FALSE(list.anyHit(Ray{{0, 0, 0}, {0, 0, -1}}, 0.0f, 2.0f));
        // Only the later copies left: the nearest is the lowest of them, 5, in the other half.
        s[2] = Sphere{"", {10, 10, 10}, 0.5f, {}};
        const std::optional<SphereHit> later =
            SphereList(s, isa).closestHit(Ray{{0, 0, 0}, {0, 0, -1}}, 0.0f, INFINITY);
        ASSERT_TRUE(later);
        EXPECT_EQ(later->index, 5u) << bvhIsaName(isa);
    }
    EXPECT_FALSE(SphereList{}.closestHit(Ray{{0, 0, 0}, {0, 0, -1}}, 0.0f, INFINITY));
}

TEST(SphereList, NegativeControlOneSphereMovedByOneFloatStepDisagrees) {
    const std::vector<Sphere> spheres = awkwardSpheres();
    std::vector<Sphere> moved = spheres;
    moved[17].radius = std::nextafter(moved[17].radius, INFINITY);
    const std::vector<Ray> rays = awkwardRays(spheres, 12u);
    for (const BvhIsa isa : flatIsas())
        EXPECT_GT(disagreements(SphereSet(moved, moved.size(), isa), SphereSet(spheres, 0), rays), 10u)
            << bvhIsaName(isa);
}

}  // namespace
