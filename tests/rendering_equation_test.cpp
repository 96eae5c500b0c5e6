// The rendering equation at a pixel (probe/rendering_equation.h): its hemisphere map is equal-area; under
// the local models its integral is the local model's pixel exactly (the probe's totals, to 1e-4), and under
// global illumination it is the path tracer's estimate of that pixel within 3 standard errors on the
// Cornell box. Negative controls: a map that is not equal-area, and an integral without its cosine, fail.
#include "probe/rendering_equation.h"
#include "probe/probe.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "test_output.h"
#include "trace/integrator.h"
#include "trace/path/path_render.h"
#include "trace/tile_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace shadelab {
namespace {

double maxAbs(const glm::vec3& a, const glm::vec3& b) {
    return std::max({std::fabs(double(a.x - b.x)), std::fabs(double(a.y - b.y)), std::fabs(double(a.z - b.z))});
}

}  // namespace

TEST(RenderingEquation, HemisphereMapIsEqualAreaAndInvertible) {
    const int n = 256;
    double meanCos = 0.0, meanCosNaive = 0.0;
    double worst = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec2 uv((float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n));
            const glm::vec3 d = hemisphereDirection(uv);
            ASSERT_GE(d.z, 0.0f);
            ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
            const glm::vec2 back = hemisphereTexel(d);
            worst = std::max(worst, double(glm::length(back - uv)));
            meanCos += double(d.z);
            // The obvious map, θ linear in the radius of a disc inscribed in the square, is not equal-area.
            meanCosNaive += std::cos(double(std::min(glm::length(2.0f * uv - 1.0f), 1.0f)) * M_PI / 2.0);
        }
    EXPECT_LT(worst, 1e-4) << "texel -> direction -> texel";
    // Equal area: texel centres sample solid angle uniformly, so the mean of cos θ is ∫cos dω / 2π = 1/2.
    EXPECT_NEAR(meanCos / (n * n), 0.5, 1e-3);
    EXPECT_GT(std::fabs(meanCosNaive / (n * n) - 0.5), 1e-2) << "negative control";
}

TEST(RenderingEquation, LocalIntegralIsTheLocalModelsPixel) {
    Scene scene = loadScene(test::sourcePath("assets/scenes/default.json"));
    scene.terms.reflections = false;  // the local model alone: kr's mirror rays are not part of it
    int pixels = 0, withoutCosineFails = 0;
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
        scene.model = model;
        const trace::TraceScene ts(scene);
        for (int y = 10; y < 90; y += 9)
            for (int x = 7; x < 160; x += 13) {
                const RenderingEquation re = renderingEquationAt(ts, 160, 90, x, y, false, 16);
                const ProbeResult p = probePixel(ts, 160, 90, x, y);
                ASSERT_EQ(re.hit, p.hit) << x << "," << y;
                if (!re.hit) continue;
                ++pixels;
                const glm::vec3 expected = model == ShadingModel::Pbr          ? p.totalPbr
                                           : model == ShadingModel::BlinnPhong ? p.totalBlinn
                                                                               : p.totalPhong;
                EXPECT_LT(maxAbs(re.total, expected), 1e-4) << toString(model) << " pixel " << x << "," << y;
                // Negative control: the same sum with each light's cos θ left out is another number.
                glm::vec3 wrong = re.ambient + re.emission;
                for (const HemisphereLight& l : re.lights) {
                    const float cosTheta = hemisphereDirection(l.at).z;
                    if (l.above && cosTheta > 1e-3f) wrong += l.term / cosTheta;
                }
                withoutCosineFails += maxAbs(wrong, expected) > 1e-3 ? 1 : 0;
            }
    }
    EXPECT_GT(pixels, 100);
    EXPECT_GT(withoutCosineFails, pixels / 2);
}

TEST(RenderingEquation, GlobalIntegralIsThePathTracersEstimate) {
    const Scene scene = loadScene(test::sourcePath("assets/scenes/cornell.json"));
    const int w = 160, h = 90;
    const auto ts = std::make_shared<const trace::TraceScene>(scene);
    trace::PathSettings s;
    s.width = w, s.height = h, s.threads = 2, s.spp = 256;
    s.sampler = trace::PathSampler::Independent;  // its standard error is an honest one
    trace::PathRender render(ts, s);
    render.addSamples(s.spp);
    int checked = 0;
    // The back wall, the left wall and the floor: diffuse surfaces lit by the lamp and by each other.
    for (const glm::ivec2 px : {glm::ivec2(80, 30), glm::ivec2(20, 45), glm::ivec2(80, 80)}) {
        const RenderingEquation re = renderingEquationAt(*ts, w, h, px.x, px.y, true, 32, 16);
        ASSERT_TRUE(re.hit);
        const glm::vec3 mean = render.mean(px.x, px.y), se = render.standardError(px.x, px.y);
        glm::vec3 noCosine = re.emission + re.lightSum;
        const float texel = 2.0f * float(M_PI) / float(re.size * re.size);
        for (int j = 0; j < re.size; ++j)
            for (int i = 0; i < re.size; ++i) {
                const size_t t = size_t(j) * size_t(re.size) + size_t(i);
                const float c =
                    hemisphereDirection({(float(i) + 0.5f) / float(re.size), (float(j) + 0.5f) / float(re.size)}).z;
                noCosine += re.product[t] / std::max(c, 0.05f) * texel;
            }
        for (int c = 0; c < 3; ++c) {
            const double sigma = std::sqrt(double(se[c]) * se[c] + double(re.imageError[c]) * re.imageError[c]);
            EXPECT_LT(std::fabs(double(re.total[c] - mean[c])), 3.0 * sigma)
                << "pixel " << px.x << "," << px.y << " channel " << c << ": integral " << re.total[c] << " (±"
                << re.imageError[c] << "), path tracer " << mean[c] << " (±" << se[c] << ")";
            EXPECT_GT(std::fabs(double(noCosine[c] - mean[c])), 3.0 * sigma) << "negative control, pixel " << px.x;
        }
        std::printf(
            "pixel %d,%d: integral %.4f %.4f %.4f (images %.4f ± %.4f, lights %.4f), path tracer %.4f %.4f %.4f ± "
            "%.4f; "
            "without the cosine %.4f\n",
            px.x, px.y, re.total.x, re.total.y, re.total.z, re.imageIntegral.x, re.imageError.x, re.lightSum.x, mean.x,
            mean.y, mean.z, se.x, noCosine.x);
        EXPECT_GT(re.imageIntegral.x, 0.0f) << "the lamp and the walls light the point";
        ++checked;
    }
    EXPECT_EQ(checked, 3);
}

}  // namespace shadelab

namespace shadelab {

// The lecture's step 0 (no light term on): the image shows each surface's unlit colour, and the probe, the
// rendering equation and the reference say the same number. Control: with the ambient on they do not.
TEST(RenderingEquation, NoIlluminationIsTheUnlitColourEverywhere) {
    Scene scene = loadScene(test::sourcePath("assets/scenes/default.json"));
    scene.terms = Terms{false, false, false, false, false};
    int checked = 0;
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Pbr}) {
        scene.model = model;
        const trace::TraceScene ts(scene);
        const trace::WhittedIntegrator whitted(ts, scene.maxDepth);
        const ViewSetup view = makeViewSetup(scene, 160, 90);
        for (int y = 5; y < 90; y += 10)
            for (int x = 5; x < 160; x += 10) {
                const ProbeResult p = probePixel(ts, 160, 90, x, y);
                if (!p.hit) continue;
                EXPECT_TRUE(p.unlit);
                const glm::vec3 shown = model == ShadingModel::Pbr ? p.totalPbr : p.totalPhong;
                if (model == ShadingModel::Phong) {
                    EXPECT_EQ(shown, p.material.md) << x << "," << y;  // the checker tile's md
                }
                const glm::vec3 traced = whitted.primary(trace::sampleRay(view, 1, x, y, 0, 0)).color;
                EXPECT_LT(maxAbs(traced, shown + p.material.emission), 1e-6) << toString(model) << " " << x << "," << y;
                EXPECT_LT(maxAbs(renderingEquationAt(ts, 160, 90, x, y, false, 8).total, traced), 1e-6)
                    << toString(model) << " " << x << "," << y;
                ++checked;
            }
    }
    EXPECT_GT(checked, 50);
    scene.terms.ambient = true;
    const trace::TraceScene lit(scene);
    const ProbeResult p = probePixel(lit, 160, 90, 80, 70);
    ASSERT_TRUE(p.hit);
    EXPECT_FALSE(p.unlit);
    EXPECT_GT(maxAbs(p.totalPhong, p.material.md), 1e-3) << "negative control: ambient on is Ia·ma, not md";
}

}  // namespace shadelab
