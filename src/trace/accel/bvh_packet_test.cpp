// Packets of eight rays (MeshBvh::closestHit8 / anyHit8, TraceScene::intersect8 / occluded8) against the
// single-ray walks: every ray's hit bit for bit (t, triangle, barycentrics) and the same any-hit answer, for
// coherent fans from one eye (the frustum path: the rays share their directions' signs), shadow-like rays from
// spread origins toward one point, incoherent rays of mixed signs (each child tested per ray), partial packets,
// rays that must leave the packet (NaN, an origin whose products overflow) and short bounds. The negative control
// cuts each single-ray bound to just before the packet's hit, which the comparison must see.
#include "scene/scene_load.h"
#include "trace/accel/bvh_isa.h"
#include "trace/accel/bvh_test_util.h"
#include "trace/accel/mesh_bvh.h"
#include "trace/trace_scene.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <vector>

using namespace shadelab;
using namespace shadelab::trace;
using namespace shadelab::trace::test;

namespace {

bool sameHit(const MeshBvh& bvh, const std::optional<MeshHit>& a, const std::optional<MeshHit>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (std::memcmp(&a->t, &b->t, 4) == 0 && bvh.sourceTriangle(a->slot) == bvh.sourceTriangle(b->slot) &&
                  std::memcmp(&a->b0, &b->b0, 4) == 0 && std::memcmp(&a->b1, &b->b1, 4) == 0 &&
                  std::memcmp(&a->b2, &b->b2, 4) == 0);
}

// Rays in groups of eight: fans of neighbouring directions from one eye outside the bounds, shadow-like rays from
// points around the bounds toward one light, then random rays of any direction, then the odd ones out.
std::vector<Ray> packetRays(const std::vector<SceneTri>& tris, const Bounds& b, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const glm::vec3 centre = 0.5f * (b.lo + b.hi), ext = b.hi - b.lo;
    const float radius = glm::length(ext);
    std::vector<Ray> rays;
    for (int fan = 0; fan < 600; ++fan) {
        const glm::vec3 eye = centre + radius * glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        const glm::vec3 aim = centre + 0.4f * ext * glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 side = glm::normalize(glm::cross(aim - eye, glm::vec3(u(rng), u(rng), u(rng))));
        for (int k = 0; k < 8; ++k) rays.push_back(rayTowards(eye, aim + (0.002f * radius * float(k)) * side));
    }
    for (int group = 0; group < 600; ++group) {
        const glm::vec3 light = centre + 2.0f * radius * glm::normalize(glm::vec3(u(rng), 1.0f, u(rng)));
        const glm::vec3 spot = centre + 0.5f * ext * glm::vec3(u(rng), u(rng), u(rng));
        for (int k = 0; k < 8; ++k) {
            const glm::vec3 o = spot + 0.01f * radius * glm::vec3(u(rng), u(rng), u(rng));
            rays.push_back(rayTowards(o, light));
        }
    }
    const std::vector<Ray> loose = randomRays(tris, b, 4800, seed + 1);
    rays.insert(rays.end(), loose.begin(), loose.end() - ptrdiff_t(loose.size() % 8));
    // A packet with a NaN ray and a ray whose box-test products overflow: both walk alone beside the others.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int k = 0; k < 8; ++k) rays.push_back(rayTowards(centre + radius * glm::vec3(1, 0.3f, 0.2f), centre));
    rays[rays.size() - 3].origin.x = nan;
    rays[rays.size() - 6] = Ray{centre + glm::vec3(3e38f, 0.0f, 0.0f), glm::vec3(-1.0f, 1e-31f, 0.0f)};
    return rays;
}

// Bounds cut short on some rays: 0 (nothing), a fraction of the way, open.
float boundOf(size_t i) { return i % 5 == 0 ? INFINITY : i % 7 == 0 ? 0.0f : 0.05f * float(i % 40); }

// Each packet of `rays` (every third one partial) against the single-ray walks, with the negative control.
void expectPacketsMatchSingleRays(const MeshBvh& bvh, const std::vector<Ray>& rays) {
    size_t hits = 0, occluded = 0, badClosest = 0, badAny = 0, control = 0;
    for (size_t first = 0; first + 8 <= rays.size(); first += 8) {
        // Whole packets, and every third one partial (some lanes not asked).
        const unsigned valid = (first / 8) % 3 == 2 ? 0xB5u : 0xFFu;
        float tMax[8];
        for (int k = 0; k < 8; ++k) tMax[k] = boundOf(first + size_t(k));
        MeshHit out[8];
        const unsigned found = bvh.closestHit8(&rays[first], tMax, valid, out);
        const unsigned blocked = bvh.anyHit8(&rays[first], tMax, valid);
        for (int k = 0; k < 8; ++k) {
            const Ray& ray = rays[first + size_t(k)];
            const bool asked = (valid >> k) & 1;
            const std::optional<MeshHit> single = bvh.closestHit(ray, tMax[k]);
            const std::optional<MeshHit> packet =
                asked && (found >> k) & 1 ? std::optional<MeshHit>(out[k]) : std::nullopt;
            if (!asked) {
                badClosest += (found >> k) & 1;
                badAny += (blocked >> k) & 1;
                continue;
            }
            hits += single.has_value();
            occluded += (blocked >> k) & 1;
            const bool same = sameHit(bvh, single, packet);
            badClosest += !same;
            if (!same) ADD_FAILURE() << describe(first + size_t(k), ray) << " closest hit differs";
            badAny += bvh.anyHit(ray, tMax[k]) != bool((blocked >> k) & 1);
            if (packet) control += !sameHit(bvh, bvh.closestHit(ray, std::nextafter(packet->t, 0.0f)), packet);
        }
    }
    std::printf("%s: %zu rays, %zu hits, %zu occluded\n", bvhIsaName(defaultBvhIsa()), rays.size(), hits, occluded);
    EXPECT_GT(hits, rays.size() / 8) << "too few hits to test anything";
    EXPECT_EQ(badClosest, 0u);
    EXPECT_EQ(badAny, 0u);
    EXPECT_EQ(control, hits) << "the comparison cannot see a changed hit";
}

TEST(BvhPacket, EightRaysAtOnceFindTheirOwnHitsBitForBit) {
    std::vector<Scene> scenes;
    scenes.push_back(soupScene(20000, 77u));
    const std::string path = modelPath("2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    if (std::filesystem::exists(path)) scenes.push_back(loadScene(path));
    for (const Scene& sc : scenes) {
        const MeshBvh bvh(sc);
        expectPacketsMatchSingleRays(bvh, packetRays(sceneTriangles(sc), bvh.bounds(), 5u));
    }
}

// A grid of 0.1-unit squares, two triangles each, and packets whose rays all reach the same few leaves (so the
// leaf is tested once for the packet) straight down onto vertices, edges and the squares' diagonals, where an edge
// function is exactly 0 and a ray must leave the packet's leaf test for its own: mixed with rays inside the
// triangles, tilted ones, and rays that start below the grid (no hit).
TEST(BvhPacket, RaysThroughEdgesAndCornersLeaveThePacketsLeafTest) {
    Scene sc;
    sc.meshes.push_back(Mesh{});
    MeshGeometry g;
    constexpr int kN = 12;
    for (int j = 0; j <= kN; ++j)
        for (int i = 0; i <= kN; ++i) g.positions.push_back(glm::vec3(0.1f * float(i), 0.1f * float(j), 0.0f));
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const uint32_t a = uint32_t(j * (kN + 1) + i), b = a + 1, c = a + kN + 1, d = c + 1;
            for (uint32_t v : {a, b, d, a, d, c}) g.indices.push_back(v);
        }
    sc.meshes[0].parts.push_back(MeshPart{shareGeometry(std::move(g)), Material{}});
    const MeshBvh bvh(sc);
    std::vector<Ray> rays;
    const float offsets[8][2] = {{0, 0},         {0.5f, 0},      {0, 0.5f}, {0.5f, 0.5f},
                                 {0.25f, 0.75f}, {0.75f, 0.25f}, {1, 1},    {1, 0.5f}};
    for (int j = 1; j < kN - 1; ++j)
        for (int i = 1; i < kN - 1; ++i)
            for (int variant = 0; variant < 3; ++variant)
                for (const auto& o : offsets) {
                    // On the grid's own float coordinates: vertices, edge midpoints, the diagonal.
                    const glm::vec3 at(0.1f * (float(i) + o[0]), 0.1f * (float(j) + o[1]), 1.0f);
                    const glm::vec3 dir = variant == 0   ? glm::vec3(0, 0, -1)
                                          : variant == 1 ? glm::vec3(0.001f * o[0], -0.002f * o[1], -1)
                                                         : glm::vec3(0, 0, 1);  // away from the grid
                    rays.push_back(Ray{variant == 1 ? at
                                                    : glm::vec3(0.1f * float(i), 0.1f * float(j), 1.0f) +
                                                          glm::vec3(0.1f * o[0], 0.1f * o[1], 0.0f),
                                       dir});
                }
    expectPacketsMatchSingleRays(bvh, rays);
}

// The whole scene's packets: spheres, a plane and triangles, with the ties between kinds that intersect() settles.
TEST(TracePacket, IntersectEightAndOccludedEightAreIntersectAndOccluded) {
    Scene sc = soupScene(4000, 78u);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    // Spheres around the soup, where the rays from outside meet them first.
    for (int i = 0; i < 24; ++i)
        sc.spheres.push_back(Sphere{"", 1.4f * glm::normalize(glm::vec3(u(rng), u(rng), u(rng))),
                                    0.2f + 0.1f * std::fabs(u(rng)), Material{}});
    sc.planes.push_back(Plane{"", {0.0f, 1.0f, 0.0f}, 0.9f, Material{}, std::nullopt});
    const TraceScene ts(sc);
    const std::vector<Ray> rays = packetRays(sceneTriangles(sc), ts.meshBvh()->bounds(), 6u);
    size_t hits = 0, kinds[3] = {0, 0, 0}, bad = 0, badOccluded = 0;
    for (size_t first = 0; first + 8 <= rays.size(); first += 8) {
        std::optional<Hit> out[8];
        float tMax[8];
        for (int k = 0; k < 8; ++k) tMax[k] = boundOf(first + size_t(k));
        ts.intersect8(&rays[first], 0xFFu, out);
        const unsigned blocked = ts.occluded8(&rays[first], tMax, 0xFFu);
        for (int k = 0; k < 8; ++k) {
            const Ray& ray = rays[first + size_t(k)];
            const std::optional<Hit> single = ts.intersect(ray);
            // A triangle by its scene-order index: one cut by spatial splits fills several slots, and the two walks
            // may reach it through different ones.
            auto object = [&ts](const Hit& h) {
                return h.kind == HitKind::Triangle ? ts.meshBvh()->sourceTriangle(h.index) : h.index;
            };
            const bool same =
                single.has_value() == out[k].has_value() &&
                (!single || (std::memcmp(&single->t, &out[k]->t, 4) == 0 && single->kind == out[k]->kind &&
                             object(*single) == object(*out[k]) && std::memcmp(&single->b0, &out[k]->b0, 12) == 0));
            bad += !same;
            badOccluded += ts.occluded(ray, tMax[k]) != bool((blocked >> k) & 1);
            if (single) ++hits, ++kinds[int(single->kind)];
        }
    }
    std::printf("%zu hits: %zu spheres, %zu planes, %zu triangles\n", hits, kinds[0], kinds[1], kinds[2]);
    EXPECT_GT(kinds[0], 100u);
    EXPECT_GT(kinds[1], 100u);
    EXPECT_GT(kinds[2], 100u);
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(badOccluded, 0u);
}

}  // namespace
