// The principled BRDF in the white furnace: a disney sphere in a uniform environment of radiance 1, path traced,
// shows at each pixel its directional albedo at that pixel's N·V, the curve the viewer's albedo plot draws
// (shading::directionalAlbedo of shadeLightDisney). With every lobe on, this checks the path tracer's sampling
// of the mixture against the BRDF's own integral. Negative control: the curve of another material is not met.
#include "shading/directional_albedo.h"
#include "trace/path/path_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

namespace shadelab::trace {
namespace {

using test::PathRun;
using test::pathRun;
using test::small;

constexpr int kSize = 40;

Material disneyMaterial(float roughness, float metallic, const DisneyParams& p) {
    Material m;
    m.model = ShadingModel::Disney;
    m.baseColor = glm::vec3(1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.disney = p;
    return m;
}

Scene disneyFurnace(const Material& m) {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fovY = 30.0f;
    scene.model = ShadingModel::Disney;
    scene.background = glm::vec3(1.0f);
    Sphere s;
    s.material = m;
    scene.spheres.push_back(s);
    return scene;
}

// The directional albedo of `m` at N·V (the albedo plot's integral of shadeLightDisney), the mean of RGB.
float albedoOf(const Material& m, float NoV) {
    const shading::vec3 N(0.0f, 0.0f, 1.0f);
    return shading::directionalAlbedo(
        [&](shading::vec3 L, shading::vec3 V) {
            const shading::vec3 I =
                shading::shadeLightDisney(N, L, V, shading::vec3(1.0f), m.baseColor, m.metallic, m.roughness,
                                          m.disney.lobes0(), m.disney.lobes1(), true, true, shading::vec3(1.0f));
            return (I.x + I.y + I.z) / 3.0f;
        },
        NoV, shading::AlbedoQuadrature{96, 48});
}

struct Ring {
    double rendered = 0.0, variance = 0.0, expected = 0.0;
    int pixels = 0;
};

// The render's pixels binned by the N·V at their centres (rings of the sphere), each ring's mean radiance and
// the mean of the curve over the same pixels. Pixels near the rim (N·V < 0.25), where N·V varies much within a
// pixel, are left out.
std::vector<Ring> rings(const PathRun& r, const Scene& scene, const Material& curve, int bins) {
    std::vector<Ring> out(static_cast<size_t>(bins));
    const Camera& c = scene.camera;
    const glm::vec3 forward = glm::normalize(c.target - c.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up)), up = glm::cross(right, forward);
    const float tanHalf = std::tan(glm::radians(c.fovY) * 0.5f);
    std::vector<float> table;
    for (int i = 0; i <= 64; ++i) table.push_back(albedoOf(curve, 0.25f + 0.75f * float(i) / 64.0f));
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::vec3 dir = shading::cameraRayDirection(forward, right, up, tanHalf, float(kSize), float(kSize),
                                                              float(x) + 0.5f, float(y) + 0.5f);
            const float t = shading::intersectSphere(c.position, dir, glm::vec3(0.0f), 1.0f, 0.0f);
            if (t < 0.0f) continue;
            const glm::vec3 N = glm::normalize(c.position + t * dir);
            const float NoV = glm::dot(N, -dir);
            if (NoV < 0.25f) continue;
            const float u = (NoV - 0.25f) / 0.75f * 64.0f;
            const int k = std::min(int(u), 63);
            const float expected = table[size_t(k)] + (u - float(k)) * (table[size_t(k) + 1] - table[size_t(k)]);
            Ring& ring = out[size_t(std::min(int((NoV - 0.25f) / 0.75f * float(bins)), bins - 1))];
            const glm::vec3 m = r.render->mean(x, y), e = r.render->standardError(x, y);
            ring.rendered += (m.x + m.y + m.z) / 3.0;
            ring.variance += double(e.x * e.x + e.y * e.y + e.z * e.z) / 9.0;
            ring.expected += expected;
            ++ring.pixels;
        }
    for (Ring& ring : out)
        if (ring.pixels > 0) {
            ring.rendered /= ring.pixels;
            ring.expected /= ring.pixels;
            ring.variance /= double(ring.pixels) * ring.pixels;
        }
    return out;
}

// Rings whose rendered mean misses the curve by more than 4 standard errors plus 0.5 % (the quadrature's and the
// pixel footprint's share); every ring printed and written to `name`.csv.
int ringsOff(const std::vector<Ring>& rs, const std::string& name) {
    const std::filesystem::path dir(SHADELAB_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(dir);
    std::ofstream csv(dir / (name + ".csv"));
    csv << "ring,pixels,rendered,expected,se\n";
    int off = 0;
    for (size_t i = 0; i < rs.size(); ++i) {
        const Ring& r = rs[i];
        if (r.pixels == 0) continue;
        const double se = std::sqrt(r.variance), allowed = 4.0 * se + 0.005 * r.expected;
        csv << i << ',' << r.pixels << ',' << r.rendered << ',' << r.expected << ',' << se << '\n';
        std::printf("%s ring %zu (%d px): rendered %.4f, curve %.4f, se %.4f\n", name.c_str(), i, r.pixels, r.rendered,
                    r.expected, se);
        if (std::abs(r.rendered - r.expected) > allowed) ++off;
    }
    return off;
}

TEST(DisneyFurnace, EachRingShowsTheAlbedoCurveOfItsViewAngle) {
    DisneyParams all;
    all.sheen = 1.0f;
    all.clearcoat = 1.0f;
    all.clearcoatGloss = 0.5f;
    all.subsurface = 0.5f;
    struct Case {
        const char* name;
        Material m;
    };
    const Case cases[] = {{"disney_furnace_dielectric", disneyMaterial(0.5f, 0.0f, all)},
                          {"disney_furnace_metal", disneyMaterial(0.3f, 1.0f, DisneyParams{})}};
    for (const Case& c : cases) {
        const Scene scene = disneyFurnace(c.m);
        const PathRun r = pathRun(scene, small(kSize, kSize, 512, 8));
        EXPECT_EQ(ringsOff(rings(r, scene, c.m, 6), c.name), 0) << c.name << ": see the lines above";
    }
    // Negative control: the dielectric's render against the curve of the same material without its sheen.
    const Scene scene = disneyFurnace(cases[0].m);
    const PathRun r = pathRun(scene, small(kSize, kSize, 512, 8));
    DisneyParams noSheen = all;
    noSheen.sheen = 0.0f;
    EXPECT_GT(ringsOff(rings(r, scene, disneyMaterial(0.5f, 0.0f, noSheen), 6), "disney_furnace_negative"), 2);
}

}  // namespace
}  // namespace shadelab::trace
