// The benchmarks' image error measures, written once: the plain RMSE, and the relative RMSE against a
// reference with the lamp left out, optionally corrected for the reference's own noise. Bench-only; the unit
// tests keep their own copies (they must not depend on bench/).
#pragma once

#include "image/image.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab::bench {

// sqrt of the mean of |a − b|² over every pixel and RGB channel (linear radiance).
inline double rmse(const ImageF& a, const ImageF& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.rgba.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgba[i + c]) - double(b.rgba[i + c]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * double(a.width) * double(a.height)));
}

// The relative RMSE, sqrt(Σ |a − r|² / Σ |r|²) over RGB: the error relative to the reference's own level.
// Pixels whose red channel is above 1 in the reference (the lamp, which is not noise and would dominate both
// sums) are left out, as path_denoise_test does.
//
// `refVariance`, when given (3 per pixel, RGB: the variance of the reference's estimate of each pixel's
// mean, e.g. its sample variance over its sample count), removes the reference's own noise from both sums.
// With r = μ + ε independent of a, E|a − r|² = E|a − μ|² + Var(r) and E|r|² = |μ|² + Var(r), so
//     Σ (|a − r|² − Var(r)) / Σ (|r|² − Var(r))
// estimates the squared relative error against the converged image μ without bias, from a reference of far
// fewer samples than a "noise-free" one needs. Only sums over many pixels are corrected (a single pixel's
// term may go negative); the ratio is clamped at 0.
inline double relativeRmse(const ImageF& a, const ImageF& ref, const std::vector<float>* refVariance = nullptr) {
    double num = 0.0, den = 0.0;
    for (size_t i = 0, p = 0; i < a.rgba.size(); i += 4, ++p) {
        if (ref.rgba[i] > 1.0f) continue;
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgba[i + c]) - double(ref.rgba[i + c]);
            const double v = refVariance ? double((*refVariance)[3 * p + c]) : 0.0;
            num += d * d - v;
            den += double(ref.rgba[i + c]) * ref.rgba[i + c] - v;
        }
    }
    return std::sqrt(std::max(0.0, num / den));
}

}  // namespace shadelab::bench
