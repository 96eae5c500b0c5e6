// The denoiser on images whose answer is known: a converged image comes back unchanged, a noisy step edge
// stays where it is and loses its noise, a pixel that is not finite stays and spreads nothing, and any
// thread count gives the same bytes. Each with a negative control that shows the check can fail.
#include "image/denoise.h"
#include "image/encode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace shadelab {
namespace {

// The same surface everywhere: the guides tell nothing apart, so only the colour's own noise can stop the
// filter.
SurfacePasses flatGuides(int w, int h) {
    SurfacePasses g(w, h);
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
        g.normal[3 * i + 2] = 1.0f;
        g.depth[i] = 5.0f;
        for (int c = 0; c < 3; ++c) g.albedo[3 * i + size_t(c)] = 0.5f;
    }
    return g;
}

// A deterministic standard normal number per index (Box-Muller over a 64-bit LCG).
float gaussian(uint64_t i) {
    auto u = [](uint64_t k) {
        k = k * 6364136223846793005ull + 1442695040888963407ull;
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdull;
        k ^= k >> 33;
        return (double(k >> 11) + 0.5) / 9007199254740992.0;
    };
    return float(std::sqrt(-2.0 * std::log(u(2 * i))) * std::cos(6.283185307179586 * u(2 * i + 1)));
}

void fill(ImageF& img, int x, int y, float v) {
    float* p = img.pixel(x, y);
    p[0] = p[1] = p[2] = v;
    p[3] = 1.0f;
}

int largestByteDifference(const ImageF& a, const ImageF& b) {
    uint64_t bad = 0;
    const Image8 ea = toImage8(a, Encoding::Srgb, {}, &bad), eb = toImage8(b, Encoding::Srgb, {}, &bad);
    int worst = 0;
    for (size_t i = 0; i < ea.data.size(); ++i) worst = std::max(worst, std::abs(int(ea.data[i]) - int(eb.data[i])));
    return worst;
}

// A smooth picture with shapes: a gradient, a disc and a ring.
ImageF converged(int w, int h) {
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float r = std::hypot(float(x - w / 2), float(y - h / 2));
            fill(img, x, y,
                 0.1f + 0.6f * float(x) / float(w) + (r < 10.0f ? 0.3f : 0.0f) +
                     (std::abs(r - 20.0f) < 1.5f ? 0.5f : 0.0f));
        }
    return img;
}

TEST(Denoise, AConvergedImageComesBackWithinOneStep) {
    const int w = 64, h = 48;
    const ImageF img = converged(w, h);
    const std::vector<float> none(size_t(w) * h, 0.0f);
    const ImageF out = denoise(img, none, flatGuides(w, h));
    EXPECT_LE(largestByteDifference(img, out), 1);
}

TEST(Denoise, NegativeControlTheSameImageCalledNoisyIsSmoothed) {
    const int w = 64, h = 48;
    const ImageF img = converged(w, h);
    const std::vector<float> noisy(size_t(w) * h, 0.05f);
    EXPECT_GT(largestByteDifference(img, denoise(img, noisy, flatGuides(w, h))), 1)
        << "with noise declared, the filter must change the image";
}

struct StepResult {
    double nearLeft = 0, nearRight = 0;  // mean of the columns beside the edge
    double rmse = 0;                     // against the noise-free step, all pixels
    bool ordered = true;                 // every column left of the edge below 0.5, right of it above
};

// Left half 0.2, right half 0.8, noise of standard deviation 0.08 (the filter is told so).
StepResult stepEdge(const DenoiseSettings& s, const SurfacePasses& guides) {
    const int w = 64, h = 32, edge = 32;
    const float sd = 0.08f;
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) fill(img, x, y, (x < edge ? 0.2f : 0.8f) + sd * gaussian(uint64_t(y * w + x)));
    const std::vector<float> var(size_t(w) * h, sd * sd);
    const ImageF out = denoise(img, var, guides, s);
    StepResult r;
    double se = 0.0;
    for (int x = 0; x < w; ++x) {
        double col = 0.0;
        for (int y = 0; y < h; ++y) {
            const double v = out.pixel(x, y)[1], truth = x < edge ? 0.2 : 0.8;
            col += v / h;
            se += (v - truth) * (v - truth);
        }
        if (x == edge - 1) r.nearLeft = col;
        if (x == edge) r.nearRight = col;
        if ((x < edge) != (col < 0.5)) r.ordered = false;
    }
    r.rmse = std::sqrt(se / (w * h));
    return r;
}

TEST(Denoise, ANoisyStepEdgeStaysWhereItIsAndLosesItsNoise) {
    const StepResult r = stepEdge({}, flatGuides(64, 32));
    std::printf("step edge: columns beside it %.3f | %.3f (0.2 | 0.8), rmse %.4f (noise 0.08)\n", r.nearLeft,
                r.nearRight, r.rmse);
    EXPECT_TRUE(r.ordered);
    EXPECT_NEAR(r.nearLeft, 0.2, 0.03);
    EXPECT_NEAR(r.nearRight, 0.8, 0.03);
    EXPECT_LT(r.rmse, 0.08 / 2.5);
}

TEST(Denoise, NegativeControlWithoutTheLuminanceStopTheEdgeBlurs) {
    DenoiseSettings s;
    s.sigmaLuminance = 1e6f;  // every difference passes for noise: a plain wavelet blur
    const StepResult r = stepEdge(s, flatGuides(64, 32));
    EXPECT_GT(std::abs(r.nearLeft - 0.2), 0.1) << "a blur must move the columns beside the edge";
}

TEST(Denoise, AnAlbedoEdgeInTheGuidesIsKeptEvenWhenTheColourStopIsOff) {
    SurfacePasses g = flatGuides(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 32; x < 64; ++x)
            for (int c = 0; c < 3; ++c) g.albedo[3 * (size_t(y) * 64 + size_t(x)) + size_t(c)] = 0.9f;
    DenoiseSettings s;
    s.sigmaLuminance = 1e6f;
    const StepResult r = stepEdge(s, g);
    EXPECT_NEAR(r.nearLeft, 0.2, 0.03);
    EXPECT_NEAR(r.nearRight, 0.8, 0.03);
}

// A noisy grey wall whose depth guide is `depth(x)`: the RMSE left after denoising (the truth is 0.5).
double wallResidual(float (*depth)(int x)) {
    const int w = 64, h = 64;
    SurfacePasses g = flatGuides(w, h);
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            g.depth[size_t(y) * w + size_t(x)] = depth(x);
            fill(img, x, y, 0.5f + 0.1f * gaussian(uint64_t(y) * w + uint64_t(x) + 777));
        }
    const ImageF out = denoise(img, std::vector<float>(size_t(w) * h, 0.01f), g);
    double se = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) se += std::pow(out.pixel(x, y)[1] - 0.5, 2.0);
    return std::sqrt(se / (w * h));
}

TEST(Denoise, AWallSeenAtAGrazingAngleIsSmoothedAsMuchAsOneFacingTheCamera) {
    // A plane's 1/z is affine in the image: from 1 to 10 units away across the image, seen edge-on as the
    // Cornell box's side walls are. The filter compares each tap with the plane through the pixel, so the
    // steep depth is no edge; comparing depths alone smoothed such walls along their depth far less than
    // across it, and left streaks.
    const double facing = wallResidual([](int) { return 5.0f; });
    const double grazing = wallResidual([](int x) { return 1.0f / (1.0f - 0.9f * float(x) / 63.0f); });
    // The negative control: the same wall as a staircase of strips 8 columns wide, each facing the camera, is
    // no plane: its depth jumps between strips, the filter keeps them apart and smooths only down each strip.
    const double stairs = wallResidual([](int x) { return 1.0f / (1.0f - 0.9f * float(x / 8 * 8) / 63.0f); });
    std::printf("noise left (of 0.1): facing %.4f, grazing %.4f, stairs %.4f\n", facing, grazing, stairs);
    EXPECT_LT(grazing, 1.15 * facing);
    EXPECT_GT(stairs, 1.5 * facing) << "the control: depth steps must be kept apart";
}

TEST(Denoise, ANonFinitePixelStaysAndSpreadsNothing) {
    const int w = 16, h = 16;
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) fill(img, x, y, 0.5f);
    img.pixel(8, 8)[0] = NAN;
    const std::vector<float> var(size_t(w) * h, 0.01f);
    const ImageF out = denoise(img, var, flatGuides(w, h));
    EXPECT_TRUE(std::isnan(out.pixel(8, 8)[0]));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (x != 8 || y != 8) {
                ASSERT_NEAR(out.pixel(x, y)[0], 0.5f, 1e-5f) << x << "," << y;
            }
}

TEST(Denoise, AnyThreadCountGivesTheSameBytes) {
    // Tall enough for one strip of rows per thread (image/denoise_kernel.h) up to three.
    const int w = 70, h = 200;
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) fill(img, x, y, 0.5f + 0.2f * gaussian(uint64_t(y * w + x)));
    const std::vector<float> var(size_t(w) * h, 0.04f);
    DenoiseSettings s;
    s.threads = 1;
    const ImageF one = denoise(img, var, flatGuides(w, h), s);
    for (const int threads : {2, 3, 7}) {
        s.threads = threads;
        EXPECT_EQ(one.rgba, denoise(img, var, flatGuides(w, h), s).rgba) << threads << " threads";
    }
    // The negative control: the images compared are not the input, nor all alike.
    EXPECT_NE(one.rgba, img.rgba);
}

TEST(Denoise, MismatchedSizesAndBadSettingsAreRefused) {
    ImageF img(8, 8);
    const std::vector<float> var(64, 0.0f);
    EXPECT_THROW(denoise(img, var, flatGuides(8, 7)), std::invalid_argument);
    EXPECT_THROW(denoise(img, std::vector<float>(63), flatGuides(8, 8)), std::invalid_argument);
    DenoiseSettings s;
    s.iterations = 0;
    EXPECT_THROW(denoise(img, var, flatGuides(8, 8), s), std::invalid_argument);
    s = {};
    s.sigmaDepth = NAN;
    EXPECT_THROW(denoise(img, var, flatGuides(8, 8), s), std::invalid_argument);
}

}  // namespace
}  // namespace shadelab
