// scene_copy_bench: what a viewer edit costs before any pixel is traced, on 2CylinderEngine.
//   copy     the Scene copy the viewer's ReferenceRenderer::request makes on every change (mesh geometry
//            is shared, so O(objects));
//   restart  after a shininess change: copy + TraceScene over the cached MeshBvh + ProgressiveTrace::start,
//            until the first 32² tile of a 1280x720 reference arrives;
//   deep     for scale: copying the vertex and index arrays, which the copy no longer does.
// Prints medians of N runs. Usage: scene_copy_bench [model.glb] [runs]
#include "bench_timing.h"
#include "scene/scene_load.h"
#include "trace/accel/mesh_bvh_cache.h"
#include "trace/progressive_trace.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <vector>

int main(int argc, char** argv) {
    using namespace shadelab;
    using namespace shadelab::bench;
    const char* model =
        argc > 1 ? argv[1] : "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 21;
    try {
        Scene scene = loadScene(model);
        size_t triangles = 0, parts = 0;
        for (const Mesh& m : scene.meshes) {
            triangles += m.triangleCount();
            parts += m.parts.size();
        }
        trace::MeshBvhCache cache;
        cache.get(scene);  // the BVH the viewer's reference built when the model opened

        std::vector<double> copy, restart, deep;
        for (int i = 0; i < runs; ++i) {
            auto t0 = Clock::now();
            Scene c = scene;
            copy.push_back(msSince(t0));

            scene.meshes[0].parts[0].material.s = float(8 + i);  // a shininess change
            t0 = Clock::now();
            Scene job = scene;
            auto ts = std::make_shared<trace::TraceScene>(job, cache.get(job));
            trace::TraceSettings settings;
            settings.width = 1280;
            settings.height = 720;
            settings.tileSize = 32;
            settings.threads = 1;
            trace::ProgressiveTrace trace;
            trace.start(ts, settings);
            std::vector<trace::TileResult> tiles;
            while (tiles.empty()) trace.wait(tiles, std::chrono::milliseconds(1));
            restart.push_back(msSince(t0));
            trace.cancel();

            t0 = Clock::now();
            std::vector<MeshGeometry> arrays;
            for (const Mesh& m : scene.meshes)
                for (const MeshPart& p : m.parts) arrays.push_back(*p.geometry);
            deep.push_back(msSince(t0));
        }
        std::printf("%s: %zu triangles in %zu parts, median of %d runs\n", model, triangles, parts, runs);
        std::printf("  scene copy (shared geometry)            %8.4f ms\n", median(copy));
        std::printf("  reference restart to first tile         %8.3f ms\n", median(restart));
        std::printf("  deep copy of the vertex/index arrays    %8.3f ms (what a copy cost before)\n", median(deep));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "scene_copy_bench: %s\n", e.what());
        return 1;
    }
}
