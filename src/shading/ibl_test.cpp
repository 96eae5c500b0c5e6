// The environment prefilter and its lookups (the split sum): face addressing, a uniform environment
// staying uniform at every level, thread-count independence, SH9 irradiance against its closed form, and
// the GGX levels conserving the environment's mean radiance.
#include "shading/ibl_lookup.h"
#include "shading/prefilter.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace shadelab::shading;

namespace {

EquirectMap makeMap(int w, int h, glm::vec3 (*radiance)(glm::vec3)) {
    EquirectMap m;
    m.width = w;
    m.height = h;
    m.rgb.resize(size_t(w) * size_t(h) * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 c = radiance(equirectDirection((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)));
            float* t = &m.rgb[(size_t(y) * size_t(w) + size_t(x)) * 3];
            t[0] = c.x, t[1] = c.y, t[2] = c.z;
        }
    return m;
}

glm::vec3 uniformSky(glm::vec3) { return {0.3f, 0.5f, 0.7f}; }
glm::vec3 gradientSky(glm::vec3 d) { return glm::vec3(1.0f + d.y); }
glm::vec3 sunSky(glm::vec3 d) {
    return glm::dot(d, glm::normalize(glm::vec3(0.3f, 0.6f, -0.7f))) > 0.995f ? glm::vec3(40.0f) : glm::vec3(0.5f);
}

// Mean of level `level` over the sphere, each texel weighted by its solid angle (border texels skipped).
glm::vec3 levelMean(const PrefilteredEnvironment& env, int level) {
    IblLookup lookup{&env, nullptr};
    const int n = lookup.iblFaceSize(env.size, level);
    glm::dvec3 sum(0.0);
    double total = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const float x = 2.0f * (float(i) + 0.5f) / float(n) - 1.0f,
                            y = 2.0f * (float(j) + 0.5f) / float(n) - 1.0f;
                const float r2 = 1.0f + x * x + y * y;
                const double dw = 1.0 / (double(r2) * std::sqrt(double(r2)));
                sum += dw *
                       glm::dvec3(lookup.iblTexel(face * (n + 2) + i + 1, lookup.iblLevelRow(env.size, level) + j + 1));
                total += dw;
            }
    return glm::vec3(sum / total);
}

}  // namespace

TEST(Ibl, CubeDirectionInvertsCubeFaceCoords) {
    IblLookup lookup;
    for (int face = 0; face < 6; ++face)
        for (float x : {-0.9f, -0.3f, 0.0f, 0.55f, 0.99f})
            for (float y : {-0.99f, -0.2f, 0.4f, 0.8f}) {
                const glm::vec3 d = cubeDirection(face, x, y);
                ASSERT_EQ(lookup.cubeFace(d), face);
                const glm::vec3 c = lookup.cubeFaceCoords(d, face);
                EXPECT_NEAR(c.x, x, 1e-5f);
                EXPECT_NEAR(c.y, y, 1e-5f);
            }
}

TEST(Ibl, EquirectCoordsInvertEquirectDirection) {
    for (float u : {0.1f, 0.5f, 0.77f})
        for (float v : {0.2f, 0.5f, 0.9f}) {
            float u2, v2;
            equirectCoords(equirectDirection(u, v), u2, v2);
            EXPECT_NEAR(u2, u, 1e-5f);
            EXPECT_NEAR(v2, v, 1e-5f);
        }
    const glm::vec3 up = equirectDirection(0.3f, 0.0f), front = equirectDirection(0.5f, 0.5f);
    EXPECT_NEAR(up.y, 1.0f, 1e-6f);
    EXPECT_NEAR(front.z, -1.0f, 1e-6f);
}

TEST(Ibl, UniformEnvironmentStaysUniformAtEveryLevel) {
    PrefilterSettings s;
    s.size = 32;
    const PrefilteredEnvironment env = prefilterEnvironment(makeMap(64, 32, uniformSky), s);
    ASSERT_EQ(env.levels, 6);
    IblLookup lookup{&env, nullptr};
    for (int l = 0; l < env.levels; ++l)
        for (int row = 0; row < lookup.iblFaceSize(env.size, l) + 2; ++row)
            for (int col = 0; col < 6 * (lookup.iblFaceSize(env.size, l) + 2); ++col) {
                const glm::vec3 t = lookup.iblTexel(col, lookup.iblLevelRow(env.size, l) + row);
                ASSERT_NEAR(t.x, 0.3f, 1e-5f) << l << " " << row << " " << col;
                ASSERT_NEAR(t.z, 0.7f, 1e-5f) << l << " " << row << " " << col;
            }
    for (glm::vec3 n : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(1, -2, 0.5f)), glm::vec3(0, 0, -1)}) {
        const glm::vec3 e = lookup.irradiance(n);
        EXPECT_NEAR(e.y, 0.5f, 2e-3f);
        for (float r : {0.0f, 0.3f, 0.71f, 1.0f}) {
            EXPECT_NEAR(lookup.prefiltered(n, r).z, 0.7f, 1e-5f);
        }
    }
    // uniformEnvironment() is the same data without the work.
    const PrefilteredEnvironment u = uniformEnvironment({0.3f, 0.5f, 0.7f}, 32);
    const IblLookup uniformLookup{&u, nullptr};
    EXPECT_NEAR(uniformLookup.irradiance(glm::vec3(0, 1, 0)).y, 0.5f, 1e-6f);
}

TEST(Ibl, SameDataForAnyThreadCount) {
    PrefilterSettings s;
    s.size = 32;
    s.threads = 1;
    const EquirectMap map = makeMap(128, 64, sunSky);
    const PrefilteredEnvironment one = prefilterEnvironment(map, s);
    s.threads = 3;
    const PrefilteredEnvironment three = prefilterEnvironment(map, s);
    EXPECT_EQ(one.atlas, three.atlas);
}

TEST(Ibl, ShIrradianceOfALinearSkyIsItsClosedForm) {
    // L(d) = 1 + d·y: the cosine convolution of a band-1 function scales it by 2/3, so E/π = 1 + (2/3) n·y.
    PrefilterSettings s;
    s.size = 64;
    const PrefilteredEnvironment env = prefilterEnvironment(makeMap(256, 128, gradientSky), s);
    IblLookup lookup{&env, nullptr};
    for (glm::vec3 n :
         {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 1, 1)), glm::vec3(1, 0, 0)}) {
        const float expected = 1.0f + 2.0f / 3.0f * n.y;
        EXPECT_NEAR(lookup.irradiance(n).x, expected, 0.01f) << n.y;
        // Negative control: the unconvolved radiance differs by more than the tolerance (except at the horizon).
        if (std::abs(n.y) > 0.5f) {
            EXPECT_GT(std::abs((1.0f + n.y) - expected), 0.01f);
        }
    }
}

TEST(Ibl, GgxLevelsBlurTheSunAndKeepTheMeanRadiance) {
    PrefilterSettings s;
    s.size = 64;
    const PrefilteredEnvironment env = prefilterEnvironment(makeMap(512, 256, sunSky), s);
    const glm::vec3 mean0 = levelMean(env, 0);
    for (int l = 1; l < env.levels; ++l) EXPECT_NEAR(levelMean(env, l).x / mean0.x, 1.0f, 0.05f) << "level " << l;
    IblLookup lookup{&env, nullptr};
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.6f, -0.7f));
    const float sharp = lookup.prefiltered(sun, 0.0f).x;
    const float rough = lookup.prefiltered(sun, 1.0f).x;
    EXPECT_GT(sharp, 20.0f);
    EXPECT_LT(rough, 2.0f);
    EXPECT_GT(rough, 0.5f);
}
