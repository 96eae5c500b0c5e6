// The benchmarks' shared timing helpers: milliseconds since a steady-clock instant, the process's CPU time (all
// its threads), and the median of a run's samples (the upper middle one for an even count; 0 for none).
// Bench-only; not part of the library.
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace shadelab::bench {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU milliseconds the process has used, every thread's: on a machine that others load, the time a run would
// take on cores of its own is nearer this (over the threads) than the wall clock.
inline double cpuMs() { return 1000.0 * double(std::clock()) / CLOCKS_PER_SEC; }

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace shadelab::bench
