// The probe explains the reference: on 2CylinderEngine with shadows on, for 1,000 pixels (random
// ones, silhouette-edge ones and shadow-boundary ones), the probe's hit object, its point and each light's
// vis_l equal what the Whitted integrator computes for the same primary ray. The oracle below is the
// tracer's own API, not the probe's code; a probe with its own intersector or shadow-ray origin fails it.
#include "probe/probe.h"
#include "scene/light_at.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "shading/lighting.h"
#include "test_output.h"
#include "trace/integrator.h"
#include "trace/tile_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

namespace shadelab {
namespace {

const char* const kEngine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
constexpr int kW = 160, kH = 120;

struct Expected {
    bool hit = false;
    uint32_t id = 0;
    glm::vec3 P{0.0f};
    std::vector<float> visibility;  // per light
};

// What the reference itself computes for pixel (x, y): its primary ray, nearest hit, surface and shadow rays.
Expected reference(const trace::TraceScene& ts, int x, int y) {
    const Scene& scene = ts.scene();
    const trace::Ray ray = trace::sampleRay(makeViewSetup(scene, kW, kH), 1, x, y, 0, 0);
    Expected e;
    const std::optional<trace::Hit> hit = ts.intersect(ray);
    if (!hit) return e;
    const trace::WhittedIntegrator integrator(ts, scene.maxDepth);
    const trace::Surface s = integrator.surfaceAt(ray, *hit);
    e.hit = true;
    e.id = ts.coverageId(*hit);
    e.P = s.P;
    for (const Light& l : scene.lights) {
        const glm::vec3 L = lightAt(l, s.P).L;
        e.visibility.push_back(glm::dot(s.N, L) > 0.0f ? integrator.visibility(s, l) : 1.0f);
    }
    return e;
}

// Pixels whose 3×3 neighbourhood mixes coverage ids (silhouettes) or, lit by the same light, mixes vis_l
// (shadow boundaries): where an intersector or a shadow-ray origin that differs by a rounding shows.
void boundaryPixels(const trace::TraceScene& ts, const std::vector<Expected>& all, std::vector<int>& edges,
                    std::vector<int>& shadowEdges) {
    const size_t lights = ts.scene().lights.size();
    for (int y = 1; y + 1 < kH; ++y)
        for (int x = 1; x + 1 < kW; ++x) {
            const Expected& c = all[size_t(y * kW + x)];
            bool edge = false, shadowEdge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const Expected& n = all[size_t((y + dy) * kW + x + dx)];
                    edge = edge || n.id != c.id || n.hit != c.hit;
                    if (c.hit && n.hit)
                        for (size_t l = 0; l < lights; ++l)
                            shadowEdge = shadowEdge || n.visibility[l] != c.visibility[l];
                }
            if (edge) edges.push_back(y * kW + x);
            if (shadowEdge) shadowEdges.push_back(y * kW + x);
        }
}

TEST(ProbeAgreement, EngineProbeEqualsTheIntegratorOnAThousandPixels) {
    if (!std::filesystem::exists(kEngine)) GTEST_SKIP() << "assimp-testmodels not installed: " << kEngine;
    Scene scene = loadScene(kEngine);
    scene.terms.shadows = true;
    ASSERT_GE(scene.lights.size(), 2u);
    const trace::TraceScene ts(scene);

    std::vector<Expected> all;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) all.push_back(reference(ts, x, y));
    std::vector<int> edges, shadowEdges;
    boundaryPixels(ts, all, edges, shadowEdges);
    ASSERT_GE(edges.size(), 300u);
    ASSERT_GE(shadowEdges.size(), 100u);

    // 400 random pixels, 300 silhouette pixels and 300 shadow-boundary pixels (with repeats if few).
    std::mt19937 rng(10);
    std::vector<int> picks;
    auto pickFrom = [&](const std::vector<int>& from, int n) {
        std::uniform_int_distribution<size_t> u(0, from.size() - 1);
        for (int i = 0; i < n; ++i) picks.push_back(from[u(rng)]);
    };
    std::uniform_int_distribution<int> any(0, kW * kH - 1);
    for (int i = 0; i < 400; ++i) picks.push_back(any(rng));
    pickFrom(edges, 300);
    pickFrom(shadowEdges, 300);

    int mismatches = 0, shadowed = 0;
    const std::string log = test::outputPath("probe_mismatches.txt");
    std::ofstream out(log);
    for (const int p : picks) {
        const int x = p % kW, y = p / kW;
        const Expected& e = all[size_t(p)];
        const ProbeResult r = probePixel(ts, kW, kH, x, y);
        bool same = r.hit == e.hit && r.objectId == e.id;
        if (same && e.hit) {
            same = r.P == e.P && r.lights.size() == e.visibility.size();
            for (size_t l = 0; same && l < e.visibility.size(); ++l) same = r.lights[l].visibility == e.visibility[l];
        }
        for (float v : e.visibility) shadowed += v == 0.0f;
        if (!same) {
            ++mismatches;
            out << "pixel " << x << "," << y << ": probe id " << r.objectId << " P " << r.P.x << " " << r.P.y << " "
                << r.P.z << "; reference id " << e.id << " P " << e.P.x << " " << e.P.y << " " << e.P.z << "\n";
        }
    }
    EXPECT_GT(shadowed, 100) << "too few shadowed samples: the test would not see a shadow-ray difference";
    EXPECT_EQ(mismatches, 0) << "probe and reference disagree; pixels listed in " << log;
}

}  // namespace
}  // namespace shadelab
