// path_sampler_bench: the path tracer's two samplers (trace/path/sample_rng.h) compared.
//   error  the RMSE (linear radiance, all pixels and channels) at 4, 16 and 64 spp against a 4096-spp Sobol
//          reference (another seed), on assets/scenes/cornell.json and local-vs-global.json, for the
//          independent and the Sobol sampler: the median over RUNS seeds of each;
//   speed  paths per second of each sampler on assets/scenes/default.json (640x360, 16 spp, the scene's
//          depth), runs alternating between the samplers: the median of RUNS.
// Usage: path_sampler_bench [WxH of the error renders, default 128x72 | speed: the speed part alone] [runs,
// default 5] [threads, default 2]
#include "bench_timing.h"
#include "image_error.h"
#include "scene/scene_load.h"
#include "trace/path/path_render.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace shadelab;

ImageF render(const std::shared_ptr<const trace::TraceScene>& scene, trace::PathSettings s) {
    trace::PathRender r(scene, s);
    r.addSamples(s.spp);
    return r.image();
}

}  // namespace

int main(int argc, char** argv) {
    using namespace shadelab::bench;
    int width = 128, height = 72;
    const bool speedOnly = argc > 1 && std::string(argv[1]) == "speed";
    if (argc > 1 && !speedOnly && std::sscanf(argv[1], "%dx%d", &width, &height) != 2) {
        std::fprintf(stderr, "usage: path_sampler_bench [WxH | speed] [runs] [threads]\n");
        return 2;
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
    const int threads = argc > 3 ? std::max(1, std::atoi(argv[3])) : 2;
    const trace::PathSampler samplers[] = {trace::PathSampler::Independent, trace::PathSampler::Sobol};
    try {
        for (const char* name : {"cornell", "local-vs-global"}) {
            if (speedOnly) break;
            const std::string path = std::string(SHADELAB_SOURCE_DIR "/assets/scenes/") + name + ".json";
            const auto scene = std::make_shared<const trace::TraceScene>(loadScene(path));
            trace::PathSettings s;
            s.width = width;
            s.height = height;
            s.threads = threads;
            s.spp = 4096;
            s.seed = 1000;
            const Clock::time_point t0 = Clock::now();
            const ImageF reference = render(scene, s);
            std::printf("%s %dx%d: reference 4096 spp in %.1f s\n", name, width, height, msSince(t0) / 1000.0);
            std::fflush(stdout);
            for (int spp : {4, 16, 64}) {
                double med[2];
                for (int k = 0; k < 2; ++k) {
                    std::vector<double> errors;
                    for (int run = 0; run < runs; ++run) {
                        s.spp = spp;
                        s.seed = uint32_t(run);
                        s.sampler = samplers[k];
                        errors.push_back(rmse(render(scene, s), reference));
                    }
                    med[k] = median(errors);
                }
                std::printf("  %2d spp: RMSE median of %d: independent %.5f, sobol %.5f, sobol / independent %.3f\n",
                            spp, runs, med[0], med[1], med[1] / med[0]);
            }
        }
        const auto scene =
            std::make_shared<const trace::TraceScene>(loadScene(SHADELAB_SOURCE_DIR "/assets/scenes/default.json"));
        trace::PathSettings s;
        s.width = 640;
        s.height = 360;
        s.spp = 16;
        s.threads = threads;
        std::vector<double> rate[2];
        render(scene, s);  // warm-up
        for (int run = 0; run < runs; ++run)
            for (int k = 0; k < 2; ++k) {
                s.sampler = samplers[(run + k) % 2];
                const Clock::time_point t0 = Clock::now();
                render(scene, s);
                rate[(run + k) % 2].push_back(double(s.width) * s.height * s.spp / (msSince(t0) / 1000.0));
            }
        std::printf(
            "default.json 640x360, 16 spp, %d threads: Mpaths/s median of %d: independent %.3f, sobol %.3f "
            "(sobol / independent %.3f)\n",
            threads, runs, median(rate[0]) / 1e6, median(rate[1]) / 1e6, median(rate[1]) / median(rate[0]));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "path_sampler_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
