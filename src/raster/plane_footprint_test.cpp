// planeFootprint: every pixel whose ray (the shaders' own cameraRayDirection and intersectPlane, compiled as
// C++) hits the plane lies inside the polygon, over many cameras, planes, bands and jitters; and the polygon
// leaves out the sky where there is one.
#include "raster/plane_footprint.h"

#include "shading/lighting.h"

#include <gtest/gtest.h>

#include <cmath>
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
    return c;
}

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

}  // namespace
}  // namespace shadelab::raster
