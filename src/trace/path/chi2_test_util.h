// Pearson's χ² goodness-of-fit test of a direction sampler against its claimed density, as pbrt-v4's
// sampling tests do: the sphere is cut into cos θ × φ bins, the expected count of each bin is the density
// integrated over it (a fine midpoint rule), bins expecting fewer than 5 samples are pooled, and the
// statistic's p-value comes from the Wilson–Hilferty normal approximation of the χ² distribution. Test-only.
#pragma once

#include "trace/path/sample_rng.h"
#include "trace/path/warp.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::trace::test {

// What the lobes' χ² tests draw and hold to: 400,000 samples each, and a significance of 1e-3 (a false alarm over
// a file's tests stays rare).
inline constexpr int kChi2Samples = 400000;
inline constexpr double kChi2Alpha = 1e-3;

// Sample k's three uniform numbers from the path tracer's own generator, one stream per test file (`seed`).
inline glm::vec3 sampleNumbers(int k, uint32_t seed) {
    SampleRng rng;
    rng.pixel = uint32_t(k);
    rng.seed = seed;
    return glm::vec3(rng.draw(0, 0));
}

struct Chi2Result {
    double statistic = 0.0;
    int dof = 0;
    double pValue = 0.0;
    double observedOutside = 0.0;  // samples in bins the density says are empty (must be none)
    std::string summary() const {
        char buf[160];
        std::snprintf(buf, sizeof buf, "chi2 = %.1f with %d dof, p = %.3g, %g samples where the pdf is 0", statistic,
                      dof, pValue, observedOutside);
        return buf;
    }
};

// `sample(k)` draws the k-th direction (nullopt: the sampler absorbed it); `pdf(w)` is the claimed density
// per solid angle. Bins: `thetaBins` in cos θ ∈ [−1, 1] × `phiBins` in φ, each integrated on a sub × sub grid.
inline Chi2Result chi2Directions(const std::function<std::optional<glm::vec3>(int)>& sample,
                                 const std::function<float(const glm::vec3&)>& pdf, int count, int thetaBins = 20,
                                 int phiBins = 40, int sub = 24) {
    const int bins = thetaBins * phiBins;
    std::vector<double> observed(size_t(bins), 0.0), expected(size_t(bins), 0.0);
    auto binOf = [&](const glm::vec3& w) {
        const float c = std::clamp(w.z, -1.0f, 1.0f);
        float phi = std::atan2(w.y, w.x);
        if (phi < 0.0f) phi += 2.0f * kPi;
        const int i = std::clamp(int((c + 1.0f) * 0.5f * float(thetaBins)), 0, thetaBins - 1);
        const int j = std::clamp(int(phi / (2.0f * kPi) * float(phiBins)), 0, phiBins - 1);
        return i * phiBins + j;
    };
    for (int k = 0; k < count; ++k)
        if (const std::optional<glm::vec3> w = sample(k)) observed[size_t(binOf(glm::normalize(*w)))] += 1.0;
    // In cos θ and φ the solid angle is uniform: dω = d(cos θ) dφ.
    const double dc = 2.0 / thetaBins, dphi = 2.0 * kPi / phiBins;
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j) {
            double sum = 0.0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    const double c = -1.0 + (i + (a + 0.5) / sub) * dc, phi = (j + (b + 0.5) / sub) * dphi;
                    const double st = std::sqrt(std::max(0.0, 1.0 - c * c));
                    sum += pdf(glm::vec3(float(st * std::cos(phi)), float(st * std::sin(phi)), float(c)));
                }
            expected[size_t(i * phiBins + j)] = sum / (sub * sub) * dc * dphi * count;
        }
    Chi2Result r;
    double pooledObs = 0.0, pooledExp = 0.0;
    for (int b = 0; b < bins; ++b) {
        if (expected[size_t(b)] == 0.0) {
            r.observedOutside += observed[size_t(b)];
            continue;
        }
        if (expected[size_t(b)] < 5.0) {
            pooledObs += observed[size_t(b)];
            pooledExp += expected[size_t(b)];
            continue;
        }
        const double d = observed[size_t(b)] - expected[size_t(b)];
        r.statistic += d * d / expected[size_t(b)];
        ++r.dof;
    }
    if (pooledExp >= 5.0) {
        const double d = pooledObs - pooledExp;
        r.statistic += d * d / pooledExp;
        ++r.dof;
    }
    // Absorbed samples (nullopt) carry no direction; the counted bins then do not sum to `count`, so one
    // degree of freedom is not lost to the total.
    const double k = std::max(1, r.dof);
    const double z = (std::cbrt(r.statistic / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
    r.pValue = 0.5 * std::erfc(z / std::sqrt(2.0));
    return r;
}

// A scattering mixture's sample() (sample k drawing sampleNumbers(k, seed)) against `claimed`'s pdf() over the
// upper hemisphere (the whole sphere for a mixture that also transmits, `sphere`), kChi2Samples samples, each bin's
// expected count integrated on `sub` × `sub` cells: the lobe tests' χ² of a whole BSDF (PathBsdf), `claimed` the
// same BSDF or a wrong one for a negative control.
template <class Bsdf>
Chi2Result chi2OfMixture(const Bsdf& sampled, const Bsdf& claimed, uint32_t seed, int sub = 24, bool sphere = false) {
    return chi2Directions(
        [&](int k) -> std::optional<glm::vec3> {
            const auto b = sampled.sample(sampleNumbers(k, seed));
            return b ? std::optional<glm::vec3>(b->wi) : std::nullopt;
        },
        [&](const glm::vec3& w) { return sphere || w.z > 0.0f ? claimed.pdf(w) : 0.0f; }, kChi2Samples, 20, 40, sub);
}

}  // namespace shadelab::trace::test
