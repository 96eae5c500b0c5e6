// class_ready_bench: how long the path tracer takes to show a "class-ready" Cornell box: the time until the
// raw image's relative RMSE (image_error.h, the lamp left out) against a converged reference falls under
// --target (5 %), and the same for the denoised preview, on --threads (2) at --size (1280x720).
//
// The render is progressive (PathRender::addSamples, one sample per pass like the viewer's Global mode, and
// after the preview's crossing passes of about 1/32 of the samples so far, which places the raw crossing
// within 3 %). The error is measured between passes, off the clock. The preview denoises after every pass:
// its time is the tracing, the first-hit passes (once) and every denoise so far; the figure "denoised once"
// counts only the last denoise (`render --time-limit T --denoise`, which traces then denoises once).
// Times are wall and process CPU time (all threads); on a shared machine CPU time is the steadier figure.
//
// The reference (path_reference.h) has --ref-spp samples in all (256), by --ref-method (split-halves: two
// Sobol renders of half each, seeds 1 and 2; or sample-variance: the independent sampler), and is cached;
// its own noise is removed from the error (image_error.h), so it need not have 4096 spp.
// --check measures that correction: at --size (160x90 by default there) images of 1..1024 spp against a
// 4096-spp reference and against 256- and 64-spp ones, with and without the correction.
// `class_ready_bench error TEST.exr REF_A.exr REF_B.exr` prints TEST's relative RMSE against (A + B) / 2,
// corrected by the two halves' difference (another renderer's reference, which has no variance: Cycles).
//
// Usage: class_ready_bench [--size WxH] [--threads T] [--target E] [--ref-spp N] [--runs R] [--raw-runs K]
//        [--max-spp N] [--no-denoise] [--scene PATH] [--cache DIR | --no-cache] [--check]
#include "bench_timing.h"
#include "image/exr.h"
#include "image_error.h"
#include "path_reference.h"
#include "scene/scene_load.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_denoise.h"
#include "trace/path/path_render.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace shadelab;
using namespace shadelab::bench;

struct Options {
    int width = 1280, height = 720, threads = 2, refSpp = 256, runs = 3, rawRuns = 1, maxSpp = 8192;
    ReferenceMethod method = ReferenceMethod::SplitHalves;
    double target = 0.05;  // relative RMSE
    bool denoise = true, check = false, sizeGiven = false;
    std::string scene = SHADELAB_SOURCE_DIR "/assets/scenes/cornell.json";
    std::string cache = SHADELAB_BENCH_CACHE_DIR;
};

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Wall and CPU seconds of the timed sections only.
struct Stopwatch {
    double wall = 0.0, cpu = 0.0;
    template <class F>
    auto time(F&& f) {
        const Clock::time_point w0 = Clock::now();
        const double c0 = cpuSeconds();
        struct Add {
            Stopwatch& s;
            Clock::time_point w0;
            double c0;
            ~Add() {
                s.wall += msSince(w0) / 1000.0;
                s.cpu += cpuSeconds() - c0;
            }
        } add{*this, w0, c0};
        return f();
    }
};

struct Crossing {
    int spp = 0;  // 0: not reached
    double wall = 0.0, cpu = 0.0, error = 0.0;
};

struct RunResult {
    Crossing raw, denoised, denoisedOnce;
};

// One progressive render until the raw image (when `raw`) and the denoised preview (when o.denoise) are under
// the target, or o.maxSpp.
RunResult timeToTarget(const std::shared_ptr<const trace::TraceScene>& scene, const PathReference& ref,
                       const Options& o, bool raw, bool verbose) {
    trace::PathSettings ps;
    ps.width = o.width;
    ps.height = o.height;
    ps.threads = o.threads;
    ps.spp = o.maxSpp;
    DenoiseSettings ds;
    ds.threads = o.threads;
    RunResult r;
    Stopwatch tracing, passes, denoiseAll;
    auto render = tracing.time([&] { return std::make_unique<trace::PathRender>(scene, ps); });
    SurfacePasses surface;
    if (o.denoise) surface = passes.time([&] { return trace::firstHitPasses(*scene, o.width, o.height, o.threads); });
    bool rawDone = !raw, denDone = !o.denoise;
    int nextPrint = 1;
    for (int n = 0; !(rawDone && denDone);) {
        const int step = denDone ? std::max(1, n / 32) : 1;
        if (n + step > o.maxSpp) break;
        tracing.time([&] { return render->addSamples(step); });
        n += step;
        double eRaw = -1.0, eDen = -1.0;
        if (!rawDone) {
            eRaw = relativeRmse(render->image(), ref.image, &ref.variance);
            if (eRaw < o.target) {
                r.raw = {n, tracing.wall, tracing.cpu, eRaw};
                rawDone = true;
            }
        }
        if (!denDone) {
            Stopwatch last;
            const ImageF den = last.time([&] { return trace::denoisedImage(*render, surface, ds); });
            denoiseAll.wall += last.wall;
            denoiseAll.cpu += last.cpu;
            eDen = relativeRmse(den, ref.image, &ref.variance);
            if (eDen < o.target) {
                r.denoised = {n, tracing.wall + passes.wall + denoiseAll.wall,
                              tracing.cpu + passes.cpu + denoiseAll.cpu, eDen};
                r.denoisedOnce = {n, tracing.wall + passes.wall + last.wall, tracing.cpu + passes.cpu + last.cpu, eDen};
                denDone = true;
            }
        }
        if (verbose && n >= nextPrint) {  // the first pass at or past each power of two
            nextPrint *= 2;
            std::printf("  %5d spp: traced %.2f s (CPU %.2f s)", n, tracing.wall, tracing.cpu);
            if (eRaw >= 0.0) std::printf(", raw %.4f", eRaw);
            if (eDen >= 0.0) std::printf(", denoised %.4f", eDen);
            std::printf("\n");
            std::fflush(stdout);
        }
    }
    return r;
}

void printCrossing(const char* what, const Crossing& c, const Options& o) {
    if (c.spp == 0)
        std::printf("  %-22s not under %.3f by %d spp\n", what, o.target, o.maxSpp);
    else
        std::printf("  %-22s %7.2f s wall, %7.2f s CPU at %5d spp (relative RMSE %.4f)\n", what, c.wall, c.cpu, c.spp,
                    c.error);
}

void printMedian(const char* what, const std::vector<RunResult>& runs, Crossing RunResult::*field) {
    std::vector<double> wall, cpu;
    int spp = 0;
    for (const RunResult& r : runs)
        if ((r.*field).spp > 0) {
            wall.push_back((r.*field).wall);
            cpu.push_back((r.*field).cpu);
            spp = (r.*field).spp;
        }
    if (wall.empty()) return;
    std::printf("  %-22s median of %zu: %.2f s wall, %.2f s CPU (%d spp)\n", what, wall.size(), median(wall),
                median(cpu), spp);
}

int timeMode(const Options& o) {
    const auto scene = std::make_shared<const trace::TraceScene>(loadScene(o.scene));
    trace::PathSettings rs;
    rs.width = o.width;
    rs.height = o.height;
    rs.threads = o.threads;
    rs.spp = o.refSpp;
    rs.seed = 1;  // independent of the images under test (seed 0)
    const PathReference ref = cachedReference(o.scene, scene, rs, o.method, o.cache);
    std::printf(
        "%s at %dx%d on %d threads: time until relative RMSE < %.3f (reference %d spp, %s, its noise "
        "removed)\n",
        o.scene.c_str(), o.width, o.height, o.threads, o.target, ref.spp, toString(o.method));
    std::vector<RunResult> results;
    for (int i = 0; i < o.runs; ++i) {
        const bool raw = i < o.rawRuns;
        std::printf("run %d:\n", i + 1);
        results.push_back(timeToTarget(scene, ref, o, raw, i == 0));
        if (raw) printCrossing("raw", results.back().raw, o);
        if (o.denoise) {
            printCrossing("denoised every pass", results.back().denoised, o);
            printCrossing("denoised once", results.back().denoisedOnce, o);
        }
        std::fflush(stdout);
    }
    std::printf("medians:\n");
    printMedian("raw", results, &RunResult::raw);
    if (o.denoise) {
        printMedian("denoised every pass", results, &RunResult::denoised);
        printMedian("denoised once", results, &RunResult::denoisedOnce);
    }
    return 0;
}

// The correction's check: errors against a "true" 4096-spp reference (split halves, so that even its small
// noise is removed) and against low-spp ones, with and without the correction: 256 spp by sample variance,
// and 256 and 64 spp by split halves.
int checkMode(Options o) {
    if (!o.sizeGiven) o.width = 160, o.height = 90;
    const auto scene = std::make_shared<const trace::TraceScene>(loadScene(o.scene));
    trace::PathSettings rs;
    rs.width = o.width;
    rs.height = o.height;
    rs.threads = o.threads;
    auto reference = [&](int spp, uint32_t seed, ReferenceMethod method) {
        rs.spp = spp;
        rs.seed = seed;
        return cachedReference(o.scene, scene, rs, method, o.cache);
    };
    const PathReference high = reference(4096, 1, ReferenceMethod::SplitHalves);
    const PathReference lows[] = {reference(256, 3, ReferenceMethod::SampleVariance),
                                  reference(256, 4, ReferenceMethod::SplitHalves),
                                  reference(64, 6, ReferenceMethod::SplitHalves)};
    std::printf(
        "%s at %dx%d: relative RMSE against 4096 spp split-halves, corrected (uncorrected); then against "
        "256 spp sample-variance, 256 spp split-halves and 64 spp split-halves: corrected (uncorrected) "
        "corrected / 4096's\n",
        o.scene.c_str(), o.width, o.height);
    trace::PathSettings ps = rs;
    ps.sampler = trace::PathSampler::Sobol;
    ps.seed = 0;
    trace::PathRender render(scene, ps);
    const SurfacePasses surface = trace::firstHitPasses(*scene, o.width, o.height, o.threads);
    DenoiseSettings ds;
    ds.threads = o.threads;
    for (int n = 0, spp = 1; spp <= 1024; spp *= 4) {
        render.addSamples(spp - n);
        n = spp;
        const ImageF images[2] = {render.image(), trace::denoisedImage(render, surface, ds)};
        for (int k = 0; k < 2; ++k) {
            const ImageF& a = images[k];
            const double h = relativeRmse(a, high.image, &high.variance);
            std::printf("  %4d spp %-8s  %.4f (%.4f)", spp, k ? "denoised" : "raw", h, relativeRmse(a, high.image));
            for (const PathReference& low : lows) {
                const double l = relativeRmse(a, low.image, &low.variance);
                std::printf("  %.4f (%.4f) %.3f", l, relativeRmse(a, low.image), l / h);
            }
            std::printf("\n");
        }
        std::fflush(stdout);
    }
    return 0;
}

// Another renderer's image against the mean of two independent references A and B: E|A − B|² = 2 Var(A)
// per pixel, so the mean's variance is |A − B|² / 4 (whatever the sampler, as long as the seeds differ).
int errorMode(const char* test, const char* a, const char* b) {
    const ImageF t = colourOf(readExr(test), test), ra = colourOf(readExr(a), a), rb = colourOf(readExr(b), b);
    if (t.width != ra.width || t.height != ra.height || rb.width != ra.width || rb.height != ra.height) {
        std::fprintf(stderr, "class_ready_bench: %s, %s, %s: sizes differ\n", test, a, b);
        return 1;
    }
    const PathReference ref = splitHalves(ra, rb);
    std::printf("relative RMSE %.5f (uncorrected %.5f; A against B %.5f)\n", relativeRmse(t, ref.image, &ref.variance),
                relativeRmse(t, ref.image), relativeRmse(ra, rb));
    return 0;
}

[[noreturn]] void usage(const char* why) {
    std::fprintf(stderr,
                 "class_ready_bench: %s\nusage: class_ready_bench [--size WxH] [--threads T] [--target E] "
                 "[--ref-spp N] [--ref-method split-halves|sample-variance] [--runs R] [--raw-runs K] [--max-spp N] "
                 "[--no-denoise] [--scene PATH] "
                 "[--cache DIR | --no-cache] [--check]\n       class_ready_bench error TEST.exr REF_A.exr "
                 "REF_B.exr\n",
                 why);
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    auto whole = [&](int& i, int lo) {
        if (i + 1 >= argc) usage((std::string(argv[i]) + " needs a value").c_str());
        char* end = nullptr;
        const long v = std::strtol(argv[++i], &end, 10);
        if (*end || v < lo || v > (1 << 20)) usage((std::string(argv[i - 1]) + ": bad number").c_str());
        return int(v);
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size") {
            if (i + 1 >= argc || std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2 || o.width < 1 ||
                o.height < 1)
                usage("--size: expected WxH");
            o.sizeGiven = true;
        } else if (a == "--threads") {
            o.threads = whole(i, 1);
        } else if (a == "--ref-spp") {
            o.refSpp = whole(i, 2);
        } else if (a == "--runs") {
            o.runs = whole(i, 1);
        } else if (a == "--raw-runs") {
            o.rawRuns = whole(i, 0);
        } else if (a == "--max-spp") {
            o.maxSpp = whole(i, 1);
        } else if (a == "--target") {
            if (i + 1 >= argc) usage("--target needs a value");
            char* end = nullptr;
            o.target = std::strtod(argv[++i], &end);
            if (*end || !(o.target > 0.0)) usage("--target: expected a relative RMSE above 0");
        } else if (a == "--ref-method" && i + 1 < argc) {
            const std::string m = argv[++i];
            if (m != "split-halves" && m != "sample-variance")
                usage("--ref-method: expected split-halves or sample-variance");
            o.method = m == "split-halves" ? ReferenceMethod::SplitHalves : ReferenceMethod::SampleVariance;
        } else if (a == "--no-denoise") {
            o.denoise = false;
        } else if (a == "--scene" && i + 1 < argc) {
            o.scene = argv[++i];
        } else if (a == "--cache" && i + 1 < argc) {
            o.cache = argv[++i];
        } else if (a == "--no-cache") {
            o.cache.clear();
        } else if (a == "--check") {
            o.check = true;
        } else {
            usage(("unknown argument '" + a + "'").c_str());
        }
    }
    return o;
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc > 1 && std::string(argv[1]) == "error") {
        if (argc != 5) usage("error: expected TEST.exr REF_A.exr REF_B.exr");
        return errorMode(argv[2], argv[3], argv[4]);
    }
    const Options o = parse(argc, argv);
    std::printf("machine: %u hardware threads\n", std::thread::hardware_concurrency());
    return o.check ? checkMode(o) : timeMode(o);
} catch (const std::exception& e) {
    std::fprintf(stderr, "class_ready_bench: %s\n", e.what());
    return 1;
}
