// χ² tests of every sampling routine of the path tracer against the density it claims (design.md §8):
// the BSDF lobes through PathBsdf::sample / pdf (Phong, Blinn-Phong, pbr's GGX visible normals, the
// diffuse lobe, and their mixtures), the emitters' cone and area sampling, and the environment map's
// texel sampling. Each routine has a negative control: a deliberately wrong density must fail.
#include "scene/environment_load.h"
#include "shading/local_illumination.h"
#include "trace/path/chi2_test_util.h"
#include "trace/path/emitters.h"
#include "trace/path/environment_sampler.h"
#include "trace/path/path_bsdf.h"
#include "trace/path/sample_rng.h"

#include <gtest/gtest.h>

#include <cmath>

namespace shadelab::trace {
namespace {

using test::Chi2Result;

constexpr int kSamples = 400000;
// Significance of one test: 1e-3 over the ~20 tests of this file keeps a false alarm below 2 %.
constexpr double kAlpha = 1e-3;

glm::vec3 numbers(int k, uint32_t group = 0) {
    SampleRng rng;
    rng.pixel = uint32_t(k);
    rng.seed = 12345u;
    return glm::vec3(rng.draw(0, group));
}

struct Lobe {
    int model;
    glm::vec3 md, ms;
    float s;  // exponent, or roughness under pbr
    glm::vec3 V;
};

// The BSDF on the plane z = 0 seen from V.
PathBsdf makeBsdf(const Lobe& l, Material& m, Surface& s) {
    m.md = l.md;
    m.ms = l.ms;
    m.s = l.s;
    s.material = &m;
    s.N = s.Nf = glm::vec3(0.0f, 0.0f, 1.0f);
    s.md = l.md;
    shading::SurfaceParams p{glm::vec3(0.0f), l.md, l.ms, l.s};
    return PathBsdf(s, p, glm::normalize(l.V), l.model, BsdfTerms{});
}

Chi2Result testLobe(const Lobe& l, float pdfScale = 1.0f, float exponentError = 0.0f) {
    Material m;
    Surface s;
    const PathBsdf bsdf = makeBsdf(l, m, s);
    Lobe wrong = l;
    wrong.s += exponentError;
    Material m2;
    Surface s2;
    const PathBsdf claimed = makeBsdf(wrong, m2, s2);
    return test::chi2Directions(
        [&](int k) -> std::optional<glm::vec3> {
            const auto b = bsdf.sample(numbers(k));
            return b ? std::optional<glm::vec3>(b->wi) : std::nullopt;
        },
        [&](const glm::vec3& w) { return w.z > 0.0f ? pdfScale * claimed.pdf(w) : 0.0f; }, kSamples);
}

const glm::vec3 kOblique(0.5f, 0.2f, 0.6f);

TEST(PathSampling, PhongLobeMatchesItsPdf) {
    for (float s : {1.0f, 10.0f, 60.0f}) {
        const Chi2Result r = testLobe({shading::SL_MODEL_PHONG, glm::vec3(0.0f), glm::vec3(1.0f), s, kOblique});
        EXPECT_GT(r.pValue, kAlpha) << "s = " << s << ": " << r.summary();
        EXPECT_EQ(r.observedOutside, 0.0);
    }
}

TEST(PathSampling, BlinnPhongLobeMatchesItsPdf) {
    for (float s : {1.0f, 10.0f, 60.0f}) {
        const Chi2Result r = testLobe({shading::SL_MODEL_BLINN_PHONG, glm::vec3(0.0f), glm::vec3(1.0f), s, kOblique});
        EXPECT_GT(r.pValue, kAlpha) << "s = " << s << ": " << r.summary();
    }
}

TEST(PathSampling, GgxVisibleNormalsMatchTheirPdf) {
    for (float roughness : {0.3f, 0.6f, 1.0f})
        for (glm::vec3 V : {kOblique, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.9f, 0.0f, 0.15f)}) {
            const Chi2Result r = testLobe({shading::SL_MODEL_PBR, glm::vec3(0.0f), glm::vec3(1.0f), roughness, V});
            EXPECT_GT(r.pValue, kAlpha) << "roughness " << roughness << ": " << r.summary();
        }
}

TEST(PathSampling, DiffuseAndMixturesMatchTheirPdf) {
    for (int model : {shading::SL_MODEL_PHONG, shading::SL_MODEL_BLINN_PHONG, shading::SL_MODEL_PBR}) {
        const float s = model == shading::SL_MODEL_PBR ? 0.5f : 20.0f;
        const Chi2Result diffuse = testLobe({model, glm::vec3(0.8f), glm::vec3(0.0f), s, kOblique});
        EXPECT_GT(diffuse.pValue, kAlpha) << "model " << model << " diffuse: " << diffuse.summary();
        const Chi2Result mix = testLobe({model, glm::vec3(0.5f), glm::vec3(0.5f), s, kOblique});
        EXPECT_GT(mix.pValue, kAlpha) << "model " << model << " mixture: " << mix.summary();
    }
}

TEST(PathSampling, NegativeControlWrongLobePdfsFail) {
    // The Phong lobe's density with the exponent off by 2 (the normalisation (s+2)/2π in place of (s+1)/2π
    // is the classic mistake), Blinn-Phong's without the 1/(4 V·H) Jacobian, GGX with roughness off by 20 %.
    const Chi2Result phong =
        testLobe({shading::SL_MODEL_PHONG, glm::vec3(0.0f), glm::vec3(1.0f), 20.0f, kOblique}, 1.0f, 2.0f);
    EXPECT_LT(phong.pValue, kAlpha) << phong.summary();
    const Chi2Result ggx =
        testLobe({shading::SL_MODEL_PBR, glm::vec3(0.0f), glm::vec3(1.0f), 0.5f, kOblique}, 1.0f, 0.1f);
    EXPECT_LT(ggx.pValue, kAlpha) << ggx.summary();
    const Chi2Result scaled =
        testLobe({shading::SL_MODEL_PHONG, glm::vec3(0.8f), glm::vec3(0.0f), 1.0f, kOblique}, 1.05f);
    EXPECT_LT(scaled.pValue, kAlpha) << scaled.summary();
}

TEST(PathSampling, WarpsMatchTheirPdfs) {
    const Chi2Result cone = test::chi2Directions(
        [](int k) -> std::optional<glm::vec3> {
            const glm::vec3 u = numbers(k);
            return sampleUniformCone(glm::vec2(u.y, u.z), 0.7f);
        },
        [](const glm::vec3& w) { return w.z >= 0.7f ? uniformConePdf(0.7f) : 0.0f; }, kSamples);
    EXPECT_GT(cone.pValue, kAlpha) << cone.summary();
    const Chi2Result sphere = test::chi2Directions(
        [](int k) -> std::optional<glm::vec3> {
            const glm::vec3 u = numbers(k);
            return sampleUniformSphere(glm::vec2(u.y, u.z));
        },
        [](const glm::vec3&) { return kUniformSpherePdf; }, kSamples);
    EXPECT_GT(sphere.pValue, kAlpha) << sphere.summary();
}

// An emissive sphere and an emissive triangle seen from the origin: the directions Emitters::sample
// draws against pdfHit of the rays that hit them.
TEST(PathSampling, EmitterSamplingMatchesItsPdf) {
    Scene scene;
    Sphere lamp;
    lamp.center = glm::vec3(0.3f, 0.2f, 2.0f);
    lamp.radius = 0.9f;
    lamp.material.emission = glm::vec3(1.0f);
    scene.spheres.push_back(lamp);
    MeshGeometry g;
    g.positions = {{-2.0f, -1.0f, -1.0f}, {1.0f, -2.0f, -1.5f}, {0.0f, 2.0f, -1.2f}};
    g.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    g.indices = {0, 1, 2};
    Mesh mesh;
    MeshPart part;
    part.geometry = shareGeometry(std::move(g));
    part.material.emission = glm::vec3(2.0f, 1.0f, 0.5f);
    mesh.parts.push_back(part);
    scene.meshes.push_back(mesh);
    const TraceScene traced(scene);
    const EnvironmentSampler env(traced.scene());
    const Emitters emitters(traced, env);
    const glm::vec3 P(0.0f);
    auto pdfOf = [&](const glm::vec3& w, float scale) {
        const Ray ray{P, glm::normalize(w)};
        const std::optional<Hit> hit = traced.intersect(ray);
        return hit ? scale * emitters.pdfHit(ray, *hit) : 0.0f;
    };
    auto sample = [&](int k) -> std::optional<glm::vec3> {
        SampleRng rng;
        rng.pixel = uint32_t(k);
        const auto e = emitters.sample(P, rng.draw(0, 1));
        return e ? std::optional<glm::vec3>(e->wi) : std::nullopt;
    };
    const Chi2Result r = test::chi2Directions(
        sample, [&](const glm::vec3& w) { return pdfOf(w, 1.0f); }, kSamples, 20, 40, 32);
    EXPECT_GT(r.pValue, kAlpha) << r.summary();
    // Negative control: the power weighting ignored (a uniform pick between the two) must fail.
    const Chi2Result wrong = test::chi2Directions(
        sample,
        [&](const glm::vec3& w) {
            const Ray ray{P, glm::normalize(w)};
            const std::optional<Hit> hit = traced.intersect(ray);
            if (!hit) return 0.0f;
            return hit->kind == HitKind::Sphere ? 1.1f * emitters.pdfHit(ray, *hit) : 0.9f * emitters.pdfHit(ray, *hit);
        },
        kSamples, 40, 80, 8);
    EXPECT_LT(wrong.pValue, kAlpha) << wrong.summary();
}

// From inside an emissive sphere the emitter samples its area; the pdf converts it to solid angle.
TEST(PathSampling, EmitterSamplingFromInsideASphereMatchesItsPdf) {
    Scene scene;
    Sphere lamp;
    lamp.radius = 1.5f;
    lamp.material.emission = glm::vec3(1.0f);
    scene.spheres.push_back(lamp);
    const TraceScene traced(scene);
    const EnvironmentSampler env(traced.scene());
    const Emitters emitters(traced, env);
    const glm::vec3 P(0.4f, -0.5f, 0.3f);
    auto sample = [&](int k) -> std::optional<glm::vec3> {
        SampleRng rng;
        rng.pixel = uint32_t(k);
        const auto e = emitters.sample(P, rng.draw(0, 1));
        return e ? std::optional<glm::vec3>(e->wi) : std::nullopt;
    };
    auto pdf = [&](const glm::vec3& w) {
        const Ray ray{P, glm::normalize(w)};
        const std::optional<Hit> hit = traced.intersect(ray);
        return hit ? emitters.pdfHit(ray, *hit) : 0.0f;
    };
    const Chi2Result r = test::chi2Directions(sample, pdf, kSamples);
    EXPECT_GT(r.pValue, kAlpha) << r.summary();
    // Negative control: a density that forgets the cosine at the light (d² alone) must fail.
    const Chi2Result wrong = test::chi2Directions(
        sample,
        [&](const glm::vec3& w) {
            const Ray ray{P, glm::normalize(w)};
            const std::optional<Hit> hit = traced.intersect(ray);
            return hit ? hit->t * hit->t / (4.0f * kPi * lamp.radius * lamp.radius) : 0.0f;
        },
        kSamples);
    EXPECT_LT(wrong.pValue, kAlpha) << wrong.summary();
}

TEST(PathSampling, EnvironmentMapSamplingMatchesItsPdf) {
    Scene scene;
    scene.environment = Environment{};
    scene.environment->hdr = SHADELAB_SOURCE_DIR "/assets/environments/sky.hdr";
    scene.environment->rotation = 30.0f;
    shading::PrefilterSettings p;
    p.size = 16;
    p.samples = 4;
    loadEnvironment(scene, "", p);
    const EnvironmentSampler env(scene);
    ASSERT_TRUE(env.emits());
    auto sample = [&](int k) -> std::optional<glm::vec3> { return env.sample(numbers(k)).dir; };
    const Chi2Result r = test::chi2Directions(
        sample, [&](const glm::vec3& w) { return env.pdf(w); }, kSamples, 30, 60, 16);
    EXPECT_GT(r.pValue, kAlpha) << r.summary();
    // Negative control: the rotation forgotten in the density.
    Scene unrotated = scene;
    unrotated.environment->rotation = 0.0f;
    const EnvironmentSampler other(unrotated);
    const Chi2Result wrong = test::chi2Directions(
        sample, [&](const glm::vec3& w) { return other.pdf(w); }, kSamples, 30, 60, 16);
    EXPECT_LT(wrong.pValue, kAlpha) << wrong.summary();
}

TEST(PathSampling, FaceDirectionInvertsCubeFaceCoords) {
    shading::IblLookup l;
    for (int f = 0; f < 6; ++f)
        for (float x : {-0.9f, 0.1f, 0.7f})
            for (float y : {-0.5f, 0.3f}) {
                const glm::vec3 d = EnvironmentSampler::faceDirection(f, x, y);
                EXPECT_EQ(l.cubeFace(d), f);
                const glm::vec3 c = l.cubeFaceCoords(d, f);
                EXPECT_NEAR(c.x, x, 1e-6f);
                EXPECT_NEAR(c.y, y, 1e-6f);
            }
}

}  // namespace
}  // namespace shadelab::trace
