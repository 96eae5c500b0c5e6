// The denoiser against the filter as image/denoise.h writes it, computed here the plain way (whole images per
// pass, double precision, std::exp): every pixel of every build (denoise_builds.h) agrees with it, on an
// image tall enough that several strips of rows (denoise_kernel.h) meet inside it, with non-finite pixels,
// a lamp far above 1 and edges in every guide. Each comparison has a negative control that must fail.
#include "image/denoise.h"
#include "image/denoise_builds.h"
#include "image/exr.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace shadelab {
namespace {

struct Input {
    ImageF color;
    std::vector<float> variance;
    SurfacePasses guides;
};

// A deterministic uniform number in [0, 1) per index.
double uniform(uint64_t k) {
    k = k * 6364136223846793005ull + 1442695040888963407ull;
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdull;
    k ^= k >> 33;
    return double(k >> 11) / 9007199254740992.0;
}

// Four regions (a normal, an albedo and a depth each, a depth ramp within) under noise whose variance varies
// from pixel to pixel, a column of lamp pixels at 30, a few pixels not finite, and a converged patch.
Input scene(int w, int h) {
    Input in{ImageF(w, h), std::vector<float>(size_t(w) * size_t(h)), SurfacePasses(w, h)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            const int region = (x / 13 + y / 29) % 4;
            const bool converged = x < 8 && y < 8;
            const double sd = converged ? 0.0 : 0.05 + 0.1 * uniform(3 * i);
            for (int c = 0; c < 3; ++c)
                in.color.rgba[4 * i + size_t(c)] =
                    float((0.15 + 0.2 * region + 0.05 * c) * (1.0 + sd * (2.0 * uniform(3 * i + 1 + c) - 1.0)));
            if (x == w / 2) in.color.rgba[4 * i] = in.color.rgba[4 * i + 1] = in.color.rgba[4 * i + 2] = 30.0f;
            in.color.rgba[4 * i + 3] = 1.0f;
            in.variance[i] = float(sd * sd * 0.3);
            in.guides.normal[3 * i + size_t(region % 3)] = region == 3 ? -1.0f : 1.0f;
            in.guides.depth[i] = float(2.0 + region + 0.02 * x + 0.01 * y);
            for (int c = 0; c < 3; ++c) in.guides.albedo[3 * i + size_t(c)] = float(0.1 + 0.2 * region + 0.1 * c);
        }
    in.color.rgba[4 * (size_t(17) * size_t(w) + 5)] = NAN;
    in.color.rgba[4 * (size_t(h - 1) * size_t(w) + size_t(w - 1)) + 1] = INFINITY;
    in.variance[size_t(h / 2) * size_t(w) + 3] = NAN;
    return in;
}

// The filter as denoise.h states it, pass k at step stepOf(k).
ImageF reference(const Input& in, const DenoiseSettings& s, const std::function<int(int)>& stepOf) {
    const int w = in.color.width, h = in.color.height;
    const size_t n = size_t(w) * size_t(h);
    const double kLum[3] = {0.2126, 0.7152, 0.0722}, kB3[3] = {0.25, 0.5, 0.25};
    std::vector<double> c(4 * n), slope(n);
    std::vector<bool> finite(n);
    const auto at = [w](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
    const auto lum = [&](const std::vector<double>& v, size_t i) {
        return kLum[0] * v[4 * i] + kLum[1] * v[4 * i + 1] + kLum[2] * v[4 * i + 2];
    };
    for (size_t i = 0; i < n; ++i) {
        const float* p = &in.color.rgba[4 * i];
        finite[i] = std::isfinite(p[0] + p[1] + p[2]) && std::isfinite(in.variance[i]);
        for (int ch = 0; ch < 3; ++ch) c[4 * i + size_t(ch)] = finite[i] ? p[ch] : 0.0;
        c[4 * i + 3] = finite[i] && in.variance[i] > 1e-20f ? in.variance[i] : 0.0;
    }
    // The depth guide as 1/z (0 on the background) and its gradient along x and y: the one-sided difference
    // of smaller magnitude, 0 without a neighbour.
    const auto inverse = [&](int x, int y) {
        const double z = in.guides.depth[at(x, y)];
        return z > 0.0 ? 1.0 / z : 0.0;
    };
    std::vector<double> gradient[2] = {std::vector<double>(n), std::vector<double>(n)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int axis = 0; axis < 2; ++axis) {
                double best = INFINITY;
                for (int sgn : {-1, 1}) {
                    const int qx = x + (axis == 0 ? sgn : 0), qy = y + (axis == 1 ? sgn : 0);
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const double d = sgn * (inverse(qx, qy) - inverse(x, y));
                    if (std::abs(d) < std::abs(best)) best = d;
                }
                gradient[axis][at(x, y)] = std::isfinite(best) ? best : 0.0;
            }
    for (size_t i = 0; i < n; ++i) slope[i] = std::max(std::abs(gradient[0][i]), std::abs(gradient[1][i]));
    // The first pass's luminance: the 3x3 B-spline mean of the finite pixels inside the image.
    std::vector<double> prefiltered(n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0.0, weight = 0.0;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    if (x + i >= 0 && y + j >= 0 && x + i < w && y + j < h && finite[at(x + i, y + j)]) {
                        sum += kB3[i + 1] * kB3[j + 1] * lum(c, at(x + i, y + j));
                        weight += kB3[i + 1] * kB3[j + 1];
                    }
            prefiltered[at(x, y)] = weight > 0.0 ? sum / weight : 0.0;
        }
    for (int k = 0; k < s.iterations; ++k) {
        const int step = stepOf(k);
        std::vector<double> next = c;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t p = at(x, y);
                if (!finite[p]) continue;
                double blur = 0.0, blurWeight = 0.0;
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i)
                        if (x + i >= 0 && y + j >= 0 && x + i < w && y + j < h) {
                            blur += kB3[i + 1] * kB3[j + 1] * c[4 * at(x + i, y + j) + 3];
                            blurWeight += kB3[i + 1] * kB3[j + 1];
                        }
                // The first pass stops at the prefiltered luminance, whose noise is (3/8) of a pixel's.
                const bool first = step == 1;
                const double invL = 1.0 / (s.sigmaLuminance * (first ? 0.375 : 1.0) *
                                               std::sqrt(std::max(0.0, std::min(blur / blurWeight, c[4 * p + 3]))) +
                                           1e-6);
                const auto luminance = [&](size_t i) { return first ? prefiltered[i] : lum(c, i); };
                const double z = inverse(x, y);
                const double invZ = 1.0 / (s.sigmaDepth * slope[p] * step + 1e-3 * std::abs(z) + 1e-6);
                double sum[4] = {0.0, 0.0, 0.0, 0.0}, wsum = 0.0;
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i) {
                        const int qx = x + i * step, qy = y + j * step;
                        if (qx < 0 || qy < 0 || qx >= w || qy >= h || !finite[at(qx, qy)]) continue;
                        const size_t q = at(qx, qy);
                        double e = 0.0;
                        if (i != 0 || j != 0) {
                            double dot = 0.0, albedo = 0.0;
                            for (int a = 0; a < 3; ++a) {
                                dot +=
                                    double(in.guides.normal[3 * p + size_t(a)]) * in.guides.normal[3 * q + size_t(a)];
                                albedo += std::abs(double(in.guides.albedo[3 * p + size_t(a)]) -
                                                   in.guides.albedo[3 * q + size_t(a)]);
                            }
                            // Depth: the tap against the plane through the pixel, 1/z being affine over a plane.
                            const double plane = z + gradient[0][p] * i * step + gradient[1][p] * j * step;
                            e = std::abs(luminance(p) - luminance(q)) * invL +
                                s.sigmaNormal * std::max(0.0, 1.0 - dot) +
                                std::abs(plane - inverse(qx, qy)) * invZ / std::sqrt(double(i * i + j * j)) +
                                albedo / s.sigmaAlbedo;
                        }
                        const double weight = kB3[i + 1] * kB3[j + 1] * (e < 16.0 ? std::exp(-e) : 0.0);
                        wsum += weight;
                        for (int ch = 0; ch < 3; ++ch) sum[ch] += weight * c[4 * q + size_t(ch)];
                        sum[3] += weight * weight * c[4 * q + 3];
                    }
                for (int ch = 0; ch < 3; ++ch) next[4 * p + size_t(ch)] = sum[ch] / wsum;
                const double v = sum[3] / (wsum * wsum);
                next[4 * p + 3] = v > 1e-20 ? v : 0.0;
            }
        c = std::move(next);
    }
    ImageF out = in.color;
    for (size_t i = 0; i < n; ++i) {
        if (!finite[i]) continue;
        for (int ch = 0; ch < 3; ++ch) out.rgba[4 * i + size_t(ch)] = float(c[4 * i + size_t(ch)]);
    }
    return out;
}

// The largest |a − b| / (1 + |b|) over every channel; non-finite values must be the same in both.
double largestDifference(const ImageF& a, const ImageF& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        const float x = a.rgba[i], y = b.rgba[i];
        if (!std::isfinite(x) || !std::isfinite(y)) {
            const bool same = std::isnan(x) ? std::isnan(y) : x == y;
            if (!same) return INFINITY;
            continue;
        }
        worst = std::max(worst, std::abs(double(x) - y) / (1.0 + std::abs(double(y))));
    }
    return worst;
}

// A failing case's evidence: build/test-output/image_test/<name>.exr, path printed.
void writeEvidence(const std::string& name, const ImageF& image) {
    const std::filesystem::path dir(SHADELAB_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / (name + ".exr")).string();
    writeExr(path, exrFromImage(image), ExrPrecision::Float);
    std::printf("evidence: %s\n", path.c_str());
}

// The weights' e^-x is within 8e-5 of std::exp (denoise_lanes.h), which moves the result by about 1e-5.
constexpr double kTolerance = 5e-5;

TEST(DenoiseReference, EveryBuildIsTheFilterAsWrittenOnEveryPixel) {
    const Input in = scene(45, 203);
    for (const int iterations : {1, 3, 5, 8}) {
        DenoiseSettings s;
        s.iterations = iterations;
        const ImageF expected = reference(in, s, [](int k) { return 1 << k; });
        for (const denoise_detail::DenoiseIsa isa : denoise_detail::denoiseIsas())
            for (const int threads : {1, 3}) {
                const ImageF got = denoise_detail::denoiseWith(isa, in.color, in.variance, in.guides, s, threads);
                const double d = largestDifference(got, expected);
                std::printf("iterations %d, build %d, %d threads: largest difference %.2e\n", iterations, int(isa),
                            threads, d);
                EXPECT_LE(d, kTolerance) << "iterations " << iterations << ", build " << int(isa) << ", " << threads
                                         << " threads";
                if (d > kTolerance) {
                    writeEvidence("reference_expected", expected);
                    writeEvidence("reference_got", got);
                }
            }
    }
}

TEST(DenoiseReference, NegativeControlAFilterWhoseLastPassRepeatsAStepDiffers) {
    const Input in = scene(45, 203);
    const ImageF wrong = reference(in, {}, [](int k) { return 1 << std::min(k, 3); });
    const double d = largestDifference(denoise(in.color, in.variance, in.guides), wrong);
    std::printf("against a last pass at step 8: %.2e\n", d);
    EXPECT_GT(d, 10 * kTolerance) << "the comparison must see a wrong step";
}

// FMA rounds a multiply and an add once: the AVX2 and AVX-512 builds differ from the baseline by that alone.
constexpr double kBuildTolerance = 2e-5;

TEST(DenoiseReference, TheBuildsAgreeWithEachOtherWithinRounding) {
    const Input in = scene(45, 203);
    const std::vector<denoise_detail::DenoiseIsa> isas = denoise_detail::denoiseIsas();
    const ImageF baseline = denoise_detail::denoiseWith(isas.front(), in.color, in.variance, in.guides, {}, 2);
    std::printf("%zu builds on this CPU\n", isas.size());
    for (const denoise_detail::DenoiseIsa isa : isas) {
        const double d =
            largestDifference(denoise_detail::denoiseWith(isa, in.color, in.variance, in.guides, {}, 2), baseline);
        std::printf("build %d against the baseline: %.2e\n", int(isa), d);
        EXPECT_LE(d, kBuildTolerance) << "build " << int(isa);
    }
    // The negative control: a 5 % wider luminance stop is a difference the comparison sees.
    DenoiseSettings wider;
    wider.sigmaLuminance *= 1.05f;
    const double d = largestDifference(denoise(in.color, in.variance, in.guides, wider), baseline);
    std::printf("a 5 %% wider luminance stop: %.2e\n", d);
    EXPECT_GT(d, 5 * kBuildTolerance);
}

}  // namespace
}  // namespace shadelab
