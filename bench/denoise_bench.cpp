// denoise_bench: the path tracer's denoised preview on the Cornell box (assets/scenes/cornell.json).
// Renders it at WxH with S samples per pixel on 2 threads, then times the first-hit passes and the denoiser
// (medians of R runs), and, with a reference of REF samples per pixel (0: none), prints the relative RMSE of
// the raw and the denoised image against it, and how many samples the raw image needs for the denoised
// one's error. T sets the denoiser's threads (2). The denoiser's CPU time (all threads) is printed beside its
// wall-clock time: on a loaded machine it is the steadier figure. Usage: denoise_bench [R] [W] [H] [S] [REF]
// [scene] [T]
#include "bench_timing.h"
#include "image/denoise.h"
#include "image_error.h"
#include "scene/scene_load.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_denoise.h"
#include "trace/path/path_render.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>

namespace {

using namespace shadelab;
using shadelab::bench::Clock;
using shadelab::bench::cpuMs;
using shadelab::bench::median;
using shadelab::bench::msSince;
using shadelab::bench::relativeRmse;

}  // namespace

int main(int argc, char** argv) try {
    const int runs = argc > 1 ? std::atoi(argv[1]) : 9;
    const int w = argc > 2 ? std::atoi(argv[2]) : 1280, h = argc > 3 ? std::atoi(argv[3]) : 720;
    const int spp = argc > 4 ? std::atoi(argv[4]) : 16, refSpp = argc > 5 ? std::atoi(argv[5]) : 0;
    const std::string path =
        argc > 6 && *argv[6] ? argv[6] : std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/cornell.json";
    DenoiseSettings ds;
    ds.threads = argc > 7 ? std::atoi(argv[7]) : 2;
    const auto scene = std::make_shared<const trace::TraceScene>(loadScene(path));
    trace::PathSettings ps;
    ps.width = w;
    ps.height = h;
    ps.spp = spp;
    ps.threads = 2;
    Clock::time_point t0 = Clock::now();
    trace::PathRender render(scene, ps);
    render.addSamples(spp);
    std::printf("%s at %dx%d, %d spp on 2 threads: traced in %.0f ms\n", path.c_str(), w, h, spp, msSince(t0));

    // The preview's cost, in two parts: the render's image and the noise of each pixel the filter stops at
    // (what trace::denoisedImage prepares: luminanceVariance, then stopVariance), and the filter itself
    // (image/denoise.h) with the preview's settings for the render's samples (previewSettings).
    std::vector<double> passMs, statsMs, statsCpuMs, filterMs, filterCpuMs, denoiseMs, denoiseCpuMs;
    SurfacePasses passes;
    ImageF denoised;
    for (int r = 0; r < runs; ++r) {
        t0 = Clock::now();
        passes = trace::firstHitPasses(*scene, w, h, 2);
        passMs.push_back(msSince(t0));
        t0 = Clock::now();
        double c0 = cpuMs();
        const ImageF image = render.image();
        const std::vector<float> variance = trace::stopVariance(render, trace::luminanceVariance(render));
        statsMs.push_back(msSince(t0));
        statsCpuMs.push_back(cpuMs() - c0);
        const Clock::time_point t1 = Clock::now();
        const double c1 = cpuMs();
        denoised = denoise(image, variance, passes, trace::previewSettings(render.samples(), ds));
        filterMs.push_back(msSince(t1));
        filterCpuMs.push_back(cpuMs() - c1);
        denoiseMs.push_back(msSince(t0));
        denoiseCpuMs.push_back(cpuMs() - c0);
    }
    std::printf("first-hit passes: median %.1f ms (2 threads)\n", median(passMs));
    std::printf(
        "denoise (image and variance from the render, then the filter): median %.1f ms (%d runs, %d threads; "
        "CPU time %.1f ms, all threads)\n",
        median(denoiseMs), runs, ds.threads, median(denoiseCpuMs));
    std::printf(
        "  image and variance (the render's %d threads): median %.1f ms (CPU %.1f ms); filter: median %.1f ms "
        "(CPU %.1f ms)\n",
        ps.threads, median(statsMs), median(statsCpuMs), median(filterMs), median(filterCpuMs));
    if (refSpp > 0) {
        trace::PathSettings rs = ps;
        rs.spp = refSpp;
        rs.seed = 1;  // independent of the image under test
        trace::PathRender ref(scene, rs);
        t0 = Clock::now();
        ref.addSamples(refSpp);
        const ImageF refImage = ref.image();
        const double raw = relativeRmse(render.image(), refImage), den = relativeRmse(denoised, refImage);
        std::printf(
            "reference %d spp (%.0f s); relative RMSE: raw %.4f, denoised %.4f (%.2f of raw; the raw image "
            "needs about %.0f spp for it)\n",
            refSpp, msSince(t0) / 1000.0, raw, den, den / raw, spp * (raw / den) * (raw / den));
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "denoise_bench: %s\n", e.what());
    return 1;
}
