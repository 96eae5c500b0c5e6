// trace_bench: in-process timings for the tracer's benchmarks (a benchmark, never a timed test).
//  (a) bench/spheres40.json at 1920x1080, 1 spp, 2 threads: median of 5 traceImage() calls, plus the
//      in-process end-to-end path (load, trace, 8-bit conversion, PNG encoding) for scale.
//  (b) 2CylinderEngine.glb at 1920x1080, 2 threads: a primary ray per pixel and one shadow ray per hit,
//      in Mrays/s (median of 5); with Embree 3 (optional, SHADELAB_HAVE_EMBREE) the same rays through
//      rtcIntersect1 / rtcOccluded1 and the ratio ours / Embree's; for the engine's coherent rays also through
//      its 8-wide packets (rtcIntersect8 / rtcOccluded8). Whole-process timing is bench/trace_spheres.sh.
//  (c) incoherent rays: on the same model, one cosine-distributed secondary ray per primary hit
//      (about the geometric normal, on the viewer's side, from a per-pixel hash), nearest hit through
//      TraceScene::intersect and through rtcIntersect1, the same precomputed rays to both.
//  (d) scale: a grid of N x N UV spheres of 4,096 triangles each built in memory (32 x 32 =
//      4.19 M triangles), BVH build time (ours and Embree's) and primary + shadow rays at 1920x1080. Peak
//      memory comes from running it alone under /usr/bin/time -v (--only scale --no-embree).
#include "image/encode.h"
#include "image/png.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "trace/accel/bvh_isa.h"
#include "trace/integrator.h"
#include "trace/tile_renderer.h"
#include "trace/trace_image.h"
#include "trace/trace_scene.h"

#ifdef SHADELAB_HAVE_EMBREE
#include "embree_scene.h"
#endif
#include "sphere_grid.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

using namespace shadelab;
using namespace shadelab::bench;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
    std::string spheres = SHADELAB_SOURCE_DIR "/bench/spheres40.json";
    std::string engine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    int runs = 5, threads = 2, width = 1920, height = 1080;
    bool skipSpheres = false, skipEngine = false, skipIncoherent = false, skipScale = false;
    bool embree = true;    // --no-embree: leave the baseline out (for a clean peak-RSS figure)
    int grid = 32;         // scale: grid x grid spheres of 4,096 triangles
    bool spatial = false;  // scale, --spatial: plain builds, then one with spatial splits whatever the size
    std::string png;       // write the spheres image here when set
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// CPU seconds this process has used (all threads): on a loaded machine, rays per CPU-second move far less with
// the other processes than rays per wall-clock second do.
double cpuSeconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

void benchSpheres(const Options& o) {
    trace::TraceSettings s;
    s.width = o.width;
    s.height = o.height;
    s.threads = o.threads;
    std::vector<double> traceTimes, totalTimes;
    for (int r = 0; r < o.runs; ++r) {
        const auto t0 = Clock::now();
        const Scene scene = loadScene(o.spheres);
        const auto t1 = Clock::now();
        const trace::TraceOutput out = trace::traceImage(scene, s);
        const auto t2 = Clock::now();
        const std::vector<uint8_t> png = encodePng(toImage8(out.color, Encoding::Srgb, DisplaySettings{}, nullptr));
        const auto t3 = Clock::now();
        traceTimes.push_back(seconds(t1, t2));
        totalTimes.push_back(seconds(t0, t3));
        std::printf("  run %d: trace %.3f s, load+trace+encode %.3f s (%zu PNG bytes)\n", r + 1, seconds(t1, t2),
                    seconds(t0, t3), png.size());
        if (r == 0 && !o.png.empty()) writePng(o.png, toImage8(out.color, Encoding::Srgb, DisplaySettings{}, nullptr));
    }
    std::printf("spheres40 %dx%d, 1 spp, %d threads: median of %d: trace %.3f s, in-process end to end %.3f s\n",
                o.width, o.height, o.threads, o.runs, median(traceTimes), median(totalTimes));
}

// Runs `perRow(row)` for every image row on `threads` threads pulling rows from a counter.
void parallelRows(int height, int threads, const std::function<void(int)>& perRow) {
    std::atomic<int> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (int y; (y = next.fetch_add(1)) < height;) perRow(y);
        });
    for (std::thread& th : pool) th.join();
}

struct RayCounts {
    uint64_t primary = 0, hits = 0, occluded = 0;
};

RayCounts sum(const std::vector<RayCounts>& perRow) {
    RayCounts total;
    for (const RayCounts& c : perRow) {
        total.primary += c.primary;
        total.hits += c.hits;
        total.occluded += c.occluded;
    }
    return total;
}

// The shadow ray of a hit: from P offset along the geometric normal on the viewer's side, toward light 0.
bool shadowRay(const Scene& scene, glm::vec3 P, glm::vec3 Ng, glm::vec3 dir, float eps, trace::Ray& out, float& tMax) {
    if (glm::dot(Ng, dir) > 0.0f) Ng = -Ng;
    const float len = glm::length(Ng);
    if (!(len > 0.0f) || scene.lights.empty()) return false;
    out.origin = P + eps * (Ng / len);
    const Light& l = scene.lights[0];
    if (l.positional()) {
        const glm::vec3 toL = l.position - out.origin;
        tMax = glm::length(toL);
        out.dir = toL / tMax;
    } else {
        tMax = INFINITY;
        out.dir = glm::normalize(-l.direction);
    }
    return true;
}

RayCounts traceOurs(const trace::TraceScene& ts, const ViewSetup& view, int threads) {
    const Scene& scene = ts.scene();
    const trace::MeshBvh& mb = *ts.meshBvh();
    std::vector<RayCounts> perRow(size_t(view.height));
    parallelRows(view.height, threads, [&](int y) {
        RayCounts c;
        for (int x = 0; x < view.width; ++x) {
            const trace::Ray ray = trace::sampleRay(view, 1, x, y, 0, 0);
            ++c.primary;
            const std::optional<trace::Hit> hit = ts.intersect(ray);
            if (!hit) continue;
            ++c.hits;
            trace::Ray sr;
            float tMax;
            if (shadowRay(scene, ray.origin + hit->t * ray.dir, mb.geometricNormal(hit->index), ray.dir, ts.epsilon(),
                          sr, tMax))
                c.occluded += ts.occluded(sr, tMax) ? 1 : 0;
        }
        perRow[size_t(y)] = c;
    });
    return sum(perRow);
}

// The same rays as packets of eight neighbouring pixels of a row, the shadow rays of their hits as one packet
// (TraceScene::intersect8 / occluded8): the shape of traceEmbree8, for the comparison with Embree's packets.
RayCounts traceOurPackets(const trace::TraceScene& ts, const ViewSetup& view, int threads) {
    const Scene& scene = ts.scene();
    const trace::MeshBvh& mb = *ts.meshBvh();
    std::vector<RayCounts> perRow(size_t(view.height));
    parallelRows(view.height, threads, [&](int y) {
        RayCounts c;
        for (int x0 = 0; x0 < view.width; x0 += 8) {
            trace::Ray rays[8], shadow[8];
            float tMax[8];
            unsigned valid = 0, shadowValid = 0;
            for (int k = 0; k < 8 && x0 + k < view.width; ++k) {
                rays[k] = trace::sampleRay(view, 1, x0 + k, y, 0, 0);
                valid |= 1u << k;
                ++c.primary;
            }
            std::optional<trace::Hit> hits[8];
            ts.intersect8(rays, valid, hits);
            for (int k = 0; k < 8; ++k) {
                if (!hits[k]) continue;
                ++c.hits;
                if (shadowRay(scene, rays[k].origin + hits[k]->t * rays[k].dir, mb.geometricNormal(hits[k]->index),
                              rays[k].dir, ts.epsilon(), shadow[k], tMax[k]))
                    shadowValid |= 1u << k;
            }
            if (shadowValid) c.occluded += uint64_t(__builtin_popcount(ts.occluded8(shadow, tMax, shadowValid)));
        }
        perRow[size_t(y)] = c;
    });
    return sum(perRow);
}

#ifdef SHADELAB_HAVE_EMBREE
RayCounts traceEmbree(const EmbreeScene& es, const Scene& scene, float eps, const ViewSetup& view, int threads) {
    std::vector<RayCounts> perRow(size_t(view.height));
    parallelRows(view.height, threads, [&](int y) {
        RayCounts c;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (int x = 0; x < view.width; ++x) {
            const trace::Ray ray = trace::sampleRay(view, 1, x, y, 0, 0);
            ++c.primary;
            RTCRayHit rh = embreeRayHit(ray);
            rtcIntersect1(es.scene, &ctx, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            ++c.hits;
            trace::Ray sr;
            float tMax;
            if (!shadowRay(scene, ray.origin + rh.ray.tfar * ray.dir, es.normals[rh.hit.primID], ray.dir, eps, sr,
                           tMax))
                continue;
            RTCRay r{};
            r.org_x = sr.origin.x;
            r.org_y = sr.origin.y;
            r.org_z = sr.origin.z;
            r.dir_x = sr.dir.x;
            r.dir_y = sr.dir.y;
            r.dir_z = sr.dir.z;
            r.tnear = 0.0f;
            r.tfar = tMax;
            r.mask = ~0u;
            rtcOccluded1(es.scene, &ctx, &r);
            c.occluded += r.tfar < 0.0f ? 1 : 0;
        }
        perRow[size_t(y)] = c;
    });
    return sum(perRow);
}

// The same rays through Embree's 8-wide packet API (rtcIntersect8 / rtcOccluded8), which the issue names as the
// coherent-ray comparison: each packet is eight neighbouring pixels of a row, its shadow rays the hits among them.
RayCounts traceEmbree8(const EmbreeScene& es, const Scene& scene, float eps, const ViewSetup& view, int threads) {
    std::vector<RayCounts> perRow(size_t(view.height));
    parallelRows(view.height, threads, [&](int y) {
        RayCounts c;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        for (int x0 = 0; x0 < view.width; x0 += 8) {
            alignas(32) int valid[8];
            alignas(32) RTCRayHit8 rh;
            trace::Ray rays[8];
            for (int k = 0; k < 8; ++k) {
                valid[k] = x0 + k < view.width ? -1 : 0;
                rays[k] = trace::sampleRay(view, 1, std::min(x0 + k, view.width - 1), y, 0, 0);
                rh.ray.org_x[k] = rays[k].origin.x;
                rh.ray.org_y[k] = rays[k].origin.y;
                rh.ray.org_z[k] = rays[k].origin.z;
                rh.ray.dir_x[k] = rays[k].dir.x;
                rh.ray.dir_y[k] = rays[k].dir.y;
                rh.ray.dir_z[k] = rays[k].dir.z;
                rh.ray.tnear[k] = 0.0f;
                rh.ray.tfar[k] = INFINITY;
                rh.ray.mask[k] = ~0u;
                rh.ray.time[k] = 0.0f;
                rh.ray.flags[k] = 0;
                rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                c.primary += valid[k] ? 1 : 0;
            }
            rtcIntersect8(valid, es.scene, &ctx, &rh);
            alignas(32) int shadowValid[8];
            alignas(32) RTCRay8 sr8;
            bool any = false;
            for (int k = 0; k < 8; ++k) {
                shadowValid[k] = 0;
                if (!valid[k] || rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) continue;
                ++c.hits;
                trace::Ray sr;
                float tMax;
                if (!shadowRay(scene, rays[k].origin + rh.ray.tfar[k] * rays[k].dir, es.normals[rh.hit.primID[k]],
                               rays[k].dir, eps, sr, tMax))
                    continue;
                shadowValid[k] = -1;
                any = true;
                sr8.org_x[k] = sr.origin.x;
                sr8.org_y[k] = sr.origin.y;
                sr8.org_z[k] = sr.origin.z;
                sr8.dir_x[k] = sr.dir.x;
                sr8.dir_y[k] = sr.dir.y;
                sr8.dir_z[k] = sr.dir.z;
                sr8.tnear[k] = 0.0f;
                sr8.tfar[k] = tMax;
                sr8.mask[k] = ~0u;
                sr8.time[k] = 0.0f;
                sr8.flags[k] = 0;
            }
            if (!any) continue;
            rtcOccluded8(shadowValid, es.scene, &ctx, &sr8);
            for (int k = 0; k < 8; ++k) c.occluded += shadowValid[k] && sr8.tfar[k] < 0.0f ? 1 : 0;
        }
        perRow[size_t(y)] = c;
    });
    return sum(perRow);
}
#endif

double mraysPerSecond(const RayCounts& c, double s) { return double(c.primary + c.hits) / s * 1e-6; }

// Node count, mean children per node, leaves and mean primitives per leaf of a built tree.
void printTreeStats(const char* what, const trace::Bvh& bvh) {
    size_t children = 0, leaves = 0, prims = 0;
    for (const trace::BvhNode& n : bvh.nodes)
        for (int k = 0; k < trace::kBvhWidth; ++k) {
            if (!n.used(k)) continue;
            ++children;
            if (trace::isLeafRef(n.child[k])) ++leaves, prims += trace::leafCount(n.child[k]);
        }
    std::printf(
        "%s: SAH cost %.2f, %zu nodes (%.2f children each, %zu MiB), %zu leaves (%.2f primitives each), depth %d\n",
        what, trace::sahCost(bvh), bvh.nodes.size(), double(children) / double(std::max<size_t>(bvh.nodes.size(), 1)),
        bvh.nodes.size() * sizeof(trace::BvhNode) >> 20, leaves, double(prims) / double(std::max<size_t>(leaves, 1)),
        bvh.depth);
}

void benchEngine(const Options& o) {
    if (!std::filesystem::exists(o.engine)) {
        std::printf("engine: %s missing (apt-get install assimp-testmodels); skipped\n", o.engine.c_str());
        return;
    }
    const Scene scene = loadScene(o.engine);
    auto t0 = Clock::now();
    const trace::TraceScene ts(scene);
    std::printf("engine: %zu triangles, built in %.1f ms\n", ts.meshBvh()->triangleCount(),
                1e3 * seconds(t0, Clock::now()));
    printTreeStats("engine BVH", ts.meshBvh()->bvh());
    const ViewSetup view = makeViewSetup(ts.scene(), o.width, o.height);
    // o.runs timed runs of `trace` (it returns the rays it traced, the last run's kept in `counts`): Mrays/s each.
    auto timedRuns = [&o](const char* label, auto&& trace, RayCounts& counts) {
        std::vector<double> rates;
        for (int r = 0; r < o.runs; ++r) {
            const auto start = Clock::now();
            counts = trace();
            const double s = seconds(start, Clock::now());
            rates.push_back(mraysPerSecond(counts, s));
            std::printf("  %s run %d: %.3f s, %.2f Mrays/s\n", label, r + 1, s, rates.back());
        }
        return rates;
    };
    RayCounts c;
    const std::vector<double> ours = timedRuns(
        "shadelab", [&] { return traceOurs(ts, view, o.threads); }, c);
    std::printf("engine %dx%d, %d threads: %llu primary + %llu shadow rays (%llu occluded)\n", o.width, o.height,
                o.threads, (unsigned long long)c.primary, (unsigned long long)c.hits, (unsigned long long)c.occluded);
    const double oursMedian = median(ours);
    std::printf("shadelab: median of %d: %.2f Mrays/s\n", o.runs, oursMedian);
    RayCounts cp;
    const std::vector<double> oursPackets = timedRuns(
        "shadelab packets", [&] { return traceOurPackets(ts, view, o.threads); }, cp);
    if (cp.primary != c.primary || cp.hits != c.hits || cp.occluded != c.occluded) {
        std::fprintf(stderr,
                     "trace_bench: the packets found other hits than single rays (%llu/%llu against %llu/%llu)\n",
                     (unsigned long long)cp.hits, (unsigned long long)cp.occluded, (unsigned long long)c.hits,
                     (unsigned long long)c.occluded);
        std::exit(1);
    }
    const double oursPacketsMedian = median(oursPackets);
    std::printf("shadelab packets (TraceScene::intersect8 / occluded8): median of %d: %.2f Mrays/s\n", o.runs,
                oursPacketsMedian);
#ifdef SHADELAB_HAVE_EMBREE
    t0 = Clock::now();
    const EmbreeScene es(scene);
    std::printf("embree %s: built in %.1f ms\n", RTC_VERSION_STRING, 1e3 * seconds(t0, Clock::now()));
    RayCounts e;
    const std::vector<double> theirs = timedRuns(
        "embree", [&] { return traceEmbree(es, scene, ts.epsilon(), view, o.threads); }, e);
    std::printf("embree: %llu primary + %llu shadow rays (%llu occluded)\n", (unsigned long long)e.primary,
                (unsigned long long)e.hits, (unsigned long long)e.occluded);
    const double embreeMedian = median(theirs);
    std::printf("embree: median of %d: %.2f Mrays/s\n", o.runs, embreeMedian);
    std::printf("ratio shadelab / embree: %.2f (target >= 0.5)\n", oursMedian / embreeMedian);
    const std::vector<double> packets = timedRuns(
        "embree packets", [&] { return traceEmbree8(es, scene, ts.epsilon(), view, o.threads); }, e);
    std::printf(
        "embree packets (rtcIntersect8 / rtcOccluded8): %llu primary + %llu shadow rays (%llu occluded); "
        "median of %d: %.2f Mrays/s\n",
        (unsigned long long)e.primary, (unsigned long long)e.hits, (unsigned long long)e.occluded, o.runs,
        median(packets));
    std::printf("ratio shadelab / embree packets: %.2f single rays, %.2f packets (target >= 1.0)\n",
                oursMedian / median(packets), oursPacketsMedian / median(packets));
#else
    std::printf("embree: not built (install libembree-dev and reconfigure for the comparison)\n");
#endif
}

// ---- (c) incoherent secondary rays ----------------------------------------------------------------------

// PCG-style integer hash (O'Neill 2014's output permutation): a reproducible stream per pixel.
uint32_t hash32(uint32_t v) {
    const uint32_t state = v * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float unitFloat(uint32_t v) { return float(v >> 8) * 0x1p-24f; }

// One cosine-distributed ray about the geometric normal (turned to the viewer) per primary hit, in pixel
// order. The same rays for any thread count: rows are generated independently and joined in order.
std::vector<trace::Ray> secondaryRays(const trace::TraceScene& ts, const ViewSetup& view, int threads) {
    const trace::MeshBvh& mb = *ts.meshBvh();
    std::vector<std::vector<trace::Ray>> rows(size_t(view.height));
    parallelRows(view.height, threads, [&](int y) {
        std::vector<trace::Ray>& out = rows[size_t(y)];
        for (int x = 0; x < view.width; ++x) {
            const trace::Ray ray = trace::sampleRay(view, 1, x, y, 0, 0);
            const std::optional<trace::Hit> hit = ts.intersect(ray);
            if (!hit || hit->kind != trace::HitKind::Triangle) continue;
            glm::vec3 n = mb.geometricNormal(hit->index);
            const float len = glm::length(n);
            if (!(len > 0.0f)) continue;
            n /= len;
            if (glm::dot(n, ray.dir) > 0.0f) n = -n;
            const uint32_t seed = hash32(uint32_t(y) * uint32_t(view.width) + uint32_t(x));
            const float u1 = unitFloat(hash32(seed ^ 0x9e3779b9u)), u2 = unitFloat(hash32(seed + 0x7f4a7c15u));
            // Malley's method: a uniform disc point lifted to the hemisphere is cosine-distributed.
            const float r = std::sqrt(u1), phi = 6.28318530718f * u2;
            const float lx = r * std::cos(phi), ly = r * std::sin(phi), lz = std::sqrt(std::max(0.0f, 1.0f - u1));
            // Orthonormal basis about n (Duff et al. 2017).
            const float sign = std::copysign(1.0f, n.z), a = -1.0f / (sign + n.z), b = n.x * n.y * a;
            const glm::vec3 t1(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x), t2(b, sign + n.y * n.y * a, -n.y);
            trace::Ray s;
            s.origin = ray.origin + hit->t * ray.dir + ts.epsilon() * n;
            s.dir = glm::normalize(lx * t1 + ly * t2 + lz * n);
            out.push_back(s);
        }
    });
    std::vector<trace::Ray> all;
    for (const std::vector<trace::Ray>& r : rows) all.insert(all.end(), r.begin(), r.end());
    return all;
}

// Runs `perBlock(begin, end)` over [0, n) in blocks of 4,096 on `threads` threads.
void parallelBlocks(size_t n, int threads, const std::function<void(size_t, size_t)>& perBlock) {
    constexpr size_t kBlock = 4096;
    std::atomic<size_t> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (size_t b; (b = next.fetch_add(kBlock)) < n;) perBlock(b, std::min(n, b + kBlock));
        });
    for (std::thread& th : pool) th.join();
}

uint64_t nearestHitsOurs(const trace::TraceScene& ts, const std::vector<trace::Ray>& rays, int threads) {
    std::atomic<uint64_t> hits{0};
    parallelBlocks(rays.size(), threads, [&](size_t b, size_t e) {
        uint64_t h = 0;
        for (size_t i = b; i < e; ++i) h += ts.intersect(rays[i]) ? 1 : 0;
        hits += h;
    });
    return hits;
}

#ifdef SHADELAB_HAVE_EMBREE
uint64_t nearestHitsEmbree(const EmbreeScene& es, const std::vector<trace::Ray>& rays, int threads) {
    std::atomic<uint64_t> hits{0};
    parallelBlocks(rays.size(), threads, [&](size_t b, size_t e) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        uint64_t h = 0;
        for (size_t i = b; i < e; ++i) {
            const trace::Ray& ray = rays[i];
            RTCRayHit rh = embreeRayHit(ray);
            rtcIntersect1(es.scene, &ctx, &rh);
            h += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
        }
        hits += h;
    });
    return hits;
}
#endif

void benchIncoherent(const Options& o) {
    if (!std::filesystem::exists(o.engine)) {
        std::printf("incoherent: %s missing (apt-get install assimp-testmodels); skipped\n", o.engine.c_str());
        return;
    }
    const Scene scene = loadScene(o.engine);
    const trace::TraceScene ts(scene);
    const ViewSetup view = makeViewSetup(ts.scene(), o.width, o.height);
    const std::vector<trace::Ray> rays = secondaryRays(ts, view, o.threads);
#ifdef SHADELAB_HAVE_EMBREE
    std::optional<EmbreeScene> es;
    if (o.embree) es.emplace(scene);
#endif
    // Runs alternate between the two (ours, Embree, ours, ...), so load from other processes hits both alike.
    std::vector<double> ours, theirs, oursCpu, theirsCpu;
    uint64_t hits = 0, eh = 0;
    for (int r = 0; r < o.runs; ++r) {
        auto t0 = Clock::now();
        double c0 = cpuSeconds();
        hits = nearestHitsOurs(ts, rays, o.threads);
        double s = seconds(t0, Clock::now());
        oursCpu.push_back(double(rays.size()) / (cpuSeconds() - c0) * 1e-6);
        ours.push_back(double(rays.size()) / s * 1e-6);
        std::printf("  shadelab run %d: %.3f s, %.2f Mrays/s (%.2f per CPU-second)\n", r + 1, s, ours.back(),
                    oursCpu.back());
#ifdef SHADELAB_HAVE_EMBREE
        if (!es) continue;
        t0 = Clock::now();
        c0 = cpuSeconds();
        eh = nearestHitsEmbree(*es, rays, o.threads);
        s = seconds(t0, Clock::now());
        theirsCpu.push_back(double(rays.size()) / (cpuSeconds() - c0) * 1e-6);
        theirs.push_back(double(rays.size()) / s * 1e-6);
        std::printf("  embree run %d: %.3f s, %.2f Mrays/s (%.2f per CPU-second)\n", r + 1, s, theirs.back(),
                    theirsCpu.back());
#endif
    }
    const double oursMedian = median(ours);
    std::printf("incoherent %dx%d, %d threads: %zu cosine-distributed secondary rays, %llu hit\n", o.width, o.height,
                o.threads, rays.size(), (unsigned long long)hits);
    std::printf("shadelab incoherent (BVH walks: %s): median of %d: %.2f Mrays/s, %.2f Mrays per CPU-second\n",
                trace::bvhIsaName(trace::defaultBvhIsa()), o.runs, oursMedian, median(oursCpu));
    if (theirs.empty()) return;
    const double embreeMedian = median(theirs);
    std::printf("embree incoherent: %llu hit; median of %d: %.2f Mrays/s, %.2f Mrays per CPU-second\n",
                (unsigned long long)eh, o.runs, embreeMedian, median(theirsCpu));
    std::printf("ratio shadelab / embree, incoherent: %.2f (target >= 1.0); per CPU-second %.2f\n",
                oursMedian / embreeMedian, median(oursCpu) / median(theirsCpu));
}

// ---- (d) scale: a generated grid of UV spheres ---------------------------------------------------------

long peakRssKiB() {
    FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return -1;
    char line[256];
    long kib = -1;
    while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, "VmHWM:", 6) == 0) kib = std::atol(line + 6);
    std::fclose(f);
    return kib;
}

void benchScale(const Options& o) {
    auto t0 = Clock::now();
    const Scene scene = sphereGrid(o.grid);
    size_t tris = 0;
    for (const Mesh& m : scene.meshes) tris += m.triangleCount();
    std::printf("scale: %dx%d spheres, %zu triangles, generated in %.3f s, peak RSS so far %.1f MiB\n", o.grid, o.grid,
                tris, seconds(t0, Clock::now()), peakRssKiB() / 1024.0);
    // Builds alternate between the two (ours, Embree, ours, ...), each freed before the next; medians.
    trace::BvhBuildOptions bo;
    bo.threads = o.threads;
    // With --spatial the timed builds are plain (no spatial splits at any size), for the ratio below.
    if (o.spatial) bo.spatialSplitBudget = 0.0f;
    std::shared_ptr<const trace::MeshBvh> mb;
    std::vector<double> ours, theirs, theirsScene, split;
    // --spatial: the default build leaves spatial splits out above kMaxSpatialSplitTriangles; these run them
    // anyway, each run's just before its plain build (the previous tree freed first).
    trace::BvhBuildOptions so = bo;
    so.spatialSplitBudget = trace::BvhBuildOptions{}.spatialSplitBudget;
    so.spatialSplitLimit = SIZE_MAX;
    size_t splitSlots = 0;
#ifdef SHADELAB_HAVE_EMBREE
    std::optional<EmbreeScene> es;
#endif
    // With --spatial, the build with spatial splits goes first in odd runs and second in even ones (after the
    // plain tree is freed): a process's second large build of the same size runs on memory the first handed back,
    // which changes its time by up to a tenth either way.
    auto buildWithSplits = [&](int r) {
        t0 = Clock::now();
        const trace::MeshBvh withSplits(scene, so);
        split.push_back(seconds(t0, Clock::now()));
        splitSlots = withSplits.slotCount();
        std::printf("  shadelab build with spatial splits %d: %.3f s, peak RSS so far %.1f MiB\n", r + 1, split.back(),
                    peakRssKiB() / 1024.0);
        if (r + 1 == o.runs) printTreeStats("scale BVH, spatial splits", withSplits.bvh());
    };
    for (int r = 0; r < o.runs; ++r) {
        mb.reset();
        if (o.spatial && r % 2 == 0) buildWithSplits(r);
        t0 = Clock::now();
        mb = std::make_shared<const trace::MeshBvh>(scene, bo);
        ours.push_back(seconds(t0, Clock::now()));
        std::printf("  shadelab build %d: %.3f s, peak RSS so far %.1f MiB\n", r + 1, ours.back(),
                    peakRssKiB() / 1024.0);
        if (o.spatial && r % 2 == 1) {
            mb.reset();
            buildWithSplits(r);
            mb = std::make_shared<const trace::MeshBvh>(scene, bo);  // for the trace below; not timed
        }
#ifdef SHADELAB_HAVE_EMBREE
        if (!o.embree) continue;
        es.reset();
        t0 = Clock::now();
        es.emplace(scene);
        theirsScene.push_back(seconds(t0, Clock::now()));
        theirs.push_back(es->commitSeconds);
        std::printf("  embree %s build %d: scene %.3f s, of which rtcCommitScene (the BVH build) %.3f s\n",
                    RTC_VERSION_STRING, r + 1, theirsScene.back(), theirs.back());
#endif
    }
    std::printf("shadelab build (MeshBvh, %d threads): median of %d: %.3f s\n", o.threads, o.runs, median(ours));
    printTreeStats("scale BVH", mb->bvh());
    if (o.spatial)
        std::printf(
            "shadelab build with spatial splits: median of %d: %.3f s, %.2f x the plain build's median, %zu "
            "references for %zu triangles\n",
            o.runs, median(split), median(split) / median(ours), splitSlots, size_t(mb->triangleCount()));
    const trace::TraceScene ts(scene, mb);
    const ViewSetup view = makeViewSetup(ts.scene(), o.width, o.height);
    t0 = Clock::now();
    const RayCounts c = traceOurs(ts, view, o.threads);
    const double s = seconds(t0, Clock::now());
    std::printf("shadelab trace %dx%d: %.3f s, %llu primary + %llu shadow rays (%llu occluded), %.2f Mrays/s\n",
                o.width, o.height, s, (unsigned long long)c.primary, (unsigned long long)c.hits,
                (unsigned long long)c.occluded, mraysPerSecond(c, s));
    std::printf("peak RSS: %.1f MiB\n", peakRssKiB() / 1024.0);
#ifdef SHADELAB_HAVE_EMBREE
    if (!es) return;
    t0 = Clock::now();
    const RayCounts e = traceEmbree(*es, scene, ts.epsilon(), view, o.threads);
    const double es2 = seconds(t0, Clock::now());
    std::printf("embree trace: %.3f s, %llu primary + %llu shadow rays (%llu occluded), %.2f Mrays/s\n", es2,
                (unsigned long long)e.primary, (unsigned long long)e.hits, (unsigned long long)e.occluded,
                mraysPerSecond(e, es2));
    std::printf("embree build: median of %d: rtcCommitScene %.3f s, whole scene %.3f s\n", o.runs, median(theirs),
                median(theirsScene));
    std::printf("ratio build shadelab / embree rtcCommitScene: %.2f (target <= 1.0)\n", median(ours) / median(theirs));
#endif
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "trace_bench: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--spheres")
            o.spheres = next();
        else if (a == "--engine")
            o.engine = next();
        else if (a == "--runs")
            o.runs = std::max(1, std::atoi(next().c_str()));
        else if (a == "--threads")
            o.threads = std::max(1, std::atoi(next().c_str()));
        else if (a == "--size") {
            const std::string s = next();
            if (std::sscanf(s.c_str(), "%dx%d", &o.width, &o.height) != 2) return 2;
        } else if (a == "--only") {
            const std::string w = next();
            o.skipSpheres = w != "spheres";
            o.skipEngine = w != "engine";
            o.skipIncoherent = w != "incoherent";
            o.skipScale = w != "scale";
        } else if (a == "--grid")
            o.grid = std::max(1, std::atoi(next().c_str()));
        else if (a == "--spatial")
            o.spatial = true;
        else if (a == "--no-embree")
            o.embree = false;
        else if (a == "--png")
            o.png = next();
        else {
            std::fprintf(stderr,
                         "usage: trace_bench [--only spheres|engine|incoherent|scale] [--runs N] [--threads N]\n"
                         "                   [--size WxH] [--spheres scene.json] [--engine model.glb]\n"
                         "                   [--png spheres.png] [--grid N] [--spatial] [--no-embree]\n");
            return 2;
        }
    }
    std::printf("machine: %u hardware threads\n", std::thread::hardware_concurrency());
    if (!o.skipSpheres) benchSpheres(o);
    if (!o.skipEngine) benchEngine(o);
    if (!o.skipIncoherent) benchIncoherent(o);
    if (!o.skipScale) benchScale(o);
    return 0;
}
