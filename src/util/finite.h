// Where a number read from a file (a double, as JSON and glTF give it) becomes the float or int the renderers
// use. A double is finite as a float only when it is finite and within ±FLT_MAX: 1e308 passes std::isfinite
// as a double, and narrowing it (undefined behaviour in C++) gives infinity on x86. So every check is made
// here, on the value in the type it is used in, and the narrowing happens only once the value is in range.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>

namespace shadelab {

// x as a float, or nothing when that float would not be finite (NaN, ±inf, or rounding beyond ±FLT_MAX). A double
// just above FLT_MAX, below FLT_MAX + half its ulp (2^103), rounds to FLT_MAX: the shortest text of FLT_MAX that
// shadelab saves, 3.4028235e+38, reads back as such a double, and must load again.
inline std::optional<float> finiteFloat(double x) {
    const double a = std::fabs(x);
    if (a <= double(FLT_MAX)) return float(x);
    if (a < double(FLT_MAX) + std::ldexp(1.0, 103)) return x > 0.0 ? FLT_MAX : -FLT_MAX;
    return std::nullopt;
}

// x clamped to [lo, hi] (in double, before narrowing), or `fallback` when x is NaN or infinite.
inline float finiteClamp(double x, float lo, float hi, float fallback) {
    if (!std::isfinite(x)) return fallback;
    return float(std::clamp(x, double(lo), double(hi)));
}

// x as an int when it is a whole number in [lo, hi], else nothing (int(1e300) is undefined behaviour).
inline std::optional<int> wholeNumber(double x, int lo, int hi) {
    if (!(x >= double(lo) && x <= double(hi)) || x != std::floor(x)) return std::nullopt;
    return int(x);
}

}  // namespace shadelab
