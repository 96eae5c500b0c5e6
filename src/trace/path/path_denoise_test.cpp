// The denoised preview on the Cornell box (assets/scenes/cornell.json) at 16 samples per pixel: its error
// against a 1,024-sample reference is at most half the raw image's, and (negative control) a plain blur of
// the same footprint, which crosses every edge, is not. Also: every pixel of a render converged enough to show
// no noise at 8 bits comes back within one 8-bit step, and the denoise flag reaches pathTraceImage's output.
#include "trace/path/path_denoise.h"
#include "image/encode.h"
#include "scene/scene_load.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_render.h"
#include "trace/trace_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

namespace shadelab::trace {
namespace {

std::shared_ptr<const TraceScene> cornell() {
    return std::make_shared<const TraceScene>(
        loadScene(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/cornell.json"));
}

PathSettings settings(int spp, uint32_t seed) {
    PathSettings s;
    s.width = 128;
    s.height = 72;
    s.spp = spp;
    s.threads = 2;
    s.seed = seed;
    return s;
}

// A reference of 2 × 128 samples at 128x72: the mean of two renders of other seeds, and per pixel and channel
// the variance of that mean, |A − B|² / 4 (exact in expectation for any sampler), which the error below
// subtracts so that 256 samples serve as well as thousands.
struct Reference {
    ImageF image;
    std::vector<double> variance;
};

const Reference& reference() {
    static const Reference ref = [] {
        PathRender a(cornell(), settings(128, 1)), b(cornell(), settings(128, 2));
        a.addSamples(128);
        b.addSamples(128);
        Reference r{a.image(), {}};
        const ImageF other = b.image();
        for (size_t i = 0; i < r.image.rgba.size(); i += 4)
            for (size_t c = 0; c < 3; ++c) {
                const double d = double(r.image.rgba[i + c]) - other.rgba[i + c];
                r.image.rgba[i + c] = 0.5f * (r.image.rgba[i + c] + other.rgba[i + c]);
                r.variance.push_back(0.25 * d * d);
            }
        return r;
    }();
    return ref;
}

// sqrt(Σ (|a − r|² − var r) / Σ (|r|² − var r)) over RGB, the lamp (above 1 in the reference) left out: it is
// not noise. With r = μ + ε, the squared error against the converged image μ, without the reference's noise.
double relativeRmse(const ImageF& a, const Reference& ref) {
    double num = 0.0, den = 0.0;
    for (size_t i = 0, k = 0; i < a.rgba.size(); i += 4, k += 3) {
        if (ref.image.rgba[i] > 1.0f) continue;
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgba[i + c]) - ref.image.rgba[i + c], r = ref.image.rgba[i + c];
            num += d * d - ref.variance[k + c];
            den += r * r - ref.variance[k + c];
        }
    }
    return std::sqrt(std::max(0.0, num / den));
}

// Σ a / Σ r over the same pixels: the image's brightness against the reference's.
double brightness(const ImageF& a, const Reference& ref) {
    double num = 0.0, den = 0.0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        if (ref.image.rgba[i] > 1.0f) continue;
        for (size_t c = 0; c < 3; ++c) {
            num += a.rgba[i + c];
            den += ref.image.rgba[i + c];
        }
    }
    return num / den;
}

TEST(PathDenoise, TheCornellBoxAt16SamplesHalvesItsErrorAndABlurDoesNot) {
    const auto scene = cornell();
    PathRender noisy(scene, settings(16, 0));
    noisy.addSamples(16);
    const SurfacePasses passes = firstHitPasses(*scene, 128, 72, 2);
    const ImageF raw = noisy.image(), denoised = denoisedImage(noisy, passes);
    DenoiseSettings blur;
    blur.sigmaLuminance = 1e6f;
    blur.sigmaNormal = 0.0f;
    blur.sigmaDepth = 1e6f;
    blur.sigmaAlbedo = 1e6f;
    const ImageF blurred = denoisedImage(noisy, passes, blur);
    const double eRaw = relativeRmse(raw, reference()), eDen = relativeRmse(denoised, reference()),
                 eBlur = relativeRmse(blurred, reference());
    std::printf("relative RMSE against 2 x 128 spp: raw %.4f, denoised %.4f (%.2f of raw), blur %.4f\n", eRaw, eDen,
                eDen / eRaw, eBlur);
    EXPECT_LT(eDen, 0.5 * eRaw);
    EXPECT_GT(eBlur, 0.5 * eRaw) << "the negative control: a blur across edges must not pass";
    if (::testing::Test::HasFailure()) {
        test::writeEvidence("path_denoise_raw", raw);
        test::writeEvidence("path_denoise_denoised", denoised);
        test::writeEvidence("path_denoise_reference", reference().image);
    }
}

TEST(PathDenoise, AtFourSamplesTheDenoisedBoxKeepsItsBrightness) {
    // Most of a 4-sample pixel's samples miss the few bright paths, and its sample variance is then small: a
    // filter that stopped at each pixel's own noise with the usual width would keep those pixels dark. The
    // preview pulls each pixel's noise toward its neighbours' and widens the stop at few samples
    // (stopVariance, previewSettings), and so keeps the light the render found.
    const auto scene = cornell();
    const SurfacePasses passes = firstHitPasses(*scene, 128, 72, 2);
    double preview = 0.0, ownNoise = 0.0, raw = 0.0;
    constexpr int kSeeds = 4;
    for (uint32_t seed = 10; seed < 10 + kSeeds; ++seed) {
        PathRender noisy(scene, settings(4, seed));
        noisy.addSamples(4);
        raw += brightness(noisy.image(), reference()) / kSeeds;
        preview += brightness(denoisedImage(noisy, passes), reference()) / kSeeds;
        ownNoise += brightness(denoise(noisy.image(), luminanceVariance(noisy), passes), reference()) / kSeeds;
    }
    std::printf(
        "brightness against the reference at 4 spp (%d seeds): raw %.4f, preview %.4f, the filter at "
        "each pixel's own noise %.4f\n",
        kSeeds, raw, preview, ownNoise);
    EXPECT_NEAR(raw, 1.0, 0.03) << "the raw estimate is unbiased";
    EXPECT_NEAR(preview, 1.0, 0.03);
    EXPECT_LT(ownNoise, 0.95) << "the negative control: stopping at each pixel's own noise darkens";
}

TEST(PathDenoise, TheFirstPassOfOneSampleIsSmoothedToo) {
    // One sample a pixel has no sample variance: the neighbours' spread stands in for it (stopVariance), so the
    // viewer's first pass is already a preview.
    const auto scene = cornell();
    PathRender noisy(scene, settings(1, 0));
    noisy.addSamples(1);
    const SurfacePasses passes = firstHitPasses(*scene, 128, 72, 2);
    const double eRaw = relativeRmse(noisy.image(), reference()),
                 eDen = relativeRmse(denoisedImage(noisy, passes), reference());
    // The negative control: with no noise to stop at, every difference is an edge and nothing moves.
    const ImageF unchanged = denoise(noisy.image(), luminanceVariance(noisy), passes);
    const double eUnchanged = relativeRmse(unchanged, reference());
    std::printf("1 spp: raw %.4f, denoised %.4f; without the neighbours' spread %.4f\n", eRaw, eDen, eUnchanged);
    EXPECT_LT(eDen, 0.3 * eRaw);
    EXPECT_GT(eUnchanged, 0.9 * eRaw) << "the control: with no noise measured, next to nothing is smoothed";
}

TEST(PathDenoise, AnImageWithoutVisibleNoiseComesBackWithinOneStep) {
    // The box's direct light only, its balls made matte (a mirror's tiny lamp reflection covers part of a
    // pixel and stays noisy far longer), at 4096 samples: a standard error far below one 8-bit step.
    Scene s = loadScene(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/cornell.json");
    s.maxDepth = 0;
    for (Sphere& sphere : s.spheres) {
        sphere.material.kr = sphere.material.kt = sphere.material.ms = glm::vec3(0.0f);
        if (sphere.material.emission == glm::vec3(0.0f)) sphere.material.md = glm::vec3(0.6f);
    }
    const auto scene = std::make_shared<const TraceScene>(s);
    PathSettings ps = settings(4096, 0);
    ps.width = 32;
    ps.height = 18;
    PathRender r(scene, ps);
    r.addSamples(ps.spp);
    const ImageF raw = r.image(), denoised = denoisedImage(r, firstHitPasses(*scene, 32, 18, 2));
    uint64_t bad = 0;
    const Image8 a = toImage8(raw, Encoding::Srgb, {}, &bad), b = toImage8(denoised, Encoding::Srgb, {}, &bad);
    // A pixel is converged when its own standard error, through the sRGB curve, is under a quarter of an 8-bit
    // step (the shadows' darkest pixels, where the curve is steepest, may not be).
    int worst = 0, converged = 0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 32; ++x) {
            const glm::vec3 m = r.mean(x, y), se = r.standardError(x, y);
            float se8 = 0.0f;
            for (int c = 0; c < 3; ++c)
                se8 = std::max(
                    se8, 255.0f * (linearToSrgb(std::min(1.0f, m[c] + se[c])) - linearToSrgb(std::min(1.0f, m[c]))));
            if (se8 >= 0.25f) continue;
            ++converged;
            const size_t i = 3 * (size_t(y) * 32 + size_t(x));
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(int(a.data[i + size_t(c)]) - int(b.data[i + size_t(c)])));
        }
    std::printf("noise %.3f/255; %d of %d pixels converged; their largest change %d/255\n",
                r.meanStandardError8(Encoding::Srgb), converged, 32 * 18, worst);
    EXPECT_GT(converged, 32 * 18 * 2 / 3) << "the check must cover most of the image";
    EXPECT_LE(worst, 1);
    if (::testing::Test::HasFailure()) {
        test::writeEvidence("path_denoise_converged_raw", raw);
        test::writeEvidence("path_denoise_converged_denoised", denoised);
    }
}

TEST(PathDenoise, TheRowsStatisticsAreEachPixelsBitForBit) {
    // standardErrorRow and image() feed the denoiser; they must be standardError(x, y) and mean(x, y).
    for (const int spp : {1, 3}) {
        PathSettings s = settings(spp, 0);
        s.width = 37;
        s.height = 5;
        PathRender r(cornell(), s);
        r.addSamples(spp);
        PathSettings other = s;
        other.seed = 9;
        PathRender control(cornell(), other);
        control.addSamples(spp);
        const ImageF image = r.image();
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 37; ++x)
                for (int c = 0; c < 3; ++c) ASSERT_EQ(image.pixel(x, y)[c], r.mean(x, y)[c]) << x << "," << y;
        std::vector<float> row(3 * 37), controlRow(3 * 37);
        bool controlDiffers = false;
        for (int y = 0; y < 5; ++y) {
            r.standardErrorRow(y, row.data());
            control.standardErrorRow(y, controlRow.data());
            for (int x = 0; x < 37; ++x)
                for (int c = 0; c < 3; ++c) {
                    const size_t i = 3 * size_t(x) + size_t(c);
                    const float expected = r.standardError(x, y)[c];
                    ASSERT_EQ(row[i], expected) << spp << " spp, pixel " << x << "," << y;
                    controlDiffers = controlDiffers || controlRow[i] != row[i];
                }
        }
        // The negative control: another seed's errors differ, so equal bits mean something (with 3 samples).
        if (spp > 1) {
            EXPECT_TRUE(controlDiffers);
        }
    }
}

TEST(PathDenoise, TheFlagGivesTheDenoisedImageBesideTheRawOne) {
    PathSettings s = settings(4, 0);
    s.width = 32;
    s.height = 18;
    s.denoise = true;
    const PathOutput out = pathTraceImage(cornell(), s);
    ASSERT_EQ(out.raw.width, 32);
    EXPECT_EQ(out.passes.width, 32);
    EXPECT_EQ(out.variance.size(), size_t(32 * 18));
    EXPECT_NE(out.raw.rgba, out.color.rgba);
    s.denoise = false;
    const PathOutput plain = pathTraceImage(cornell(), s);
    EXPECT_EQ(plain.raw.width, 0);
    EXPECT_EQ(plain.color.rgba, out.raw.rgba) << "the raw estimate is the image without denoise";
}

}  // namespace
}  // namespace shadelab::trace
