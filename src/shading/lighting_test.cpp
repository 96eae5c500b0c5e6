// Shading maths against hand-computed values: clamps, x^0 = 1, peaks, per-channel colour, sums.
#include "shading/local_illumination.h"

#include <gtest/gtest.h>
#include <cmath>
#include <glm/trigonometric.hpp>

using namespace shadelab::shading;

namespace {

constexpr int kPhong = SL_MODEL_PHONG;
constexpr int kBlinn = SL_MODEL_BLINN_PHONG;
const vec3 kWhite(1.0f);
const vec3 kUp(0.0f, 0.0f, 1.0f);

void expectVec(const vec3& a, const vec3& b, float tol = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

vec3 fromAngle(float degrees) {  // unit vector in the xz plane, `degrees` away from +z
    float r = glm::radians(degrees);
    return vec3(std::sin(r), 0.0f, std::cos(r));
}

}  // namespace

TEST(Lighting, BelowHorizonGivesNoDiffuseNoSpecular) {
    vec3 L = fromAngle(120.0f);  // NoL = cos(120°) = -0.5
    for (int model : {kPhong, kBlinn}) {
        vec3 I = shadeLight(kUp, L, kUp, kWhite, vec3(0.8f), vec3(1.0f), 10.0f, model, true, true);
        expectVec(I, vec3(0.0f));
    }
    // Even at s = 0, where spec would be 1, an unlit point gets no specular.
    EXPECT_EQ(specularPhong(kUp, L, kUp, 0.0f), 0.0f);
    EXPECT_EQ(specularBlinnPhong(kUp, L, kUp, 0.0f), 0.0f);
}

TEST(Lighting, DiffuseIsLambert) {
    vec3 L = fromAngle(60.0f);  // NoL = 0.5
    vec3 I = shadeLight(kUp, L, kUp, kWhite, vec3(0.8f, 0.4f, 0.2f), vec3(0.0f), 1.0f, kPhong, true, true);
    expectVec(I, vec3(0.4f, 0.2f, 0.1f));
}

TEST(Lighting, PhongNegativeRoVGivesNoSpecular) {
    // L at 30° on one side: R at 30° on the other. V at 80° on L's side: angle(R, V) = 110°, RoV < 0.
    vec3 L = fromAngle(30.0f);
    vec3 V = fromAngle(80.0f);
    vec3 R = reflectLight(kUp, L);
    ASSERT_LT(dot(R, V), 0.0f);
    EXPECT_EQ(specularPhong(kUp, L, V, 8.0f), 0.0f);
    // Blinn-Phong at the same vectors still sees a highlight: H lies between L and V.
    EXPECT_GT(specularBlinnPhong(kUp, L, V, 8.0f), 0.0f);
}

TEST(Lighting, PhongValueByHand) {
    // L at 30°, V at -60°: R at -30°, angle(R, V) = 30°, RoV = cos 30° = 0.866025; ^4 = 0.5625.
    vec3 L = fromAngle(30.0f);
    vec3 V = fromAngle(-60.0f);
    EXPECT_NEAR(specularPhong(kUp, L, V, 4.0f), 0.5625f, 1e-5f);
    // Blinn: H at -15°, NoH = cos 15° = 0.965926; ^4 = 0.870513.
    EXPECT_NEAR(specularBlinnPhong(kUp, L, V, 4.0f), 0.870513f, 1e-5f);
}

TEST(Lighting, HalfwayEqualsNormalGivesPeak) {
    vec3 L = fromAngle(40.0f);
    vec3 V = fromAngle(-40.0f);  // H = N exactly
    for (float s : {1.0f, 32.0f, 1000.0f}) {
        EXPECT_NEAR(specularBlinnPhong(kUp, L, V, s), 1.0f, 1e-5f) << "s=" << s;
        EXPECT_NEAR(specularPhong(kUp, L, V, s), 1.0f, 1e-4f) << "s=" << s;  // R = V too
    }
}

TEST(Lighting, ZeroShininessGivesOne) {
    EXPECT_EQ(shininessPow(0.0f, 0.0f), 1.0f);
    EXPECT_EQ(shininessPow(0.3f, 0.0f), 1.0f);
    EXPECT_EQ(shininessPow(-0.3f, 0.0f), 1.0f);
    vec3 L = fromAngle(30.0f);
    vec3 V = fromAngle(75.0f);  // RoV < 0, but s = 0 gives 1 on the lit side
    EXPECT_EQ(specularPhong(kUp, L, V, 0.0f), 1.0f);
    EXPECT_EQ(specularBlinnPhong(kUp, L, V, 0.0f), 1.0f);
    EXPECT_EQ(shininessPow(0.0f, 5.0f), 0.0f);
}

TEST(Lighting, ColouredLightsMultiplyPerChannel) {
    vec3 L = kUp, V = kUp;
    vec3 Il(1.0f, 0.5f, 0.0f);
    vec3 md(0.2f, 0.4f, 0.6f), ms(0.1f, 0.2f, 0.3f);
    vec3 I = shadeLight(kUp, L, V, Il, md, ms, 16.0f, kBlinn, true, true);
    expectVec(I, Il * (md + ms));  // NoL = 1, NoH = 1
}

TEST(Lighting, TwoLightsSumAndAmbientAdds) {
    SurfaceParams m{vec3(0.5f), vec3(0.6f), vec3(0.0f), 1.0f};
    LightSample lights[2] = {{fromAngle(60.0f), vec3(1.0f, 0.0f, 0.0f)}, {fromAngle(0.0f), vec3(0.0f, 1.0f, 0.0f)}};
    vec3 Ia(0.2f);
    vec3 I = shadeLocal(kUp, kUp, lights, 2, m, Ia, kPhong, TermFlags{});
    // ambient 0.1; red: 0.6·0.5 = 0.3; green: 0.6·1 = 0.6.
    expectVec(I, vec3(0.1f + 0.3f, 0.1f + 0.6f, 0.1f));
    vec3 one = shadeLocal(kUp, kUp, lights, 1, m, Ia, kPhong, TermFlags{});
    vec3 other = shadeLocal(kUp, kUp, lights + 1, 1, m, Ia, kPhong, TermFlags{});
    expectVec(I, one + other - shadeAmbient(Ia, m.ma, true));
}

TEST(Lighting, TermSwitchesRemoveTheirTerm) {
    SurfaceParams m{vec3(0.5f), vec3(0.6f), vec3(0.4f), 8.0f};
    LightSample light{kUp, kWhite};
    vec3 Ia(0.2f);
    expectVec(shadeLocal(kUp, kUp, &light, 1, m, Ia, kPhong, {true, false, false}), vec3(0.1f));
    expectVec(shadeLocal(kUp, kUp, &light, 1, m, Ia, kPhong, {false, true, false}), vec3(0.6f));
    expectVec(shadeLocal(kUp, kUp, &light, 1, m, Ia, kPhong, {false, false, true}), vec3(0.4f));
    expectVec(shadeLocal(kUp, kUp, &light, 1, m, Ia, kPhong, {false, false, false}), vec3(0.0f));
}

TEST(Lighting, InputsAreNormalisedInside) {
    vec3 a = shadeLight(kUp * 3.0f, fromAngle(30.0f) * 7.0f, fromAngle(-50.0f) * 0.1f, kWhite, vec3(0.5f), vec3(0.5f),
                        20.0f, kPhong, true, true);
    vec3 b =
        shadeLight(kUp, fromAngle(30.0f), fromAngle(-50.0f), kWhite, vec3(0.5f), vec3(0.5f), 20.0f, kPhong, true, true);
    expectVec(a, b);
}

TEST(Geometry, SphereHitsMissesAndInside) {
    vec3 o(0.0f, 0.0f, 5.0f), d(0.0f, 0.0f, -1.0f);
    EXPECT_NEAR(intersectSphere(o, d, vec3(0.0f), 1.0f, 0.0f), 4.0f, 1e-6f);
    EXPECT_EQ(intersectSphere(o, vec3(0.0f, 1.0f, 0.0f), vec3(0.0f), 1.0f, 0.0f), -1.0f);
    EXPECT_NEAR(intersectSphere(vec3(0.0f), d, vec3(0.0f), 1.0f, 0.0f), 1.0f, 1e-6f);  // from inside
}

TEST(Geometry, PlaneParallelAndBehind) {
    vec3 n(0.0f, 1.0f, 0.0f);
    EXPECT_NEAR(intersectPlane(vec3(0.0f, 2.0f, 0.0f), vec3(0.0f, -1.0f, 0.0f), n, 0.0f, 0.0f), 2.0f, 1e-6f);
    EXPECT_EQ(intersectPlane(vec3(0.0f, 2.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), n, 0.0f, 0.0f), -1.0f);
    EXPECT_EQ(intersectPlane(vec3(0.0f, 2.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f), n, 0.0f, 0.0f), -1.0f);
}

TEST(Geometry, PlaneBasisIsOrthonormal) {
    for (vec3 n : {vec3(0, 1, 0), vec3(0, 0, -1), glm::normalize(vec3(1, 2, -3))}) {
        vec3 t = planeTangent(n), b = planeBitangent(n);
        EXPECT_NEAR(dot(t, n), 0.0f, 1e-6f);
        EXPECT_NEAR(dot(b, n), 0.0f, 1e-6f);
        EXPECT_NEAR(dot(t, b), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
    }
    vec3 n(0, 1, 0);
    EXPECT_NE(checkerParity(vec3(0.5f, 0, 0.5f), n, 1.0f), checkerParity(vec3(1.5f, 0, 0.5f), n, 1.0f));
    EXPECT_EQ(checkerParity(vec3(0.5f, 0, 0.5f), n, 1.0f), checkerParity(vec3(1.5f, 0, 1.5f), n, 1.0f));
}
