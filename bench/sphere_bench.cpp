// sphere_bench: the sphere set's two ways, a flat pass over every sphere (SphereList) and the BVH walk, on the
// same rays for sets of 4 to 512 spheres, one thread; it chose kFlatSphereLimit (trace/accel/sphere_set.h).
// The spheres lie on a floor at spheres40.json's density (the area grows with the count), seen by camera rays
// from spheres40's eye, and shadow rays run from points on the spheres to its key light. Each figure is the
// median of `runs` passes, flat and tree alternated, and the ratio flat / tree is of the same run. The flat pass
// runs in AVX2 where the CPU has it; SHADELAB_BVH_ISA=sse2 times the baseline pass.
// usage: sphere_bench [runs]   (default 9)
#include "bench_timing.h"
#include "trace/accel/sphere_set.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

namespace {

using namespace shadelab;
using namespace shadelab::trace;

struct Workload {
    std::vector<Sphere> spheres;
    std::vector<Ray> camera, shadow;
    std::vector<float> shadowLength;
};

Workload makeWorkload(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    // spheres40: 40 spheres of radius 0.3-1.2 on about 20 x 12 units of floor.
    const float side = std::sqrt(240.0f * float(n) / 40.0f);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Workload w;
    for (int i = 0; i < n; ++i) {
        const float r = 0.3f + 0.9f * u(rng);
        w.spheres.push_back(Sphere{"", {(u(rng) - 0.5f) * side, r, -u(rng) * side}, r, Material{}});
    }
    const glm::vec3 eye(0.0f, 5.0f, 14.0f), light(-8.0f, 12.0f, 8.0f);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 target((u(rng) - 0.5f) * side, u(rng) * 1.5f, -u(rng) * side);
        w.camera.push_back(Ray{eye, glm::normalize(target - eye)});
        const Sphere& s = w.spheres[size_t(i) % w.spheres.size()];
        const glm::vec3 d = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng), u(rng) - 0.5f));
        const glm::vec3 p = s.center + (s.radius * 1.001f) * d;
        w.shadow.push_back(Ray{p, glm::normalize(light - p)});
        w.shadowLength.push_back(glm::length(light - p));
    }
    return w;
}

// Nanoseconds per ray of one pass over the workload's camera rays (closest hit) and shadow rays (any hit).
struct Pass {
    double closestNs, anyNs;
};

Pass timePass(const SphereSet& set, const Workload& w, uint64_t& sink) {
    const auto t0 = bench::Clock::now();
    for (const Ray& r : w.camera)
        if (const std::optional<SphereHit> h = set.closestHit(r, 0.0f, INFINITY)) sink += h->index;
    const double closest = bench::msSince(t0);
    const auto t1 = bench::Clock::now();
    for (size_t i = 0; i < w.shadow.size(); ++i) sink += set.anyHit(w.shadow[i], 0.0f, w.shadowLength[i]);
    const double any = bench::msSince(t1);
    return {closest * 1e6 / double(w.camera.size()), any * 1e6 / double(w.shadow.size())};
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::atoi(argv[1]) : 9;
    if (runs < 1) {
        std::fprintf(stderr, "usage: sphere_bench [runs]\n");
        return 2;
    }
    uint64_t sink = 0;
    std::printf("spheres  closest ns/ray: flat  tree  flat/tree   any ns/ray: flat  tree  flat/tree\n");
    for (const int n : {4, 8, 16, 24, 32, 40, 48, 64, 96, 128, 256, 512}) {
        const Workload w = makeWorkload(n, 7u + uint32_t(n));
        const SphereSet flat(w.spheres, size_t(n)), tree(w.spheres, 0);
        std::vector<double> fc, tc, fa, ta, rc, ra;
        for (int run = 0; run < runs; ++run) {
            const Pass f = timePass(flat, w, sink), t = timePass(tree, w, sink);
            fc.push_back(f.closestNs), tc.push_back(t.closestNs), fa.push_back(f.anyNs), ta.push_back(t.anyNs);
            rc.push_back(f.closestNs / t.closestNs), ra.push_back(f.anyNs / t.anyNs);
        }
        std::printf("%7d  %20.1f %5.1f %9.2f %17.1f %5.1f %9.2f\n", n, bench::median(fc), bench::median(tc),
                    bench::median(rc), bench::median(fa), bench::median(ta), bench::median(ra));
    }
    std::printf("(checksum %llu)\n", static_cast<unsigned long long>(sink));
    return 0;
}
