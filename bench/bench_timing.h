// The benchmarks' shared timing helpers: milliseconds since a steady-clock instant, and the median of a run's
// samples (the upper middle one for an even count; 0 for none). Bench-only; not part of the library.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace shadelab::bench {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace shadelab::bench
