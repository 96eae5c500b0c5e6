// prefilter_bench: building the prefiltered environment of a 256² cube from the shipped sky
// (assets/environments/sky.hdr, 256x128) on 2 threads: the source cube, its mips, the GGX levels and the SH9
// (the budget is 150 ms on 2 cores), and, for scale, on 1 thread; the .hdr decode and the DFG table apart.
// Prints medians of N runs. Usage: prefilter_bench [sky.hdr] [runs] [cube size]
#include "bench_timing.h"
#include "image/hdr.h"
#include "shading/dfg_lut.h"
#include "shading/prefilter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

using shadelab::bench::Clock;
using shadelab::bench::median;
using shadelab::bench::msSince;

double fastest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

}  // namespace

int main(int argc, char** argv) {
    using namespace shadelab;
    const std::string path = argc > 1 ? argv[1] : SHADELAB_SOURCE_DIR "/assets/environments/sky.hdr";
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 11;
    const int size = argc > 3 ? std::atoi(argv[3]) : 256;
    try {
        std::vector<double> decode, two, one, dfg;
        shading::EquirectMap map;
        for (int i = 0; i < runs; ++i) {
            auto t0 = Clock::now();
            HdrImage hdr = readHdr(path);
            decode.push_back(msSince(t0));
            map.width = hdr.width;
            map.height = hdr.height;
            map.rgb = std::move(hdr.rgb);

            shading::PrefilterSettings s;
            s.size = size;
            s.threads = 2;
            t0 = Clock::now();
            const shading::PrefilteredEnvironment env = shading::prefilterEnvironment(map, s);
            two.push_back(msSince(t0));
            s.threads = 1;
            t0 = Clock::now();
            const shading::PrefilteredEnvironment env1 = shading::prefilterEnvironment(map, s);
            one.push_back(msSince(t0));
            if (env.atlas != env1.atlas) {
                std::fprintf(stderr, "prefilter_bench: the thread count changed the result\n");
                return 1;
            }
            t0 = Clock::now();
            const shading::DfgLut lut = shading::computeDfgLut();
            dfg.push_back(msSince(t0));
        }
        std::printf("environment %s (%dx%d), cube %d² with %d levels, %d runs\n", path.c_str(), map.width, map.height,
                    size, shading::prefilterLevels(size), runs);
        std::printf("  decode .hdr          median %7.2f ms\n", median(decode));
        // The fastest run is what the code costs when nothing else competes for the cores.
        std::printf("  prefilter, 2 threads median %7.2f ms, fastest %7.2f ms   (budget 150 ms)\n", median(two),
                    fastest(two));
        std::printf("  prefilter, 1 thread  median %7.2f ms, fastest %7.2f ms\n", median(one), fastest(one));
        std::printf("  DFG table 32², 1 thread median %5.2f ms\n", median(dfg));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "prefilter_bench: %s\n", e.what());
        return 1;
    }
}
