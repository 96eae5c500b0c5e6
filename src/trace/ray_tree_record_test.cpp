// The ray view's record (WhittedIntegrator::recordPrimary) and its algebra (ray_algebra.h): recording changes
// nothing; every recorded ray is one the tracer traced, with its hit and t (re-asked of the tracer's own
// intersection); every shadow ray's answer is the tracer's; the algebra's t is the hit's t. Over 1,000 pixels
// of the default scene and of a glass, mirror and mesh scene; a tree recorded one bounce shallower differs.
#include "scene/scene_load.h"
#include "scene/view.h"
#include "trace/integrator.h"
#include "trace/ray_algebra.h"
#include "trace/tile_renderer.h"
#include "trace/trace_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace shadelab;
using namespace shadelab::trace;

namespace {

// A glass sphere (kr 0.1, kt 0.9) before a mirror sphere and a mirrored box (triangles), over a checker
// floor with kr 0.3, two lights: every kind of ray, every kind of hit, and shadows cast by each.
Scene glassScene() {
    Scene sc;
    sc.camera.position = {0.0f, 2.0f, 7.0f};
    sc.camera.target = {0.0f, 0.6f, 0.0f};
    sc.ambient = glm::vec3(0.15f);
    sc.background = {0.1f, 0.15f, 0.3f};
    sc.maxDepth = 5;
    sc.lights.push_back(Light{LightType::Point, "key", {-4, 7, 5}, {0, -1, 0}, {1.0f, 0.95f, 0.9f}, {1, 0, 0}});
    sc.lights.push_back(Light{LightType::Directional, "sun", {0, 0, 0}, {0.3f, -1, -0.2f}, glm::vec3(0.4f), {1, 0, 0}});
    Material glass = test::plainMaterial(glm::vec3(0.02f), glm::vec3(0.05f), glm::vec3(0.8f), 200.0f);
    glass.kr = glm::vec3(0.1f);
    glass.kt = glm::vec3(0.9f);
    Material mirror = test::plainMaterial(glm::vec3(0.05f), glm::vec3(0.1f), glm::vec3(0.6f), 100.0f);
    mirror.kr = {0.8f, 0.8f, 0.7f};
    Material floor = test::plainMaterial(glm::vec3(0.3f), glm::vec3(0.7f), glm::vec3(0.2f), 16.0f);
    floor.kr = glm::vec3(0.3f);
    sc.spheres.push_back(Sphere{"glass", {0.0f, 1.0f, 0.5f}, 1.0f, glass});
    sc.spheres.push_back(Sphere{"mirror", {-2.2f, 1.0f, -1.0f}, 1.0f, mirror});
    sc.planes.push_back(Plane{"floor", {0, 1, 0}, 0.0f, floor, Checker{glm::vec3(0.1f), 1.0f}});
    Mesh box;
    box.name = "box";
    box.parts.push_back(test::cubePart({1.4f, 0.0f, -1.5f}, {3.0f, 1.6f, 0.0f}, mirror));
    sc.meshes.push_back(box);
    return sc;
}

struct Pixel {
    int i, j;
};
// 1,000 pixels spread over a w x h image (40 x 25, the grid's cell centres).
std::vector<Pixel> thousandPixels(int w, int h) {
    std::vector<Pixel> px;
    for (int b = 0; b < 25; ++b)
        for (int a = 0; a < 40; ++a) px.push_back({(2 * a + 1) * w / 80, (2 * b + 1) * h / 50});
    return px;
}

// What a tree is, for the negative control: each ray's kind, parent, hit object and t.
bool sameTree(const RayTreeRecord& a, const RayTreeRecord& b) {
    if (a.rays.size() != b.rays.size()) return false;
    for (size_t k = 0; k < a.rays.size(); ++k) {
        const TreeRay &x = a.rays[k], &y = b.rays[k];
        if (x.kind != y.kind || x.parent != y.parent || x.hitId != y.hitId || x.blocked != y.blocked) return false;
        if (x.hit.has_value() != y.hit.has_value() || (x.hit && x.hit->t != y.hit->t)) return false;
    }
    return true;
}

struct Checked {
    int rays = 0, shadows = 0, blocked = 0, spheres = 0, planes = 0, triangles = 0, deepest = 0;
};

// Everything the record must agree with the tracer on, for one scene.
Checked checkScene(const Scene& sc, const std::string& what) {
    const int w = 320, h = 180;
    const TraceScene ts(sc);
    const WhittedIntegrator wi(ts, sc.maxDepth);
    const ViewSetup view = makeViewSetup(sc, w, h);
    Checked c;
    for (const Pixel& p : thousandPixels(w, h)) {
        const Ray primary = sampleRay(view, 1, p.i, p.j, 0, 0);
        TreeStats plain, recorded;
        const PrimarySample expected = wi.primary(primary, nullptr, &plain);
        RayTreeRecord tree;
        const PrimarySample got = wi.recordPrimary(primary, tree, &recorded);
        const std::string at = what + " pixel " + std::to_string(p.i) + "," + std::to_string(p.j);
        // Recording changes nothing.
        EXPECT_EQ(got.color, expected.color) << at;
        EXPECT_EQ(got.coverage, expected.coverage) << at;
        EXPECT_EQ(recorded.secondaryRays, plain.secondaryRays) << at;
        EXPECT_EQ(recorded.pruned, plain.pruned) << at;
        // The tree: rooted at the primary ray, parents before children, one record per secondary ray.
        EXPECT_FALSE(tree.rays.empty()) << at;
        if (tree.rays.empty()) continue;
        EXPECT_EQ(tree.rays[0].kind, TreeRayKind::Primary) << at;
        EXPECT_EQ(tree.rays[0].ray.origin, primary.origin) << at;
        EXPECT_EQ(tree.rays[0].hitId, expected.coverage) << at;
        int secondary = 0;
        for (size_t k = 0; k < tree.rays.size(); ++k) {
            const TreeRay& r = tree.rays[k];
            ++c.rays;
            c.deepest = std::max(c.deepest, r.depth);
            EXPECT_LT(r.parent, int(k)) << at;
            if (k > 0) {
                EXPECT_GE(r.parent, 0) << at;
            }
            if (r.kind == TreeRayKind::Reflected || r.kind == TreeRayKind::Refracted) {
                ++secondary;
                EXPECT_EQ(r.depth, tree.rays[size_t(r.parent)].depth + 1) << at;
            }
            if (r.kind == TreeRayKind::Shadow) {
                ++c.shadows;
                // The tracer's answer for this very ray.
                EXPECT_EQ(r.blocked, ts.occluded(r.ray, r.tMax)) << at << " ray " << k;
                if (r.blocked) {
                    ++c.blocked;
                    EXPECT_TRUE(r.hit.has_value()) << at << " ray " << k;
                    if (r.hit) {
                        EXPECT_LT(r.hit->t, r.tMax) << at;
                    }
                }
                continue;
            }
            // The same hit and t from the tracer's own intersection.
            const std::optional<Hit> again = wi.visibleHit(r.ray, r.after, r.depth);
            EXPECT_EQ(again.has_value(), r.hit.has_value()) << at << " ray " << k;
            if (!r.hit || !again) continue;
            EXPECT_EQ(again->t, r.hit->t) << at << " ray " << k;
            EXPECT_EQ(ts.coverageId(*again), r.hitId) << at << " ray " << k;
            if (r.after > 0.0f) continue;  // the algebra is of rays from o, t > 0
            // The algebra reproduces the tracer's t: exactly for spheres and planes, to 1e-6 relative for triangles.
            const Hit& hit = *r.hit;
            if (hit.kind == HitKind::Sphere) {
                ++c.spheres;
                const Sphere& s = sc.spheres[hit.index];
                EXPECT_EQ(sphereAlgebra(r.ray, s.center, s.radius).t, hit.t) << at << " ray " << k;
            } else if (hit.kind == HitKind::Plane) {
                ++c.planes;
                const Plane& pl = sc.planes[hit.index];
                EXPECT_EQ(planeAlgebra(r.ray, pl.normal, pl.offset).t, hit.t) << at << " ray " << k;
            } else {
                ++c.triangles;
                const MeshGeometry& g = *ts.meshPart(hit).geometry;
                const size_t tri = 3 * size_t(ts.triangleInPart(hit));
                const TriangleAlgebra t =
                    triangleAlgebra(r.ray, g.positions[g.indices[tri]], g.positions[g.indices[tri + 1]],
                                    g.positions[g.indices[tri + 2]]);
                // Relative to the ray's scale: t, or the coordinates' size when t is tiny (a float hit point
                // cannot be closer than its coordinates' rounding).
                const double scale = std::max(double(hit.t), double(glm::length(r.ray.origin)));
                EXPECT_NEAR(t.t, double(hit.t), 1e-6 * scale) << at << " ray " << k;
                EXPECT_NEAR(t.b0, double(hit.b0), 1e-5) << at;
                EXPECT_NEAR(t.b1, double(hit.b1), 1e-5) << at;
                EXPECT_NEAR(t.b2, double(hit.b2), 1e-5) << at;
            }
            EXPECT_FALSE(rayAlgebraLines(ts, r.ray, hit).empty());
        }
        EXPECT_EQ(secondary, plain.secondaryRays) << at;
    }
    return c;
}

}  // namespace

TEST(RayTreeRecord, DefaultSceneTreesAreTheTracersOwn) {
    const Checked c = checkScene(loadScene(SHADELAB_SOURCE_DIR "/assets/scenes/default.json"), "default.json");
    // The default scene has spheres, a floor, shadows cast: every check above ran.
    EXPECT_GT(c.spheres, 100);
    EXPECT_GT(c.planes, 100);
    EXPECT_GT(c.shadows, 1000);
    EXPECT_GT(c.blocked, 10);
}

TEST(RayTreeRecord, GlassSceneTreesAreTheTracersOwn) {
    const Checked c = checkScene(glassScene(), "glass scene");
    EXPECT_GT(c.triangles, 50);
    EXPECT_GT(c.blocked, 10);
    EXPECT_GE(c.deepest, 3);
}

TEST(RayTreeRecord, ATreeCutOneBounceShallowerDiffers) {
    // Negative control: the comparison above would see a tracer that stopped one bounce early.
    const Scene sc = glassScene();
    const TraceScene ts(sc);
    const WhittedIntegrator full(ts, sc.maxDepth), cut(ts, sc.maxDepth - 1);
    const ViewSetup view = makeViewSetup(sc, 320, 180);
    int differ = 0;
    for (const Pixel& p : thousandPixels(320, 180)) {
        const Ray primary = sampleRay(view, 1, p.i, p.j, 0, 0);
        RayTreeRecord a, b;
        full.recordPrimary(primary, a);
        cut.recordPrimary(primary, b);
        EXPECT_TRUE(sameTree(a, a));
        differ += sameTree(a, b) ? 0 : 1;
    }
    EXPECT_GT(differ, 10);
}

TEST(RayAlgebra, SphereRootsAndWhichIsTaken) {
    // From outside: the nearer root. o = (0, 0, 5), d = −z, unit sphere at the origin: t = 4 and 6.
    const SphereAlgebra out = sphereAlgebra(Ray{{0, 0, 5}, {0, 0, -1}}, glm::vec3(0.0f), 1.0f);
    EXPECT_TRUE(out.real);
    EXPECT_EQ(out.a, 1.0f);
    EXPECT_EQ(out.b, -10.0f);
    EXPECT_EQ(out.c, 24.0f);
    EXPECT_EQ(out.discriminant, 100.0f - 96.0f);
    EXPECT_EQ(out.tNear, 4.0f);
    EXPECT_EQ(out.tFar, 6.0f);
    EXPECT_EQ(out.taken, 1);
    EXPECT_EQ(out.t, 4.0f);
    // From inside: the nearer root is behind, the farther taken.
    const SphereAlgebra in = sphereAlgebra(Ray{{0, 0, 0}, {0, 0, -1}}, glm::vec3(0.0f), 1.0f);
    EXPECT_EQ(in.taken, 2);
    EXPECT_EQ(in.t, 1.0f);
    // A miss: Δ < 0.
    const SphereAlgebra miss = sphereAlgebra(Ray{{0, 2, 5}, {0, 0, -1}}, glm::vec3(0.0f), 1.0f);
    EXPECT_FALSE(miss.real);
    EXPECT_LT(miss.discriminant, 0.0f);
    EXPECT_EQ(miss.t, -1.0f);
    // Negative control: a sphere behind the ray takes neither root.
    EXPECT_EQ(sphereAlgebra(Ray{{0, 0, 5}, {0, 0, 1}}, glm::vec3(0.0f), 1.0f).taken, 0);
}

TEST(RayAlgebra, PlaneParallelAndBehind) {
    const PlaneAlgebra hit = planeAlgebra(Ray{{0, 2, 0}, {0, -1, 0}}, {0, 1, 0}, 0.0f);
    EXPECT_FALSE(hit.parallel);
    EXPECT_EQ(hit.t, 2.0f);
    const PlaneAlgebra parallel = planeAlgebra(Ray{{0, 2, 0}, {1, 0, 0}}, {0, 1, 0}, 0.0f);
    EXPECT_TRUE(parallel.parallel);
    EXPECT_EQ(parallel.t, -1.0f);
    EXPECT_EQ(planeAlgebra(Ray{{0, 2, 0}, {0, 1, 0}}, {0, 1, 0}, 0.0f).t, -1.0f);  // behind
}

TEST(RayAlgebra, TriangleBarycentrics) {
    const TriangleAlgebra t = triangleAlgebra(Ray{{0.25f, 0.25f, 1}, {0, 0, -1}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    EXPECT_NEAR(t.t, 1.0, 1e-12);
    EXPECT_NEAR(t.b0, 0.5, 1e-12);
    EXPECT_NEAR(t.b1, 0.25, 1e-12);
    EXPECT_NEAR(t.b2, 0.25, 1e-12);
}
