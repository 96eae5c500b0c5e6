// Specular lobes and the half-maximum matching rule between Phong and Blinn-Phong exponents.
#include "app/specular_lobe.h"

#include "shading/lighting.h"

#include <algorithm>
#include <cmath>

namespace shadelab::app {
namespace {

constexpr double kLn2 = 0.69314718055994531;
constexpr double kHalfPi = 1.5707963267948966;

double angleAt(int i, int count, float maxDegrees) {
    return count > 1 ? kHalfPi * double(maxDegrees) / 90.0 * double(i) / double(count - 1) : 0.0;
}

}  // namespace

float equivalentBlinnExponent(float s) {
    if (!(s > 0.0f)) return 0.0f;
    // cos(a/2) = sqrt((1 + cos a) / 2), with cos a = 2^(-1/s) at Phong's half maximum.
    const double c = std::exp2(-1.0 / double(s));
    return float(2.0 * kLn2 / -std::log(0.5 * (1.0 + c)));
}

float equivalentPhongExponent(float blinnExponent) {
    if (!(blinnExponent > 2.0f)) return 0.0f;
    // Solve (1 + c) / 2 = 2^(-2/s') for c = 2^(-1/s).
    const double c = 2.0 * std::exp2(-2.0 / double(blinnExponent)) - 1.0;
    return float(-kLn2 / std::log(c));
}

std::vector<float> phongLobe(float s, int count, float maxDegrees) {
    std::vector<float> v(size_t(std::max(count, 0)));
    for (int i = 0; i < count; ++i)
        v[size_t(i)] = shading::shininessPow(float(std::cos(angleAt(i, count, maxDegrees))), s);
    return v;
}

std::vector<float> blinnLobe(float blinnExponent, int count, float maxDegrees) {
    std::vector<float> v(size_t(std::max(count, 0)));
    for (int i = 0; i < count; ++i)
        v[size_t(i)] = shading::shininessPow(float(std::cos(0.5 * angleAt(i, count, maxDegrees))), blinnExponent);
    return v;
}

float lobeRmsDifference(float s, float blinnExponent, int count) {
    const std::vector<float> a = phongLobe(s, count), b = blinnLobe(blinnExponent, count);
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) sum += double(a[i] - b[i]) * double(a[i] - b[i]);
    return a.empty() ? 0.0f : float(std::sqrt(sum / double(a.size())));
}

}  // namespace shadelab::app
