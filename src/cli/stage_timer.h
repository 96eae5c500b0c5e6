// StageTimer: wall-clock time and resident memory after each named stage of a command, for --timings and
// the benchmarks. Memory is read from /proc/self/statm (Linux); elsewhere it prints 0.
#pragma once

#include <unistd.h>
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
        stages_.push_back(
            {std::move(name), std::chrono::duration<double, std::milli>(now - last_).count(), residentMiB()});
        last_ = Clock::now();
    }
    // Ends the current stage as two interleaved ones whose durations were measured by the caller.
    void stageSplit(std::string first, double firstMs, std::string second, double secondMs) {
        double rss = residentMiB();
        stages_.push_back({std::move(first), firstMs, rss});
        stages_.push_back({std::move(second), secondMs, rss});
        last_ = Clock::now();
    }
    void print(std::FILE* out) const {
        double total = 0.0;
        std::fprintf(out, "  %-42s %8s %12s\n", "stage", "time", "RSS after");
        for (const Stage& st : stages_) {
            std::fprintf(out, "  %-42s %5.1f ms %8.1f MiB\n", st.name.c_str(), st.ms, st.rssMiB);
            total += st.ms;
        }
        std::fprintf(out, "  %-42s %5.1f ms\n", "total (in process)", total);
    }

private:
    struct Stage {
        std::string name;
        double ms;
        double rssMiB;
    };
    static double residentMiB() {
        long pages = 0, resident = 0;
        if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
            if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
            std::fclose(f);
        }
        return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
    }
    Clock::time_point last_ = Clock::now();
    std::vector<Stage> stages_;
};

}  // namespace shadelab::cli
