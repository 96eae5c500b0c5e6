// StageTimer: wall-clock time per named stage of a command, for --timings and the benchmarks.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace shadelab::cli {

class StageTimer {
public:
    using Clock = std::chrono::steady_clock;
    // Ends the current stage (which began at the last call, or at construction).
    void stage(std::string name) {
        Clock::time_point now = Clock::now();
        stages_.emplace_back(std::move(name), std::chrono::duration<double, std::milli>(now - last_).count());
        last_ = now;
    }
    void print(std::FILE* out) const {
        double total = 0.0;
        for (const auto& [name, ms] : stages_) {
            std::fprintf(out, "  %-42s %8.1f ms\n", name.c_str(), ms);
            total += ms;
        }
        std::fprintf(out, "  %-42s %8.1f ms\n", "total (in process)", total);
    }

private:
    Clock::time_point last_ = Clock::now();
    std::vector<std::pair<std::string, double>> stages_;
};

}  // namespace shadelab::cli
