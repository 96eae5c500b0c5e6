// Tracer-only physics with exact expected values: hard shadows leave only ambient, a mirror sphere
// returns a known colour, a glass slab shifts a checker as Snell's law predicts, total internal reflection
// sends the transmitted energy into the reflected ray, and the depth limit. Each with a negative control.
#include "trace/integrator.h"
#include "scene/coverage.h"
#include "shading/lighting.h"
#include "trace/trace_image.h"
#include "trace/trace_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>

using namespace shadelab;
using namespace shadelab::trace;

namespace {

// Bit-exact colour comparison that prints both sides in full.
::testing::AssertionResult exactly(glm::vec3 got, glm::vec3 want) {
    if (got.x == want.x && got.y == want.y && got.z == want.z) return ::testing::AssertionSuccess();
    std::ostringstream s;
    s << std::setprecision(9) << "got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", "
      << want.y << ", " << want.z << ")";
    return ::testing::AssertionFailure() << s.str();
}

glm::vec3 nudged(glm::vec3 c) { return {std::nextafter(c.x, 2.0f), c.y, c.z}; }

Plane plane(glm::vec3 n, float offset, const Material& m) { return Plane{"", n, offset, m, std::nullopt}; }

Light pointLight(glm::vec3 p, glm::vec3 color) {
    Light l;
    l.position = p;
    l.color = color;
    return l;
}

// A plane under a sphere, lit from straight above (a point light, then a directional one).
TEST(TracerPhysics, PointInShadowReceivesOnlyAmbient) {
    Scene sc;
    sc.ambient = {0.25f, 0.5f, 1.0f};
    const Material floor = test::plainMaterial({0.3f, 0.5f, 0.7f}, {0.8f, 0.6f, 0.4f}, glm::vec3(0.5f), 20.0f);
    sc.planes.push_back(plane({0, 1, 0}, 0.0f, floor));
    sc.spheres.push_back(Sphere{"occluder", {0, 1, 0}, 0.5f, Material{}});
    Light directional;
    directional.type = LightType::Directional;
    directional.direction = {0, -1, 0};
    directional.color = {0.7f, 0.8f, 0.9f};
    const Ray toShadow = test::rayTowards({3, 0.4f, 0}, {0.1f, 0, 0.05f});  // passes under the sphere
    const Ray toLit = test::rayTowards({3, 0.4f, 0}, {1.6f, 0, 0.2f});
    const glm::vec3 ambientOnly = shading::shadeAmbient(sc.ambient, floor.ma, true);
    for (const Light& light : {pointLight({0, 3, 0}, {1.0f, 0.9f, 0.8f}), directional}) {
        sc.lights = {light};
        sc.terms.shadows = true;
        const TraceScene shadowed(sc);
        const WhittedIntegrator wi(shadowed, 5);
        const PrimarySample s = wi.primary(toShadow);
        EXPECT_EQ(s.coverage, planeCoverageId(sc, 0));
        EXPECT_TRUE(exactly(s.color, ambientOnly)) << "a shadowed point must get exactly Ia ⊙ ma";
        EXPECT_FALSE(exactly(s.color, nudged(ambientOnly))) << "negative control: the comparison sees one ulp";
        const glm::vec3 lit = wi.primary(toLit).color;
        EXPECT_TRUE(lit.x > ambientOnly.x && lit.y > ambientOnly.y && lit.z > ambientOnly.z) << "outside the shadow";

        sc.terms.shadows = false;  // negative control: the same point without shadows gets the light too
        const glm::vec3 unshadowed = WhittedIntegrator(TraceScene(sc), 5).primary(toShadow).color;
        EXPECT_FALSE(exactly(unshadowed, ambientOnly));
        EXPECT_GT(unshadowed.x, ambientOnly.x + 0.1f);
    }
}

// A mirror sphere (kr, md = ms = ma = 0) in front of a pinhole camera; behind the camera a small ambient-only
// sphere that only the ray reflected straight back can reach.
Scene mirrorScene(glm::vec3 kr) {
    Scene sc;
    sc.camera.position = {0, 0, 5};
    sc.camera.target = {0, 0, 0};
    sc.camera.up = {0, 1, 0};
    sc.ambient = {0.5f, 0.25f, 1.0f};
    sc.background = {0.25f, 0.5f, 0.75f};
    sc.lights = {pointLight({3, 3, 3}, glm::vec3(1.0f))};
    Material mirror = test::plainMaterial(glm::vec3(0.0f));
    mirror.kr = kr;
    sc.spheres.push_back(Sphere{"mirror", {0, 0, 0}, 1.0f, mirror});
    sc.spheres.push_back(Sphere{"behind", {0, 0, 7}, 0.5f, test::plainMaterial({0.9f, 0.5f, 0.1f})});
    return sc;
}

glm::vec3 centrePixel(const Scene& sc, int maxDepth = -1) {
    TraceSettings st;
    st.width = st.height = 5;  // odd: the centre pixel's ray is exactly the camera's forward axis
    st.threads = 1;
    st.maxDepth = maxDepth;
    const TraceOutput out = traceImage(sc, st);
    const float* p = out.color.pixel(2, 2);
    return {p[0], p[1], p[2]};
}

TEST(TracerPhysics, MirrorSphereReflectsAKnownColour) {
    for (const glm::vec3 kr : {glm::vec3(1.0f), glm::vec3(1.0f, 0.5f, 0.25f)}) {
        Scene sc = mirrorScene(kr);
        const glm::vec3 behind = kr * (sc.ambient * sc.spheres[1].material.ma);
        EXPECT_TRUE(exactly(centrePixel(sc), behind)) << "the centre ray must come back along itself";
        EXPECT_FALSE(exactly(centrePixel(sc), nudged(behind))) << "negative control";
        sc.spheres.pop_back();
        EXPECT_TRUE(exactly(centrePixel(sc), kr * sc.background)) << "back along itself into the background";
        sc.terms.reflections = false;
        EXPECT_TRUE(exactly(centrePixel(sc), glm::vec3(0.0f))) << "negative control: reflections off is black";
    }
}

// Glass slab: planes y = 0 and y = -d, or a wide flat-shaded box mesh between them (kt = 1, ior 1.5, no local
// terms), over a red/blue checker floor at y = -d - gap lit from straight above: the floor colour is md or md2.
struct Slab {
    float d = 1.0f, gap = 0.5f, height = 2.0f, tile = 0.05f, ior = 1.5f;
};

enum class SlabKind { None, Planes, Mesh };

// The box [lo, hi] with one normal per face (4 own vertices each), counter-clockwise seen from outside.
MeshPart flatBox(glm::vec3 lo, glm::vec3 hi, const Material& m) {
    MeshGeometry p;
    for (int axis = 0; axis < 3; ++axis)
        for (const bool high : {false, true}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // e_u × e_v = e_axis
            const uint32_t base = uint32_t(p.positions.size());
            for (int k = 0; k < 4; ++k) {
                glm::vec3 c, n(0.0f);
                c[axis] = high ? hi[axis] : lo[axis];
                c[u] = k == 1 || k == 2 ? hi[u] : lo[u];
                c[v] = k >= 2 ? hi[v] : lo[v];
                n[axis] = high ? 1.0f : -1.0f;
                p.positions.push_back(c);
                p.normals.push_back(n);
            }
            if (high)
                p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            else
                p.indices.insert(p.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
        }
    return MeshPart{shareGeometry(std::move(p)), m};
}

Scene slabScene(const Slab& s, SlabKind kind) {
    Scene sc;
    sc.camera.position = {0, 3, 4};
    sc.ambient = glm::vec3(0.0f);
    sc.terms.shadows = false;  // glass casts black shadows (trace_scene.h); this test is about refraction
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, -1, 0};
    sc.lights = {sun};
    Material glass = test::plainMaterial(glm::vec3(0.0f));
    glass.kt = glm::vec3(1.0f);
    glass.ior = s.ior;
    if (kind == SlabKind::Planes) {
        sc.planes.push_back(plane({0, 1, 0}, 0.0f, glass));
        sc.planes.push_back(plane({0, -1, 0}, s.d, glass));
    } else if (kind == SlabKind::Mesh) {
        sc.meshes = {Mesh{}};
        sc.meshes[0].parts = {flatBox({-20.0f, -s.d, -20.0f}, {20.0f, 0.0f, 20.0f}, glass)};
    }
    Plane floor = plane({0, 1, 0}, -(s.d + s.gap), test::plainMaterial(glm::vec3(0.0f), {1, 0, 0}));
    floor.checker = Checker{{0, 0, 1}, s.tile};
    sc.planes.push_back(floor);
    return sc;
}

// Where a ray from `o` at incidence θ and azimuth φ lands on the floor: the straight line, moved back along
// the azimuth by the slab's lateral displacement d·sin(θ − θt)/cos θt, seen on the floor as that / cos θ.
glm::vec3 predictedLanding(const Slab& s, glm::vec3 o, float theta, float phi, float ior, bool withSlab) {
    const double th = theta, tt = std::asin(std::sin(th) / double(ior));
    const double along = double(s.height + s.d + s.gap) * std::tan(th) -
                         (withSlab ? double(s.d) * std::sin(th - tt) / std::cos(tt) / std::cos(th) : 0.0);
    return {float(o.x + along * std::cos(phi)), -(s.d + s.gap), float(o.z + along * std::sin(phi))};
}

// Parity at P, or -1 when P lies within 20 % of a tile of a tile edge (epsilon offsets move the landing).
int safeParity(glm::vec3 P, float tile) {
    const glm::vec3 n(0, 1, 0);
    for (const glm::vec3 axis : {shading::planeTangent(n), shading::planeBitangent(n)}) {
        const float u = glm::dot(P, axis) / tile;
        if (std::fabs(u - std::round(u)) < 0.2f) return -1;
    }
    return shading::checkerParity(P, n, tile);
}

TEST(TracerPhysics, GlassSlabShiftsTheCheckerAsSnellPredicts) {
    const Slab slab;
    const TraceScene tsFree(slabScene(slab, SlabKind::None));
    const WhittedIntegrator noSlab(tsFree, 5);
    for (const SlabKind kind : {SlabKind::Planes, SlabKind::Mesh}) {
        const TraceScene tsSlab(slabScene(slab, kind));
        const WhittedIntegrator slabbed(tsSlab, 5);
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f), theta(0.09f, 1.2f), phi(0.0f, 6.2831853f);
        int checked = 0, wrong = 0, straightDiffers = 0, wrongIorDiffers = 0, controlChecked = 0, controlWrong = 0;
        auto parityOf = [](glm::vec3 c) { return c == glm::vec3(1, 0, 0) ? 0 : c == glm::vec3(0, 0, 1) ? 1 : -1; };
        for (int i = 0; i < 400; ++i) {
            const float th = theta(rng), ph = phi(rng);
            const glm::vec3 o(u(rng), slab.height, u(rng));
            const Ray ray{
                o, glm::normalize(glm::vec3(std::sin(th) * std::cos(ph), -std::cos(th), std::sin(th) * std::sin(ph)))};
            const int parity = parityOf(slabbed.radiance(ray, 0)), parityFree = parityOf(noSlab.radiance(ray, 0));
            ASSERT_GE(parity, 0) << "through kt = 1 the floor colour must arrive unchanged, ray " << i;
            const int expected = safeParity(predictedLanding(slab, o, th, ph, slab.ior, true), slab.tile);
            if (expected >= 0) {
                ++checked;
                wrong += parity != expected;
                const int straight = safeParity(predictedLanding(slab, o, th, ph, slab.ior, false), slab.tile);
                straightDiffers += straight >= 0 && straight != parity;
                const int water = safeParity(predictedLanding(slab, o, th, ph, 1.33f, true), slab.tile);
                wrongIorDiffers += water >= 0 && water != parity;
            }
            const int expectedFree = safeParity(predictedLanding(slab, o, th, ph, slab.ior, false), slab.tile);
            if (expectedFree >= 0) ++controlChecked, controlWrong += parityFree != expectedFree;
        }
        const char* name = kind == SlabKind::Planes ? "two planes" : "box mesh";
        EXPECT_GT(checked, 60) << name;
        EXPECT_EQ(wrong, 0) << name << ": of " << checked
                            << " rays, the checker seen through the slab is not where Snell puts it";
        EXPECT_GT(controlChecked, 60);
        EXPECT_EQ(controlWrong, 0) << "without the slab the straight-line prediction must hold";
        // Negative controls: ignoring the slab, or assuming water's ior, mispredicts many rays.
        EXPECT_GT(straightDiffers, checked / 10) << name;
        EXPECT_GT(wrongIorDiffers, 0) << name;
    }
}

// An interface plane y = 0 (outward +y) with the dense side below; ambient-only floor (y = -2) and ceiling
// (y = +2) tell where the energy went.
TEST(TracerPhysics, TotalInternalReflectionSendsTransmissionIntoTheReflectedRay) {
    Scene sc;
    sc.ambient = glm::vec3(0.5f);
    Material glass = test::plainMaterial(glm::vec3(0.0f));
    glass.kt = {1.0f, 0.5f, 0.25f};
    glass.ior = 1.5f;
    sc.planes = {plane({0, 1, 0}, 0.0f, glass), plane({0, 1, 0}, -2.0f, test::plainMaterial({0.8f, 0.4f, 0.2f})),
                 plane({0, -1, 0}, -2.0f, test::plainMaterial({0.1f, 0.7f, 0.3f}))};
    const glm::vec3 floorC = sc.ambient * sc.planes[1].material.ma, ceilingC = sc.ambient * sc.planes[2].material.ma;
    const float critical = std::asin(1.0f / 1.5f);  // 41.8°
    auto fromInside = [](float th) { return Ray{{0, -1, 0}, {std::sin(th), std::cos(th), 0.0f}}; };
    for (const glm::vec3 kr : {glm::vec3(0.0f), glm::vec3(0.25f, 0.125f, 0.5f)}) {
        sc.planes[0].material.kr = kr;
        const TraceScene ts(sc);
        const WhittedIntegrator wi(ts, 5);
        for (const float th : {critical + 0.02f, 1.05f, 1.4f})
            EXPECT_TRUE(exactly(wi.radiance(fromInside(th), 0), (kr + glass.kt) * floorC)) << "TIR at θ = " << th;
        for (const float th : {0.0f, 0.5f, critical - 0.02f})
            EXPECT_TRUE(exactly(wi.radiance(fromInside(th), 0), kr * floorC + glass.kt * ceilingC))
                << "refraction at θ = " << th << " (negative control: below the critical angle the light leaves)";
        // From the rare side (outside) there is no critical angle: steep rays still enter.
        const Ray fromOutside{{0, 1, 0}, {std::sin(1.4f), -std::cos(1.4f), 0.0f}};
        EXPECT_TRUE(exactly(wi.radiance(fromOutside, 0), kr * ceilingC + glass.kt * floorC));
    }
}

TEST(TracerPhysics, DepthZeroGivesLocalShadingOnly) {
    Scene sc = mirrorScene(glm::vec3(0.6f));
    sc.spheres[0].material.ma = glm::vec3(0.2f);
    sc.spheres[0].material.md = glm::vec3(0.5f, 0.3f, 0.1f);
    sc.spheres[0].material.ms = glm::vec3(0.4f);
    const TraceScene ts(sc);
    const WhittedIntegrator depth0(ts, 0), depth1(ts, 1);
    const Ray ray = test::rayTowards(sc.camera.position, {0.2f, 0.1f, 0.9f});
    const std::optional<Hit> hit = ts.intersect(ray);
    ASSERT_TRUE(hit);
    const glm::vec3 local = depth0.local(ray, depth0.surfaceAt(ray, *hit));
    EXPECT_TRUE(exactly(depth0.primary(ray).color, local));
    EXPECT_FALSE(exactly(depth1.primary(ray).color, local)) << "negative control: depth 1 adds the reflection";

    // Whole images: settings depth 0 and scene depth 0 both equal reflections off, and depth 1 does not.
    TraceSettings st;
    st.width = 24;
    st.height = 16;
    st.threads = 1;
    st.maxDepth = 0;
    const ImageF limited = traceImage(sc, st).color;
    Scene off = sc;
    off.terms.reflections = false;
    st.maxDepth = -1;
    EXPECT_EQ(limited.rgba, traceImage(off, st).color.rgba);
    Scene sceneDepth0 = sc;
    sceneDepth0.maxDepth = 0;
    EXPECT_EQ(limited.rgba, traceImage(sceneDepth0, st).color.rgba);
    st.maxDepth = 1;
    EXPECT_NE(limited.rgba, traceImage(sc, st).color.rgba);

    // Depth counts bounces: the floor under the slab is two transmissions away.
    const Slab slab;
    const TraceScene glass(slabScene(slab, SlabKind::Planes));
    const Ray down{{0.026f, 2, -0.024f}, {0, -1, 0}};  // lands mid-tile on md (red)
    EXPECT_TRUE(exactly(WhittedIntegrator(glass, 0).radiance(down, 0), glm::vec3(0.0f)));
    EXPECT_TRUE(exactly(WhittedIntegrator(glass, 1).radiance(down, 0), glm::vec3(0.0f)));
    EXPECT_TRUE(exactly(WhittedIntegrator(glass, 2).radiance(down, 0), glm::vec3(1, 0, 0)));
}

}  // namespace
