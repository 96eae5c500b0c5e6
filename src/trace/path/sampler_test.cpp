// The path tracer's samplers (sample_rng.h, owen_sobol.h; design.md §8): the Sobol sampler's stratification
// (the first 2^k samples of each group are a (0,k,2)-net in its first two numbers and one point per 2^-k
// interval in each of the four), its uniformity and the decorrelation of its groups (χ²), images that do not
// depend on threads or passes, and less error than independent numbers on the Cornell box at 16 spp. Each
// check has a negative control: independent numbers are not stratified, one shared index shuffle correlates
// two groups, and two independent renders do not differ in error as the samplers do.
#include "scene/scene_load.h"
#include "trace/path/owen_sobol.h"
#include "trace/path/path_render.h"
#include "trace/path/sample_rng.h"
#include "trace/trace_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

namespace shadelab::trace {
namespace {

// Whether the points are one per cell of every grid of 2^a × 2^(k−a) cells (a = 0..k) in (x, y), i.e. a
// (0,k,2)-net in base 2, and one per 2^-k interval in each of `dims` numbers.
bool stratified(const std::vector<glm::vec4>& points, int k, int dims) {
    const size_t n = size_t(1) << k;
    if (points.size() != n) return false;
    std::vector<int> count(n);
    for (int a = 0; a <= k; ++a) {
        std::fill(count.begin(), count.end(), 0);
        for (const glm::vec4& p : points) {
            const size_t cx = size_t(std::ldexp(p.x, a)), cy = size_t(std::ldexp(p.y, k - a));
            if (++count[(cy << a) | cx] > 1) return false;
        }
    }
    for (int d = 0; d < dims; ++d) {
        std::fill(count.begin(), count.end(), 0);
        for (const glm::vec4& p : points)
            if (++count[size_t(std::ldexp(p[d], k))] > 1) return false;
    }
    return true;
}

std::vector<glm::vec4> firstSamples(PathSampler sampler, uint32_t pixel, uint32_t bounce, uint32_t group, int k) {
    SampleRng rng;
    rng.sampler = sampler;
    rng.pixel = pixel;
    std::vector<glm::vec4> out;
    for (uint32_t i = 0; i < (1u << k); ++i) {
        rng.sample = i;
        out.push_back(rng.draw(bounce, group));
    }
    return out;
}

struct Use {
    uint32_t bounce, group;
};
// The camera jitter's group (path_render.cpp), a vertex's BSDF, emitter and first blend groups, a deep one.
const Use kUses[] = {{0, 0xFFu}, {0, 0}, {0, 1}, {0, 2}, {3, 0}, {7, 1}};
const uint32_t kPixels[] = {0, 7, 12345, 921599};

TEST(PathSampler, SobolSamplesAreStratifiedInEveryGroup) {
    for (uint32_t pixel : kPixels)
        for (const Use& u : kUses)
            for (int k = 0; k <= 12; ++k)
                EXPECT_TRUE(stratified(firstSamples(PathSampler::Sobol, pixel, u.bounce, u.group, k), k, 4))
                    << "pixel " << pixel << ", bounce " << u.bounce << ", group " << u.group << ", 2^" << k;
    // Unscrambled, the derived direction numbers make the same net (Sobol's first two dimensions are a
    // (0,2)-sequence; each dimension alone a (0,1)-sequence).
    for (int k = 0; k <= 12; ++k) {
        std::vector<glm::vec4> points;
        for (uint32_t i = 0; i < (1u << k); ++i) points.push_back(glm::vec4(sobolPoint(i) >> 8u) / 16777216.0f);
        EXPECT_TRUE(stratified(points, k, 4)) << "unscrambled Sobol, 2^" << k;
    }
    // Direction numbers of the second dimension: Pascal's triangle mod 2 (v_2 = 0.11b, v_3 = 0.101b, ...).
    EXPECT_EQ(sobol_detail::directions(1)[1], 0xC0000000u);
    EXPECT_EQ(sobol_detail::directions(1)[3], 0xF0000000u);
    EXPECT_EQ(sobol_detail::directions(1)[4], 0x88000000u);
}

TEST(PathSampler, NegativeControlIndependentSamplesAreNotStratified) {
    int stratifiedSets = 0, sets = 0;
    for (uint32_t pixel : kPixels)
        for (const Use& u : kUses) {
            ++sets;
            stratifiedSets += stratified(firstSamples(PathSampler::Independent, pixel, u.bounce, u.group, 6), 6, 4);
        }
    EXPECT_EQ(stratifiedSets, 0) << "of " << sets << " sets of 64 independent samples";
}

// Pearson's χ² of counts against a uniform expectation, its p-value by Wilson–Hilferty (as chi2_test_util.h).
double uniformPValue(const std::vector<int>& counts) {
    double total = 0.0;
    for (int c : counts) total += c;
    const double expected = total / double(counts.size());
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    const double k = double(counts.size() - 1);
    const double z = (std::cbrt(chi2 / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

constexpr double kAlpha = 1e-3;

TEST(PathSampler, SobolNumbersAreUniformOverPixelsAndGroupsAreUncorrelated) {
    // Each number of a group over 2^16 pixels (one sample each): uniform, 64 bins.
    for (const Use& u : kUses)
        for (uint32_t sample : {0u, 5u, 1000u})
            for (int d = 0; d < 4; ++d) {
                std::vector<int> bins(64);
                SampleRng rng;
                rng.sample = sample;
                for (uint32_t p = 0; p < 65536; ++p) {
                    rng.pixel = p;
                    ++bins[size_t(rng.draw(u.bounce, u.group)[d] * 64.0f)];
                }
                EXPECT_GT(uniformPValue(bins), kAlpha) << "group " << u.group << ", sample " << sample << ", d" << d;
            }
    // Two groups' first numbers over one pixel's 4096 samples, 16 × 16 bins: independent of each other.
    auto pairCounts = [](const std::function<glm::vec2(uint32_t)>& pair) {
        std::vector<int> bins(256);
        for (uint32_t i = 0; i < 4096; ++i) {
            const glm::vec2 q = pair(i);
            ++bins[size_t(q.y * 16.0f) * 16 + size_t(q.x * 16.0f)];
        }
        return uniformPValue(bins);
    };
    SampleRng rng;
    rng.pixel = 77;
    for (const auto& [a, b] : {std::pair<Use, Use>{{0, 0}, {0, 1}}, {{0, 0xFFu}, {0, 0}}, {{0, 0}, {1, 0}}}) {
        const double p = pairCounts([&](uint32_t i) {
            SampleRng r = rng;
            r.sample = i;
            return glm::vec2(r.draw(a.bounce, a.group).x, r.draw(b.bounce, b.group).x);
        });
        EXPECT_GT(p, kAlpha) << "groups " << a.bounce << "/" << a.group << " and " << b.bounce << "/" << b.group;
    }
    // Negative control: without its own index shuffle a second group is the same sequence scrambled
    // otherwise, and an Owen scramble keeps every 1/16 interval together: the pairs fill 16 of 256 bins.
    const double shared = pairCounts([](uint32_t i) {
        return glm::vec2(owenSobol4(i, 99u, glm::uvec4(1, 2, 3, 4)).x >> 8,
                         owenSobol4(i, 99u, glm::uvec4(5, 6, 7, 8)).x >> 8) /
               16777216.0f;
    });
    EXPECT_LT(shared, 1e-9);
}

bool sameBytes(const ImageF& a, const ImageF& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

std::shared_ptr<const TraceScene> cornell() {
    static const std::shared_ptr<const TraceScene> scene =
        std::make_shared<const TraceScene>(loadScene(SHADELAB_SOURCE_DIR "/assets/scenes/cornell.json"));
    return scene;
}

PathSettings cornellSettings(PathSampler sampler, int spp, uint32_t seed = 0) {
    PathSettings s;
    s.width = 32;
    s.height = 24;
    s.spp = spp;
    s.threads = 2;
    s.sampler = sampler;
    s.seed = seed;
    return s;
}

ImageF renderImage(const PathSettings& s) {
    PathRender r(cornell(), s);
    r.addSamples(s.spp);
    return r.image();
}

TEST(PathSampler, SobolImagesAreTheSameForAnyThreadCountAndPassSplit) {
    for (PathSampler sampler : {PathSampler::Sobol, PathSampler::Independent}) {
        PathSettings s = cornellSettings(sampler, 12);
        s.threads = 1;
        const ImageF one = renderImage(s);
        s.threads = 3;
        s.tileSize = 5;
        EXPECT_TRUE(sameBytes(one, renderImage(s))) << toString(sampler) << ": 1 and 3 threads";
        PathRender progressive(cornell(), s);
        progressive.addSamples(5);
        progressive.addSamples(7);
        EXPECT_TRUE(sameBytes(one, progressive.image())) << toString(sampler) << ": 5 + 7 samples";
    }
    // Negative control: the two samplers' images differ.
    EXPECT_FALSE(sameBytes(renderImage(cornellSettings(PathSampler::Sobol, 12)),
                           renderImage(cornellSettings(PathSampler::Independent, 12))));
}

double rmse(const ImageF& a, const ImageF& b) {
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c]);
                sum += d * d;
            }
    return std::sqrt(sum / (3.0 * a.width * a.height));
}

// The Cornell box at 16 spp against a 2048-spp reference: the mean RMSE (linear radiance) over eight seeds of
// each sampler. Measured (Release, 2 cores, 4 s): sobol 0.66x independent; a second set of independent seeds
// 0.98x the first. The bound sits between them.
constexpr double kRatio = 0.8;
constexpr int kSeeds = 8;

TEST(PathSampler, SobolHasLessErrorThanIndependentAtSixteenSamples) {
    const ImageF reference = renderImage(cornellSettings(PathSampler::Sobol, 2048, 1000));
    double sobol = 0.0, independent = 0.0, independentB = 0.0;
    ImageF sobolImage, independentImage;
    for (uint32_t seed = 0; seed < uint32_t(kSeeds); ++seed) {
        sobolImage = renderImage(cornellSettings(PathSampler::Sobol, 16, seed));
        independentImage = renderImage(cornellSettings(PathSampler::Independent, 16, seed));
        sobol += rmse(sobolImage, reference) / kSeeds;
        independent += rmse(independentImage, reference) / kSeeds;
        independentB +=
            rmse(renderImage(cornellSettings(PathSampler::Independent, 16, seed + 100)), reference) / kSeeds;
    }
    std::printf(
        "Cornell 32x24, 16 spp, RMSE against 2048 spp: sobol %.5f, independent %.5f (ratio %.3f); "
        "independent, other seeds %.5f\n",
        sobol, independent, sobol / independent, independentB);
    ::testing::Test::RecordProperty("rmse_sobol", std::to_string(sobol));
    ::testing::Test::RecordProperty("rmse_independent", std::to_string(independent));
    EXPECT_LT(sobol, kRatio * independent);
    // Negative control: two sets of independent renders are not told apart by the same bound.
    EXPECT_GE(independentB, kRatio * independent);
    if (::testing::Test::HasFailure()) {
        test::writeEvidence("sampler_reference", reference);
        test::writeEvidence("sampler_sobol_16spp", sobolImage);
        test::writeEvidence("sampler_independent_16spp", independentImage);
    }
}

}  // namespace
}  // namespace shadelab::trace
