// process_bench: runs a command N times and prints each run's wall time and peak resident memory, then
// the medians. Whole-process figures, as the speed targets in bench/README.md are stated.
// usage: process_bench [--runs N] [--warmup K] -- command [args...]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Run {
    double wallMs;
    double peakMiB;
    int status;
};

Run runOnce(char** argv) {
    auto start = std::chrono::steady_clock::now();
    pid_t pid = fork();
    if (pid == 0) {
        execvp(argv[0], argv);
        std::perror(argv[0]);
        _exit(127);
    }
    int status = 0;
    struct rusage usage {};
    wait4(pid, &status, 0, &usage);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return {ms, double(usage.ru_maxrss) / 1024.0, status};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 5, warmup = 1, i = 1;
    for (; i < argc && std::strcmp(argv[i], "--") != 0; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--warmup") && i + 1 < argc)
            warmup = std::atoi(argv[++i]);
        else {
            std::fprintf(stderr, "usage: process_bench [--runs N] [--warmup K] -- command [args...]\n");
            return 2;
        }
    }
    if (i + 1 >= argc || runs < 1) {
        std::fprintf(stderr, "usage: process_bench [--runs N] [--warmup K] -- command [args...]\n");
        return 2;
    }
    char** cmd = argv + i + 1;
    for (int w = 0; w < warmup; ++w) runOnce(cmd);
    std::vector<double> wall, mem;
    for (int r = 0; r < runs; ++r) {
        Run run = runOnce(cmd);
        if (!WIFEXITED(run.status) || WEXITSTATUS(run.status) != 0) {
            std::fprintf(stderr, "process_bench: run %d failed (status %d)\n", r + 1, run.status);
            return 1;
        }
        std::printf("  run %d: %7.1f ms  %6.1f MiB peak\n", r + 1, run.wallMs, run.peakMiB);
        wall.push_back(run.wallMs);
        mem.push_back(run.peakMiB);
    }
    std::printf("median of %d: %.1f ms wall, %.1f MiB peak RSS\n", runs, median(wall), median(mem));
    return 0;
}
