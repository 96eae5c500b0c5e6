// fitShadows without a GL context: every caster inside its layer, the cube-face order of shaders/cube_face.glsl,
// the plane mask against the tracer's opposite-side rule, and the depth-test constants; each with a negative
// control that must fail the same check.
#include "raster/shadow_fit.h"
#include "raster/cube_face.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <utility>
#include <vector>

namespace shadelab::raster {
namespace {

using Rng = std::mt19937;

float uniform(Rng& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
glm::vec3 uniform3(Rng& rng, float lo, float hi) {
    const float x = uniform(rng, lo, hi), y = uniform(rng, lo, hi);
    return {x, y, uniform(rng, lo, hi)};
}
glm::vec3 unitVector(Rng& rng) {
    for (;;) {
        const glm::vec3 v = uniform3(rng, -1.0f, 1.0f);
        const float n = glm::length(v);
        if (n > 0.1f && n <= 1.0f) return v / n;
    }
}
glm::vec3 pointIn(Rng& rng, const Bounds& b) {
    return b.lo + glm::vec3(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1)) * (b.hi - b.lo);
}

// A scene and the draw ranges RasterRenderer::uploadMeshes would build for it: one per mesh part, with its
// world bounds. Only the ranges' bounds matter to fitting, so the parts themselves stay empty.
struct Stage {
    Scene scene;
    std::vector<DrawRange> ranges;
};

// Each caster's own box: each sphere's and each mesh part's.
std::vector<Bounds> casterBoxes(const Stage& stage) {
    std::vector<Bounds> boxes;
    for (const Sphere& s : stage.scene.spheres)
        boxes.push_back({s.center - glm::vec3(s.radius), s.center + glm::vec3(s.radius)});
    for (const DrawRange& r : stage.ranges) boxes.push_back({r.lo, r.hi});
    return boxes;
}

// Spheres and mesh parts somewhere in [-4, 4]³, and planes with random normals. Lights: one directional,
// one point far outside (a perspective layer), one near the casters' centre (a cube), then more at random.
Stage randomStage(Rng& rng) {
    Stage stage;
    Scene& scene = stage.scene;
    scene.camera.position = uniform3(rng, -10.0f, 10.0f);
    const int spheres = std::uniform_int_distribution<int>(0, 4)(rng);
    for (int i = 0; i < spheres; ++i) {
        Sphere s;
        s.center = uniform3(rng, -4.0f, 4.0f);
        s.radius = uniform(rng, 0.05f, 1.5f);
        scene.spheres.push_back(s);
    }
    const int meshes = std::uniform_int_distribution<int>(spheres == 0 ? 1 : 0, 2)(rng);
    scene.meshes.resize(size_t(meshes));
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        scene.meshes[m].parts.resize(size_t(std::uniform_int_distribution<int>(1, 3)(rng)));
        for (size_t p = 0; p < scene.meshes[m].parts.size(); ++p) {
            const glm::vec3 centre = uniform3(rng, -4.0f, 4.0f);
            const glm::vec3 a = centre + uniform3(rng, -1.0f, 1.0f), b = centre + uniform3(rng, -1.0f, 1.0f);
            stage.ranges.push_back({m, p, 0, 3, glm::min(a, b), glm::max(a, b)});
        }
    }
    const int planes = std::uniform_int_distribution<int>(0, 4)(rng);
    for (int i = 0; i < planes; ++i) {
        Plane p;
        p.normal = unitVector(rng);
        p.offset = uniform(rng, -6.0f, 6.0f);
        scene.planes.push_back(p);
    }
    const Bounds box = casterBounds(scene, stage.ranges);
    Light directional;
    directional.type = LightType::Directional;
    directional.direction = unitVector(rng) * uniform(rng, 0.5f, 2.0f);  // need not be unit
    Light far;
    far.position = box.centroid() + unitVector(rng) * uniform(rng, 12.0f, 40.0f);
    Light inside;  // within 0.3 of the bounding sphere's radius from its centre
    inside.position = box.centroid() + uniform3(rng, -0.3f, 0.3f) * 0.5f * (box.hi - box.lo);
    scene.lights = {directional, far, inside};
    while (scene.lights.size() < size_t(kMaxShadowedLights)) {
        Light l;
        if (uniform(rng, 0, 1) < 0.3f) {
            l.type = LightType::Directional;
            l.direction = unitVector(rng);
        } else {
            l.position = uniform3(rng, -12.0f, 12.0f);
        }
        scene.lights.push_back(l);
    }
    return stage;
}

RasterSettings fineSettings() {
    RasterSettings s;
    s.shadowMapSize = 2048;  // the thinnest margins fitShadows adds
    return s;
}

ShadowFit fitStage(const Stage& stage) {
    return fitShadows(stage.scene, casterBounds(stage.scene, stage.ranges), fineSettings());
}

// Points of a caster that fall in a layer but outside its clip volume, or in a layer that culls the caster's
// box (outsideClip, as the depth pass does). Each caster box is sampled at its corners and inside; a cube
// light's point counts for the face shaders/cube_face.glsl picks for it.
int castersOutsideTheirLayers(const Stage& stage, const ShadowFit& fit, Rng& rng) {
    const Scene& scene = stage.scene;
    int misses = 0;
    const std::vector<Bounds> boxes = casterBoxes(stage);
    const int lights = std::min<int>(int(scene.lights.size()), kMaxShadowedLights);
    for (int i = 0; i < lights; ++i) {
        const int kind = fit.block.light[i].x, first = fit.block.light[i].y;
        if (kind == kShadowNone) continue;
        const glm::vec3 L = scene.lights[size_t(i)].position;
        for (const Bounds& b : boxes) {
            for (int k = 0; k < 8 + 24; ++k) {
                const glm::vec3 p = k < 8 ? b.corner(k) : pointIn(rng, b);
                int layer = first;
                if (kind == kShadowCube) {
                    const glm::vec3 d = p - L;
                    const int face = glsl::cubeFace(d);
                    if (glsl::cubeFaceCoords(d, face).z <= fit.block.range[i].y) continue;  // nearer than zNear
                    layer += face;
                }
                const glm::mat4& vp = fit.block.layerViewProj[layer];
                const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
                const float w = clip.w * (1.0f + 1e-5f);
                const bool inside =
                    clip.w > 0.0f && std::abs(clip.x) <= w && std::abs(clip.y) <= w && std::abs(clip.z) <= w;
                if (!inside || outsideClip(vp, b.lo, b.hi)) ++misses;
            }
        }
    }
    return misses;
}

TEST(ShadowFit, LayersPerLightKind) {
    Rng rng(1);
    const Stage stage = randomStage(rng);
    const Scene& scene = stage.scene;
    const ShadowFit fit = fitStage(stage);
    EXPECT_EQ(fit.block.light[0].x, kShadowOrtho);
    EXPECT_EQ(fit.block.light[1].x, kShadowPerspective);
    EXPECT_EQ(fit.block.light[2].x, kShadowCube);
    int layers = 0;
    for (int i = 0; i < kMaxShadowedLights; ++i) {
        EXPECT_EQ(fit.block.light[i].y, layers) << "light " << i;
        layers += fit.block.light[i].x == kShadowCube ? 6 : 1;
    }
    EXPECT_EQ(fit.layers, layers);
    EXPECT_EQ(fit.block.info.z, 2048);
    ASSERT_EQ(fit.block.info.x, int(scene.planes.size()));
    for (size_t k = 0; k < scene.planes.size(); ++k)
        EXPECT_EQ(fit.block.planes[k], glm::vec4(scene.planes[k].normal, scene.planes[k].offset));
}

TEST(ShadowFit, NoCastersNoLayers) {
    Scene scene;
    Plane floor;
    scene.planes = {floor};
    scene.lights = {Light{}};
    const ShadowFit fit = fitShadows(scene, casterBounds(scene, {}), fineSettings());
    EXPECT_EQ(fit.layers, 0);
    EXPECT_EQ(fit.block.light[0].x, kShadowNone);
    EXPECT_EQ(fit.block.info.x, 1);
}

TEST(ShadowFit, RangesNamingNoPartAreSkipped) {
    Scene scene;
    Sphere s;
    scene.spheres = {s};
    const std::vector<DrawRange> stale = {{3, 0, 0, 3, glm::vec3(50.0f), glm::vec3(60.0f)}};
    const Bounds b = casterBounds(scene, stale);
    EXPECT_EQ(b.lo, glm::vec3(-1.0f));
    EXPECT_EQ(b.hi, glm::vec3(1.0f));
}

TEST(ShadowFit, EveryCasterInsideItsLayer) {
    for (unsigned seed = 1; seed <= 40; ++seed) {
        Rng rng(seed);
        const Stage stage = randomStage(rng);
        EXPECT_EQ(castersOutsideTheirLayers(stage, fitStage(stage), rng), 0) << "seed " << seed;
    }
}

// Negative control: the same check on layers zoomed in by 10 % must find casters outside.
TEST(ShadowFit, EveryCasterInsideItsLayerNegativeControl) {
    const glm::mat4 zoom = glm::scale(glm::mat4(1.0f), glm::vec3(1.1f, 1.1f, 1.0f));
    for (unsigned seed = 1; seed <= 10; ++seed) {
        Rng rng(seed);
        const Stage stage = randomStage(rng);
        ShadowFit fit = fitStage(stage);
        for (int layer = 0; layer < fit.layers; ++layer)
            fit.block.layerViewProj[layer] = zoom * fit.block.layerViewProj[layer];
        EXPECT_GT(castersOutsideTheirLayers(stage, fit, rng), 0) << "seed " << seed;
    }
}

// Directions from a cube light whose layer (the face cubeFace picks) disagrees with the shader's coordinates:
// cubeFaceCoords must be that layer's NDC xy and its w, and lie inside [-1, 1].
int faceMismatches(const ShadowBlock& block, int first, const glm::vec3& L, Rng& rng) {
    int misses = 0;
    for (int k = 0; k < 2000; ++k) {
        const glm::vec3 d = unitVector(rng) * uniform(rng, 0.5f, 3.0f);
        const int face = glsl::cubeFace(d);
        const glm::vec3 c = glsl::cubeFaceCoords(d, face);
        const glm::vec4 clip = block.layerViewProj[first + face] * glm::vec4(L + d, 1.0f);
        const bool same = std::abs(clip.x / clip.w - c.x) <= 1e-4f && std::abs(clip.y / clip.w - c.y) <= 1e-4f &&
                          std::abs(clip.w - c.z) <= 1e-4f * c.z;
        const bool inside = std::abs(c.x) <= 1.0f && std::abs(c.y) <= 1.0f;
        if (!same || !inside) ++misses;
    }
    return misses;
}

TEST(ShadowFit, CubeFaceOrderMatchesShader) {
    Rng rng(7);
    const Stage stage = randomStage(rng);
    const Scene& scene = stage.scene;
    const ShadowFit fit = fitStage(stage);
    ASSERT_EQ(fit.block.light[2].x, kShadowCube);
    const int first = fit.block.light[2].y;
    const glm::vec3 L = scene.lights[2].position;
    // +X −X +Y −Y +Z −Z: a point along each axis lands in its layer's centre, two units away.
    for (int face = 0; face < 6; ++face) {
        glm::vec3 d(0.0f);
        d[face / 2] = face % 2 ? -2.0f : 2.0f;
        EXPECT_EQ(glsl::cubeFace(d), face);
        const glm::vec4 clip = fit.block.layerViewProj[first + face] * glm::vec4(L + d, 1.0f);
        EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-5f) << "face " << face;
        EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-5f) << "face " << face;
        EXPECT_NEAR(clip.w, 2.0f, 1e-5f) << "face " << face;
    }
    // A point off +X towards +Y and +Z: layer 0, up the face and to the right (lookAt's right is +Z there).
    const glm::vec3 c = glsl::cubeFaceCoords(glm::vec3(2.0f, 0.5f, 1.0f), 0);
    EXPECT_FLOAT_EQ(c.x, 0.5f);
    EXPECT_FLOAT_EQ(c.y, 0.25f);
    EXPECT_FLOAT_EQ(c.z, 2.0f);
    EXPECT_EQ(faceMismatches(fit.block, first, L, rng), 0);
}

// Negative controls: ±Y swapped, and the faces in the order +X +Y +Z −X −Y −Z, must fail the same check.
TEST(ShadowFit, CubeFaceOrderNegativeControl) {
    Rng rng(7);
    const Stage stage = randomStage(rng);
    const Scene& scene = stage.scene;
    const ShadowFit fit = fitStage(stage);
    const int first = fit.block.light[2].y;
    const glm::vec3 L = scene.lights[2].position;
    ShadowBlock swapped = fit.block;
    std::swap(swapped.layerViewProj[first + 2], swapped.layerViewProj[first + 3]);
    EXPECT_GT(faceMismatches(swapped, first, L, rng), 0);
    ShadowBlock byAxis = fit.block;
    const int order[6] = {0, 2, 4, 1, 3, 5};
    for (int f = 0; f < 6; ++f) byAxis.layerViewProj[first + f] = fit.block.layerViewProj[first + order[f]];
    EXPECT_GT(faceMismatches(byAxis, first, L, rng), 0);
}

// The tracer's rule (intersectPlane's 0 < t < tMax): a shadow ray from O towards the light is blocked by
// plane k exactly when O and the light lie strictly on opposite sides of it.
bool blockedByPlane(const Plane& p, const Light& l, const glm::vec3& O) {
    const float a = glm::dot(p.normal, O) - p.offset;
    const float b = l.positional() ? glm::dot(p.normal, l.position) - p.offset : -glm::dot(p.normal, l.direction);
    return (a < 0.0f && b > 0.0f) || (a > 0.0f && b < 0.0f);
}

// Receivers a light's mask leaves out although a plane blocks them: points in the casters' box and on every
// other plane (a plane's own pixels face away from a light behind it, so N·L <= 0 there).
int blockedButMasked(const Scene& scene, const Bounds& casters, const std::vector<int>& masks, Rng& rng) {
    int misses = 0;
    const int planes = std::min<int>(int(scene.planes.size()), kMaxShadowPlanes);
    for (size_t i = 0; i < masks.size(); ++i) {
        const Light& l = scene.lights[i];
        for (int n = 0; n < 200; ++n) {
            std::vector<std::pair<glm::vec3, int>> receivers;  // point, the plane it lies on (-1: none)
            if (!casters.empty()) receivers.push_back({pointIn(rng, casters), -1});
            for (int j = 0; j < int(scene.planes.size()); ++j) {
                const Plane& q = scene.planes[size_t(j)];
                const glm::vec3 t = glm::cross(q.normal, unitVector(rng));
                receivers.push_back({q.offset * q.normal + uniform(rng, 0.0f, 20.0f) * t, j});
            }
            for (const auto& [O, on] : receivers)
                for (int k = 0; k < planes; ++k)
                    if (k != on && blockedByPlane(scene.planes[size_t(k)], l, O) && !(masks[i] & (1 << k))) ++misses;
        }
    }
    return misses;
}

TEST(ShadowFit, PlaneMaskAgreesWithTracer) {
    int blockingPlanes = 0, skippedPlanes = 0;
    for (unsigned seed = 1; seed <= 60; ++seed) {
        Rng rng(seed);
        const Stage stage = randomStage(rng);
        const Scene& scene = stage.scene;
        const Bounds box = casterBounds(scene, stage.ranges);
        const ShadowFit fit = fitShadows(scene, box, fineSettings());
        std::vector<int> masks;
        for (int i = 0; i < kMaxShadowedLights; ++i) {
            masks.push_back(fit.block.light[i].z);
            EXPECT_EQ(masks.back(), planeMask(scene, box, scene.lights[size_t(i)]));
            for (size_t k = 0; k < scene.planes.size(); ++k)
                (masks.back() & (1 << k) ? blockingPlanes : skippedPlanes)++;
        }
        EXPECT_EQ(blockedButMasked(scene, box, masks, rng), 0) << "seed " << seed;
    }
    // Both outcomes occur, so the sweep tests the rule rather than an all-ones mask.
    EXPECT_GT(blockingPlanes, 0);
    EXPECT_GT(skippedPlanes, 0);
}

// Negative control: empty masks on the same scenes must miss blocked receivers.
TEST(ShadowFit, PlaneMaskNegativeControl) {
    int misses = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        Rng rng(seed);
        const Stage stage = randomStage(rng);
        misses += blockedButMasked(stage.scene, casterBounds(stage.scene, stage.ranges),
                                   std::vector<int>(kMaxShadowedLights, 0), rng);
    }
    EXPECT_GT(misses, 0);
}

// Hand-made stages with known masks. Bit k is clear only when neither the casters' box nor another plane
// reaches the far side of plane k from the light; every other plane not parallel to k does.
TEST(ShadowFit, PlaneMaskOnStages) {
    Scene scene;
    Sphere s;
    s.center = {0.0f, 1.0f, 0.0f};
    scene.spheres = {s};
    Plane floor, ceiling, wall, through;
    ceiling.offset = 10.0f;
    wall.normal = {1.0f, 0.0f, 0.0f};
    wall.offset = 3.0f;
    through.normal = {0.0f, 0.0f, 1.0f};
    Light between, above, beyondWall, sun;
    between.position = {0.0f, 5.0f, 0.0f};
    above.position = {0.0f, 12.0f, 0.0f};
    beyondWall.position = {6.0f, 5.0f, 0.0f};
    sun.type = LightType::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    const Bounds box = casterBounds(scene, {});

    scene.planes = {floor, ceiling};
    EXPECT_EQ(planeMask(scene, box, between), 0);
    EXPECT_EQ(planeMask(scene, box, above), 0b10);
    EXPECT_EQ(planeMask(scene, box, sun), 0b10);
    scene.planes = {wall};
    EXPECT_EQ(planeMask(scene, box, between), 0);
    EXPECT_EQ(planeMask(scene, box, beyondWall), 0b1);
    scene.planes = {floor, ceiling, wall};             // the wall reaches below the floor and above the ceiling, and
    EXPECT_EQ(planeMask(scene, box, between), 0b111);  // the floor beyond the wall
    scene.planes = {through};                          // the light lies in the plane
    EXPECT_EQ(planeMask(scene, box, between), 0b1);
}

// perspectiveDepthTest against glm::perspective: a receiver at distance r along the axis has window depth
// A - B/r, so a stored depth just above it is lit and just below it is shadowed.
TEST(ShadowFit, PerspectiveDepthTestIsWindowDepth) {
    const float zNear = 0.5f, zFar = 20.0f;
    const glm::vec4 test = perspectiveDepthTest(zNear, zFar);
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, zNear, zFar);
    for (float r : {0.5f, 0.7f, 2.0f, 9.0f, 20.0f}) {
        const glm::vec4 clip = proj * glm::vec4(0.3f, -0.2f, -r, 1.0f);
        const float window = 0.5f * clip.z / clip.w + 0.5f;
        EXPECT_NEAR(test.x - test.y / r, window, 1e-6f) << "r " << r;
        EXPECT_TRUE((test.x - (window + 1e-4f)) * r <= test.y) << "r " << r;
        EXPECT_FALSE((test.x - (window - 1e-4f)) * r <= test.y) << "r " << r;
    }
    EXPECT_NEAR(test.x - test.y / zNear, 0.0f, 1e-6f);
    EXPECT_NEAR(test.x - test.y / zFar, 1.0f, 1e-6f);
}

// orthoDepthTest: `depthBiasTexels` texels of `texelWorld` along the axis, in window units of glm::ortho.
TEST(ShadowFit, OrthoDepthTestIsBiasInWindowUnits) {
    const float zNear = 1.0f, zFar = 9.0f, texel = 0.01f, bias = 1.5f;
    const glm::vec4 test = orthoDepthTest(zNear, zFar, texel, bias);
    const glm::mat4 proj = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, zNear, zFar);
    const float a = 0.5f * (proj * glm::vec4(0, 0, -3.0f, 1)).z + 0.5f;
    const float b = 0.5f * (proj * glm::vec4(0, 0, -3.0f - bias * texel, 1)).z + 0.5f;
    EXPECT_NEAR(test.z, b - a, 1e-6f);
    EXPECT_FLOAT_EQ(test.z, 1.5f * 0.01f / 8.0f);
    EXPECT_EQ(test.x, 0.0f);
    EXPECT_EQ(test.y, 0.0f);
}

}  // namespace
}  // namespace shadelab::raster
