// planeFootprint: every pixel whose ray (the shaders' own cameraRayDirection and intersectPlane, compiled as
// C++) hits the plane lies inside the polygon, over many cameras, planes, bands and jitters; and the polygon
// leaves out the sky where there is one. sphereHole: every pixel in a hole sees the sphere, nearer than the
// plane. footprintTriangles: they cover the footprint less the holes, and nothing in the holes.
#include "raster/plane_footprint.h"

#include "shading/lighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

namespace shadelab::raster {
namespace {

// Whether window point (fx, fy) of a width x height viewport lies inside the fan (convex, either winding).
bool inside(const PlaneFootprint& f, int width, int height, float fx, float fy) {
    if (f.count < 3) return false;
    const glm::vec2 p(2.0f * fx / float(width) - 1.0f, 2.0f * fy / float(height) - 1.0f);
    int positive = 0, negative = 0;
    for (int k = 0; k < f.count; ++k) {
        const glm::vec2 a = f.corners[k], b = f.corners[(k + 1) % f.count];
        const float cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        positive += cross >= 0.0f;
        negative += cross <= 0.0f;
    }
    return positive == f.count || negative == f.count;
}

struct Counts {
    int hits = 0, missedHits = 0, covered = 0, pixels = 0;
};

// plane.frag's test at every pixel centre of a band `rows` high whose bottom is GL row `band` of the image.
Counts check(const PlaneCamera& c, int width, int rows, const glm::vec3& n, float offset, const PlaneFootprint& f) {
    Counts out;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < width; ++x) {
            const float fx = float(x) + 0.5f, fy = float(y) + 0.5f;
            const glm::vec3 dir = shading::cameraRayDirection(c.forward, c.right, c.up, c.viewport.z, c.viewport.x,
                                                              c.viewport.y, fx, c.viewport.y - (fy + c.viewport.w));
            const bool hit = shading::intersectPlane(c.eye, dir, n, offset, 0.0f) >= 0.0f;
            const bool in = inside(f, width, rows, fx, fy);
            out.hits += hit;
            out.missedHits += hit && !in;
            out.covered += in;
            ++out.pixels;
        }
    return out;
}

PlaneCamera lookAt(glm::vec3 eye, glm::vec3 target, float fovY, int width, int height, glm::vec2 jitter = {}) {
    PlaneCamera c;
    c.eye = eye;
    const glm::vec3 f = glm::normalize(target - eye);
    c.right = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
    c.up = glm::cross(c.right, f);
    const float t = std::tan(0.5f * fovY), aspect = float(width) / float(height);
    // As makeFrameBlock moves forward by the jitter.
    c.forward =
        f + (2.0f * jitter.x / float(width)) * t * aspect * c.right - (2.0f * jitter.y / float(height)) * t * c.up;
    c.viewport = glm::vec4(float(width), float(height), t, 0.0f);
    c.viewProj = glm::perspective(fovY, aspect, 0.1f, 1000.0f) * glm::lookAt(eye, eye + f, c.up);
    return c;
}

// Whether point q (normalised device coordinates) lies in one of the triangles.
bool covered(const std::vector<glm::vec2>& tris, glm::vec2 q) {
    for (size_t k = 0; k + 2 < tris.size(); k += 3) {
        const glm::vec2 a = tris[k], b = tris[k + 1], c = tris[k + 2];
        const float d0 = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
        const float d1 = (c.x - b.x) * (q.y - b.y) - (c.y - b.y) * (q.x - b.x);
        const float d2 = (a.x - c.x) * (q.y - c.y) - (a.y - c.y) * (q.x - c.x);
        if ((d0 >= 0.0f && d1 >= 0.0f && d2 >= 0.0f) || (d0 <= 0.0f && d1 <= 0.0f && d2 <= 0.0f)) return true;
    }
    return false;
}

// Whether q lies in the hole (counter-clockwise, convex).
bool inHole(const FootprintHole& h, glm::vec2 q) {
    if (h.count < 3) return false;
    for (int k = 0; k < h.count; ++k) {
        const glm::vec2 a = h.corners[k], b = h.corners[(k + 1) % h.count];
        if ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) < 0.0f) return false;
    }
    return true;
}

// The default scene's camera, floor and five spheres at w x h.
struct DefaultScene {
    int w = 160, h = 90;
    PlaneCamera camera = lookAt({0.0f, 2.5f, 9.0f}, {0.0f, 0.7f, 0.0f}, glm::radians(35.0f), 160, 90);
    glm::vec3 n{0.0f, 1.0f, 0.0f};
    glm::vec4 spheres[5] = {{-3.0f, 0.8f, 0.5f, 0.8f},
                            {-1.4f, 0.6f, 1.8f, 0.6f},
                            {0.2f, 1.0f, -0.6f, 1.0f},
                            {1.8f, 0.7f, 1.3f, 0.7f},
                            {3.3f, 0.9f, -0.4f, 0.9f}};
};

TEST(PlaneFootprint, TheDefaultViewLeavesOutTheSkyAndKeepsEveryFloorPixel) {
    const int w = 128, h = 72;
    const PlaneCamera c = lookAt({0.0f, 2.5f, 9.0f}, {0.0f, 0.7f, 0.0f}, glm::radians(35.0f), w, h);
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const PlaneFootprint f = planeFootprint(c, w, h, n, 0.0f);
    const Counts k = check(c, w, h, n, 0.0f, f);
    EXPECT_EQ(k.missedHits, 0);
    EXPECT_GT(k.hits, k.pixels / 2);
    EXPECT_LT(k.covered, k.pixels * 9 / 10);  // the sky above the horizon is left out
    EXPECT_LE(k.covered, k.hits + 4 * w);     // within a few rows of the horizon
    // Negative control: a footprint drawn three pixels inside the horizon misses floor pixels.
    EXPECT_GT(check(c, w, h, n, 0.0f, planeFootprint(c, w, h, n, 0.0f, -3.0f)).missedHits, 0);
}

TEST(PlaneFootprint, NoPixelCanHitAPlaneBehindTheCamera) {
    const int w = 64, h = 48;
    const PlaneCamera c = lookAt({0.0f, 2.0f, 5.0f}, {0.0f, 6.0f, 0.0f}, glm::radians(40.0f), w, h);  // 39° up
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const PlaneFootprint f = planeFootprint(c, w, h, n, 0.0f);
    EXPECT_EQ(check(c, w, h, n, 0.0f, f).hits, 0);
    EXPECT_EQ(f.count, 0);
}

TEST(PlaneFootprint, RandomCamerasPlanesBandsAndJittersMissNoHit) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int shrunk = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int w = 40 + int(40.0f * (u(rng) + 1.0f)), fullH = 30 + int(30.0f * (u(rng) + 1.0f));
        const glm::vec3 eye(5.0f * u(rng), 5.0f * u(rng), 5.0f * u(rng));
        const glm::vec3 target = eye + glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.0f, 0.0f, 0.01f);
        PlaneCamera c = lookAt(eye, target, glm::radians(30.0f + 60.0f * (u(rng) + 1.0f)), w, fullH,
                               glm::vec2(0.5f * u(rng), 0.5f * u(rng)));
        // A band of the image: its rows from GL row `bottom` up.
        const int rows = trial % 3 == 0 ? fullH : std::max(1, fullH / 3), bottom = trial % 3 == 0 ? 0 : fullH / 2;
        c.viewport.w = float(bottom);
        glm::vec3 n(u(rng), u(rng), u(rng));
        if (glm::length(n) < 0.1f) n = glm::vec3(0.0f, 1.0f, 0.0f);
        n = glm::normalize(n);
        const float offset = 3.0f * u(rng);
        const PlaneFootprint f = planeFootprint(c, w, rows, n, offset);
        const Counts k = check(c, w, rows, n, offset, f);
        ASSERT_EQ(k.missedHits, 0) << "trial " << trial;
        shrunk += k.covered < k.pixels;
    }
    EXPECT_GT(shrunk, 50);  // the footprint is often smaller than the viewport
}

TEST(PlaneFootprint, EveryPixelInASphereHoleSeesTheSphereBeforeThePlane) {
    const DefaultScene d;
    const PlaneFootprint f = planeFootprint(d.camera, d.w, d.h, d.n, 0.0f);
    int holes = 0, holePixels = 0;
    for (const glm::vec4& s : d.spheres) {
        // The default scene's spheres rest on the floor (touching it); lifted a little, too.
        const glm::vec3 centre = glm::vec3(s) + glm::vec3(0.0f, (&s - d.spheres) % 2 == 0 ? 0.0f : 0.05f, 0.0f);
        const FootprintHole hole = sphereHole(d.camera, d.w, d.h, d.n, 0.0f, centre, s.w, f);
        holes += hole.count > 0;
        for (int y = 0; y < d.h; ++y)
            for (int x = 0; x < d.w; ++x) {
                const float fx = float(x) + 0.5f, fy = float(y) + 0.5f;
                if (!inHole(hole, {2.0f * fx / float(d.w) - 1.0f, 2.0f * fy / float(d.h) - 1.0f})) continue;
                ++holePixels;
                const PlaneCamera& c = d.camera;
                const glm::vec3 dir = shading::cameraRayDirection(c.forward, c.right, c.up, c.viewport.z, c.viewport.x,
                                                                  c.viewport.y, fx, c.viewport.y - fy);
                const float ts = shading::intersectSphere(c.eye, dir, centre, s.w, 0.0f);
                const float tp = shading::intersectPlane(c.eye, dir, d.n, 0.0f, 0.0f);
                ASSERT_GT(ts, 0.0f) << x << "," << y;
                ASSERT_TRUE(tp < 0.0f || ts < tp) << x << "," << y;
            }
    }
    EXPECT_EQ(holes, 5);
    EXPECT_GT(holePixels, 1000);
}

TEST(PlaneFootprint, AHoleDrawnOutsideTheSilhouetteIsCaught) {
    // Negative control for the test above: the octagon moved outward instead of inward covers misses.
    const DefaultScene d;
    const PlaneFootprint f = planeFootprint(d.camera, d.w, d.h, d.n, 0.0f);
    const glm::vec3 centre(0.2f, 1.05f, -0.6f);
    FootprintHole hole = sphereHole(d.camera, d.w, d.h, d.n, 0.0f, centre, 1.0f, f, 0.5f);
    ASSERT_EQ(hole.count, 8);
    glm::vec2 g(0.0f);
    for (int k = 0; k < 8; ++k) g += hole.corners[k] / 8.0f;
    for (int k = 0; k < 8; ++k) hole.corners[k] = g + 1.2f * (hole.corners[k] - g);
    int misses = 0;
    for (int y = 0; y < d.h; ++y)
        for (int x = 0; x < d.w; ++x) {
            const float fx = float(x) + 0.5f, fy = float(y) + 0.5f;
            if (!inHole(hole, {2.0f * fx / float(d.w) - 1.0f, 2.0f * fy / float(d.h) - 1.0f})) continue;
            const PlaneCamera& c = d.camera;
            const glm::vec3 dir = shading::cameraRayDirection(c.forward, c.right, c.up, c.viewport.z, c.viewport.x,
                                                              c.viewport.y, fx, c.viewport.y - fy);
            misses += shading::intersectSphere(c.eye, dir, centre, 1.0f, 0.0f) < 0.0f;
        }
    EXPECT_GT(misses, 0);
}

TEST(PlaneFootprint, NoHoleWhereTheSphereCrossesThePlaneOrHoldsTheEye) {
    const DefaultScene d;
    const PlaneFootprint f = planeFootprint(d.camera, d.w, d.h, d.n, 0.0f);
    EXPECT_EQ(sphereHole(d.camera, d.w, d.h, d.n, 0.0f, {0.0f, 0.5f, 0.0f}, 1.0f, f).count, 0);   // sunk in
    EXPECT_EQ(sphereHole(d.camera, d.w, d.h, d.n, 0.0f, {0.0f, 0.99f, 0.0f}, 1.0f, f).count, 0);  // sunk a little
    EXPECT_EQ(sphereHole(d.camera, d.w, d.h, d.n, 0.0f, {0.0f, -3.0f, 0.0f}, 1.0f, f).count, 0);  // beneath
    EXPECT_EQ(sphereHole(d.camera, d.w, d.h, d.n, 0.0f, d.camera.eye, 1.0f, f).count, 0);         // the eye inside
    EXPECT_EQ(sphereHole(d.camera, d.w, d.h, d.n, 0.0f, {0.0f, 1.5f, 0.0f}, 1e-3f, f).count, 0);  // too small
}

TEST(PlaneFootprint, TrianglesCoverTheFootprintLessTheHolesExactly) {
    const DefaultScene d;
    const PlaneFootprint f = planeFootprint(d.camera, d.w, d.h, d.n, 0.0f);
    std::vector<FootprintHole> holes;
    for (const glm::vec4& s : d.spheres)
        holes.push_back(sphereHole(d.camera, d.w, d.h, d.n, 0.0f, glm::vec3(s) + glm::vec3(0.0f, 0.05f, 0.0f), s.w, f));
    // Two holes that overlap: the smaller is dropped, and its pixels stay covered.
    FootprintHole overlapping = holes[2];
    for (int k = 0; k < 8; ++k) overlapping.corners[k] = 0.5f * overlapping.corners[k] + 0.5f * holes[2].corners[0];
    holes.push_back(overlapping);
    const std::vector<glm::vec2> tris = footprintTriangles(f, holes);
    ASSERT_EQ(tris.size() % 3, 0u);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    // Every point of the footprint outside the holes is covered, nothing outside the footprint is, and most of
    // the holes are left out (a hole whose box meets another's is dropped, so not all of them).
    int inFootprint = 0, holesLeftOut = 0;
    for (int i = 0; i < 40000; ++i) {
        const glm::vec2 q(u(rng), u(rng));
        bool hole = false;
        for (const FootprintHole& h : holes) hole = hole || inHole(h, q);
        const bool in = inside(f, 2, 2, q.x + 1.0f, q.y + 1.0f);
        if (!in) {
            EXPECT_FALSE(covered(tris, q)) << q.x << "," << q.y;
        } else if (hole) {
            holesLeftOut += !covered(tris, q);
        } else {
            ++inFootprint;
            EXPECT_TRUE(covered(tris, q)) << q.x << "," << q.y;
        }
    }
    EXPECT_GT(holesLeftOut, 400);
    EXPECT_GT(inFootprint, 10000);
    // Without holes, the footprint's fan.
    EXPECT_EQ(footprintTriangles(f, {}).size(), size_t(3 * (f.count - 2)));
    // Negative control: with one hole's triangles lost, its neighbours' pixels are found uncovered.
    std::vector<glm::vec2> cut(tris.begin() + 3, tris.end());
    int uncovered = 0;
    for (int i = 0; i < 40000; ++i) {
        const glm::vec2 q(u(rng), u(rng));
        bool hole = false;
        for (const FootprintHole& h : holes) hole = hole || inHole(h, q);
        uncovered += !hole && inside(f, 2, 2, q.x + 1.0f, q.y + 1.0f) && !covered(cut, q);
    }
    EXPECT_GT(uncovered, 0);
}

}  // namespace
}  // namespace shadelab::raster
