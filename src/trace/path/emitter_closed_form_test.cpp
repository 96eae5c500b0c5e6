// Next-event estimation of area emitters against closed forms, for each estimator on its own (BSDF sampling,
// light sampling, MIS): the irradiance a uniform sphere emitter gives a diffuse floor at gaps from 2 % of its
// radius upwards and sunk into the floor (its cone above the horizon, integrated numerically), the same from
// an emissive square (Lambert's polygon formula), and the radiance inside an emitting sphere. A light sample
// shadowed by its own emitter near the rim made the light and MIS estimators about 10 % dark next to a
// sphere lamp while BSDF sampling stayed right; these receivers sit where that shows. Each point is
// rendered by PathRender as a 1x1 image through a camera whose pixel is a tiny spot (so its jitter does not
// move the point), with maxDepth 0: the floor's direct light only. Negative controls: a 3 % brighter
// expectation is refused at the same sample counts, and so is a pixel wide enough to move the receiver.
#include "shading/lighting.h"
#include "trace/path/path_render.h"
#include "trace/trace_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace shadelab::trace {
namespace {

constexpr float kAlbedo = 0.5f;  // the floor's md: Lo = md/π · E
constexpr float kRadiance = 2.0f;
constexpr double kPiD = 3.14159265358979323846;

// A diffuse floor y = 0 and nothing else; the camera looks at `point` from `from` (a direction away from the
// emitter) with a field of view so narrow that the pixel's footprint is about 1e-5 wide.
Scene floorScene(const glm::vec3& point, const glm::vec3& from, float fovY = 1e-3f) {
    Scene scene;
    scene.model = ShadingModel::Phong;
    scene.background = glm::vec3(0.0f);
    scene.terms.specular = false;
    Plane floor;
    floor.material = test::plainMaterial(glm::vec3(0.0f), glm::vec3(kAlbedo));
    scene.planes.push_back(floor);
    scene.camera.position = point + glm::normalize(from);
    scene.camera.target = point;
    scene.camera.fovY = fovY;
    return scene;
}

Material emitter() {
    Material m = test::plainMaterial(glm::vec3(0.0f));
    m.emission = glm::vec3(kRadiance);
    return m;
}

// E at a point with normal n from a sphere of radiance L: L ∫ max(0, n·ω) dω over the cone the sphere
// subtends, by the midpoint rule in (θ, φ) around the cone's axis, in double.
double sphereIrradiance(const glm::dvec3& P, const glm::dvec3& n, const glm::dvec3& centre, double radius) {
    const glm::dvec3 toC = centre - P;
    const double d = glm::length(toC);
    const glm::dvec3 a = toC / d;
    const double alpha = std::asin(radius / d);
    const glm::dvec3 t =
        glm::normalize(std::abs(a.x) < 0.9 ? glm::cross(a, glm::dvec3(1, 0, 0)) : glm::cross(a, glm::dvec3(0, 1, 0)));
    const glm::dvec3 b = glm::cross(a, t);
    const int nt = 800, np = 1600;
    double sum = 0.0;
    for (int i = 0; i < nt; ++i) {
        const double th = (i + 0.5) * alpha / nt;
        for (int j = 0; j < np; ++j) {
            const double ph = (j + 0.5) * 2.0 * kPiD / np;
            const glm::dvec3 w = std::cos(th) * a + std::sin(th) * (std::cos(ph) * t + std::sin(ph) * b);
            sum += std::max(0.0, glm::dot(n, w)) * std::sin(th);
        }
    }
    return kRadiance * sum * (alpha / nt) * (2.0 * kPiD / np);
}

// Lambert's formula for a polygon wholly above the horizon: E = L/2 Σ γ_i n·(v_i × v_{i+1})/|v_i × v_{i+1}|,
// γ_i the angle between the unit vectors to consecutive corners (Arvo 1995, "Applications of Irradiance
// Tensors"), for corners wound counter-clockwise as seen from P.
double polygonIrradiance(const glm::dvec3& P, const glm::dvec3& n, const std::vector<glm::dvec3>& corners) {
    double sum = 0.0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 u = glm::normalize(corners[i] - P), v = glm::normalize(corners[(i + 1) % corners.size()] - P);
        const glm::dvec3 c = glm::cross(u, v);
        sum += std::acos(std::clamp(glm::dot(u, v), -1.0, 1.0)) * glm::dot(n, c) / glm::length(c);
    }
    return kRadiance * 0.5 * std::abs(sum);
}

struct Estimate {
    double mean = 0.0, se = 0.0;
};

Estimate renderPoint(const Scene& scene, PathEstimator estimator, int spp) {
    PathSettings s;
    s.width = s.height = 1;
    s.spp = spp;
    s.maxDepth = 0;
    s.threads = 2;
    s.estimator = estimator;
    PathRender r(std::make_shared<const TraceScene>(scene), s);
    r.addSamples(spp);
    return {double(r.mean(0, 0).y), double(r.standardError(0, 0).y)};
}

struct Receiver {
    std::string what;
    Scene scene;
    double expected = 0.0;  // Lo of the floor point
    int lightSamples = 1;   // times more samples for light sampling alone, where it is noisy
};

// How many samples each estimator needs for about 0.5 % standard error here: BSDF sampling finds a small
// lamp only by chance; area sampling of a large lamp just above the point has a variance ∝ 1/gap².
int samplesFor(PathEstimator e, const Receiver& r) {
    return e == PathEstimator::Bsdf ? 524288 : e == PathEstimator::Light ? 32768 * r.lightSamples : 32768;
}

// The receivers near a sphere lamp of radius 0.2: gaps from 0.02 to 0.5 above the floor, and sunk 0.05 into
// it (part of its cone then lies below the floor's horizon), at several distances from below its centre.
std::vector<Receiver> sphereReceivers() {
    std::vector<Receiver> out;
    const float radius = 0.2f;
    const struct {
        float gap, h;
    } cases[] = {{0.02f, 0.0f}, {0.02f, 0.1f},  {0.02f, 0.3f}, {0.1f, 0.2f},
                 {0.5f, 0.4f},  {-0.05f, 0.2f}, {-0.05f, 0.5f}};
    for (const auto& c : cases) {
        const glm::vec3 centre(0.0f, radius + c.gap, 0.0f), P(c.h, 0.0f, 0.0f);
        Receiver r;
        char name[64];
        std::snprintf(name, sizeof name, "sphere gap %.2f at %.1f", double(c.gap), double(c.h));
        r.what = name;
        // Seen from low over the floor on the far side (+x): the view ray never meets the lamp.
        r.scene = floorScene(P, glm::vec3(1.0f, 0.05f, 0.0f));
        Sphere lamp;
        lamp.center = centre;
        lamp.radius = radius;
        lamp.material = emitter();
        r.scene.spheres.push_back(lamp);
        r.expected = kAlbedo / kPiD * sphereIrradiance(P, glm::dvec3(0, 1, 0), centre, radius);
        out.push_back(std::move(r));
    }
    return out;
}

// A square lamp of side 0.4 facing the floor at gap 0.02 and 0.2, two triangles of one mesh.
std::vector<Receiver> squareReceivers() {
    std::vector<Receiver> out;
    for (const float gap : {0.02f, 0.2f})
        for (const float h : {0.0f, 0.15f}) {
            const std::vector<glm::vec3> c = {
                {-0.2f, gap, -0.2f}, {0.2f, gap, -0.2f}, {0.2f, gap, 0.2f}, {-0.2f, gap, 0.2f}};
            const glm::vec3 P(h, 0.0f, 0.05f);
            Receiver r;
            char name[64];
            std::snprintf(name, sizeof name, "square gap %.2f at %.2f", double(gap), double(h));
            r.what = name;
            r.scene = floorScene(P, glm::vec3(1.0f, 0.02f, 0.0f));
            r.lightSamples = gap < 0.1f ? 32 : 1;
            Mesh lamp;
            lamp.parts.push_back(test::makePart(c, {0, 1, 2, 0, 2, 3}, glm::vec3(0.0f, gap, 0.0f)));
            lamp.parts[0].material = emitter();
            r.scene.meshes.push_back(lamp);
            r.expected = kAlbedo / kPiD *
                         polygonIrradiance(P, glm::dvec3(0, 1, 0),
                                           {glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]), glm::dvec3(c[3])});
            out.push_back(std::move(r));
        }
    return out;
}

// Every receiver within 3 standard errors of its closed form, and (negative control) not within 3 of a value
// 3 % brighter.
void expectClosedForm(const std::vector<Receiver>& receivers, PathEstimator e) {
    for (const Receiver& r : receivers) {
        const Estimate est = renderPoint(r.scene, e, samplesFor(e, r));
        const double z = (est.mean - r.expected) / est.se, zBright = (est.mean - 1.03 * r.expected) / est.se;
        std::printf("%-5s %-26s %.5f ± %.5f, closed form %.5f (%+.2f %%, z %+.2f; against +3 %%: z %+.2f)\n",
                    toString(e), r.what.c_str(), est.mean, est.se, r.expected, 100.0 * (est.mean / r.expected - 1.0), z,
                    zBright);
        EXPECT_LT(std::abs(z), 3.0) << toString(e) << ", " << r.what << ": " << est.mean << " ± " << est.se
                                    << " against " << r.expected;
        EXPECT_GT(std::abs(zBright), 3.0)
            << toString(e) << ", " << r.what << ": the control (3 % brighter) is not told apart";
    }
}

TEST(EmitterClosedForm, NumericConeIntegralEqualsTheClosedFormWhenTheSphereIsWhollyAboveTheHorizon) {
    // E = π L sin²α cos β (the sphere as seen from P subtends half-angle α, its centre at β from the normal).
    const glm::dvec3 P(0.3, 0.0, 0.0), centre(0.0, 0.22, 0.0);
    const double d = glm::length(centre - P), sinA = 0.2 / d, cosB = 0.22 / d;
    EXPECT_NEAR(sphereIrradiance(P, glm::dvec3(0, 1, 0), centre, 0.2), kPiD * kRadiance * sinA * sinA * cosB, 1e-5);
    // Lambert's formula on a tiny square straight above at distance 1: a point-like patch, E = L · area.
    const double s = 1e-3;
    const std::vector<glm::dvec3> tiny = {{-s, 1, -s}, {s, 1, -s}, {s, 1, s}, {-s, 1, s}};
    EXPECT_NEAR(polygonIrradiance(glm::dvec3(0.0), glm::dvec3(0, 1, 0), tiny) / (kRadiance * 4 * s * s), 1.0, 1e-5);
}

TEST(EmitterClosedForm, SphereLampOverAFloorBsdfSampling) { expectClosedForm(sphereReceivers(), PathEstimator::Bsdf); }
TEST(EmitterClosedForm, SphereLampOverAFloorLightSampling) {
    expectClosedForm(sphereReceivers(), PathEstimator::Light);
}
TEST(EmitterClosedForm, SphereLampOverAFloorMis) { expectClosedForm(sphereReceivers(), PathEstimator::Mis); }

TEST(EmitterClosedForm, SquareLampOverAFloorEachEstimator) {
    for (PathEstimator e : {PathEstimator::Bsdf, PathEstimator::Light, PathEstimator::Mis})
        expectClosedForm(squareReceivers(), e);
}

// Inside a diffuse emitting sphere of albedo 0.5 and emission 0.5, L = 1 everywhere (pbrt-v4's test), with
// the emitter sampled by area from a point on itself.
TEST(EmitterClosedForm, InsideAnEmittingSphereEachEstimator) {
    for (PathEstimator e : {PathEstimator::Bsdf, PathEstimator::Light, PathEstimator::Mis}) {
        Scene scene;
        scene.model = ShadingModel::Phong;
        scene.terms.specular = false;
        scene.background = glm::vec3(0.0f);
        scene.camera.position = glm::vec3(0.0f);
        scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
        scene.camera.fovY = 1e-3f;
        Sphere s;
        s.radius = 1.0f;
        s.material = test::plainMaterial(glm::vec3(0.0f), glm::vec3(0.5f));
        s.material.emission = glm::vec3(0.5f);
        scene.spheres.push_back(s);
        PathSettings ps;
        ps.width = ps.height = 1;
        ps.spp = 16384;
        ps.maxDepth = 64;
        ps.threads = 2;
        ps.estimator = e;
        PathRender r(std::make_shared<const TraceScene>(scene), ps);
        r.addSamples(ps.spp);
        const double mean = r.mean(0, 0).y, se = r.standardError(0, 0).y;
        std::printf("%-5s inside: %.5f ± %.5f (expected 1)\n", toString(e), mean, se);
        EXPECT_LT(std::abs(mean - 1.0), 3.0 * se) << toString(e);
        EXPECT_GT(std::abs(mean - 1.03), 3.0 * se) << toString(e) << ": the control (1.03) is not told apart";
    }
}

// A receiver that is not where the closed form is computed must fail: a pixel 5 degrees wide, seen from low
// over the floor, spreads the shading point from 0.5 to 8 away from under the lamp.
TEST(EmitterClosedForm, NegativeControlAWideSpotIsNotThePoint) {
    const glm::vec3 P(0.0f, 0.0f, 0.0f);
    Scene scene = floorScene(P, glm::vec3(1.0f, 0.05f, 0.0f), 5.0f);
    Sphere lamp;
    lamp.center = glm::vec3(0.0f, 0.22f, 0.0f);
    lamp.radius = 0.2f;
    lamp.material = emitter();
    scene.spheres.push_back(lamp);
    const double expected = kAlbedo / kPiD * sphereIrradiance(glm::dvec3(P), glm::dvec3(0, 1, 0), lamp.center, 0.2);
    const Estimate est = renderPoint(scene, PathEstimator::Mis, 32768);
    std::printf("wide spot: %.5f ± %.5f against the point's %.5f\n", est.mean, est.se, expected);
    EXPECT_GT(std::abs(est.mean - expected), 3.0 * est.se);
}

}  // namespace
}  // namespace shadelab::trace
