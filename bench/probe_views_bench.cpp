// probe_views_bench: what a click costs the probe's two teaching views (probe/ray_tree_view.h,
// probe/rendering_equation.h), medians over runs: the ray tree recorded with every ray's words and algebra
// (target: at most 30 ms), and the rendering equation's three hemispheres at 64² (target: at most 200 ms),
// for the local model and path traced (kDefaultPathsPerTexel, as the viewer's Global modes compute it).
//
//   build/bench/probe_views_bench [runs]
#include "bench_timing.h"
#include "probe/ray_tree_view.h"
#include "probe/rendering_equation.h"
#include "scene/scene_load.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace shadelab;

namespace {

struct Case {
    const char* scene;
    int x, y;  // a pixel of a 1280x720 image
    const char* what;
};

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
    const Case cases[] = {{"assets/scenes/default.json", 280, 500, "default.json, floor by the blue sphere"},
                          {"assets/scenes/default.json", 1030, 300, "default.json, the mirror sphere"},
                          {"bench/glass-tree.json", 640, 360, "glass-tree.json (kr = kt = 1, the 1,024-ray budget)"},
                          {"assets/scenes/cornell.json", 640, 250, "cornell.json, the back wall"}};
    std::printf("probe_views_bench: medians of %d runs, 1280x720 image, one thread\n", runs);
    std::printf("%-52s %8s %6s %12s %12s\n", "pixel", "tree ms", "rays", "local ms", "global ms");
    for (const Case& c : cases) {
        const Scene scene = loadScene(std::string(SHADELAB_SOURCE_DIR) + "/" + c.scene);
        const trace::TraceScene traced(scene);
        std::vector<double> tree, local, global;
        size_t rays = 0;
        for (int r = 0; r < runs; ++r) {
            auto t0 = bench::Clock::now();
            const RayTreeView view = recordRayTree(traced, 1280, 720, c.x, c.y);
            size_t words = 0;
            for (size_t k = 0; k < view.record.rays.size(); ++k)
                words += rayTreeRayLine(scene, view.record, k).size() + rayTreeAlgebra(traced, view.record, k).size();
            tree.push_back(bench::msSince(t0));
            rays = view.record.rays.size() + (words == 0 ? 1 : 0);
            t0 = bench::Clock::now();
            const RenderingEquation l = renderingEquationAt(traced, 1280, 720, c.x, c.y, false);
            local.push_back(bench::msSince(t0));
            t0 = bench::Clock::now();
            const RenderingEquation g = renderingEquationAt(traced, 1280, 720, c.x, c.y, true);
            global.push_back(bench::msSince(t0));
            if (!l.hit || !g.hit) std::printf("  (%s: the pixel shows the background)\n", c.what);
        }
        std::printf("%-52s %8.2f %6zu %12.2f %12.1f\n", c.what, bench::median(tree), rays, bench::median(local),
                    bench::median(global));
    }
    std::printf("targets: tree <= 30 ms, three hemispheres <= 200 ms\n");
    return 0;
}
