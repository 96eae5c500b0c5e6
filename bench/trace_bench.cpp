// trace_bench: in-process timings for issue 3's tracer benchmarks (a benchmark, never a timed test).
//  (a) bench/spheres40.json at 1920x1080, 1 spp, 2 threads: median of 5 traceImage() calls, plus the
//      in-process end-to-end path (load, trace, 8-bit conversion, PNG encoding) for scale.
//  (b) 2CylinderEngine.glb at 1920x1080, 2 threads: a primary ray per pixel and one shadow ray per hit,
//      in Mrays/s (median of 5); with Embree 3 (optional, SHADELAB_HAVE_EMBREE) the same rays through
//      rtcIntersect1 / rtcOccluded1 and the ratio ours / Embree's. Whole-process timing is bench/trace_spheres.sh.
#include "image/encode.h"
#include "image/png.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "trace/integrator.h"
#include "trace/tile_renderer.h"
#include "trace/trace_image.h"
#include "trace/trace_scene.h"

#ifdef SHADELAB_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

using namespace shadelab;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
    std::string spheres = SHADELAB_SOURCE_DIR "/bench/spheres40.json";
    std::string engine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    int runs = 5, threads = 2, width = 1920, height = 1080;
    bool skipSpheres = false, skipEngine = false;
    std::string png;  // write the spheres image here when set
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

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
        const std::vector<uint8_t> png = encodePng(toImage8(out.color, Encoding::Srgb));
        const auto t3 = Clock::now();
        traceTimes.push_back(seconds(t1, t2));
        totalTimes.push_back(seconds(t0, t3));
        std::printf("  run %d: trace %.3f s, load+trace+encode %.3f s (%zu PNG bytes)\n", r + 1, seconds(t1, t2),
                    seconds(t0, t3), png.size());
        if (r == 0 && !o.png.empty()) writePng(o.png, toImage8(out.color, Encoding::Srgb));
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

// The shadow ray of a hit: from P offset along the geometric normal on the viewer's side, toward light 0.
bool shadowRay(const Scene& scene, glm::vec3 P, glm::vec3 Ng, glm::vec3 dir, float eps, trace::Ray& out, float& tMax) {
    if (glm::dot(Ng, dir) > 0.0f) Ng = -Ng;
    const float len = glm::length(Ng);
    if (!(len > 0.0f) || scene.lights.empty()) return false;
    out.origin = P + eps * (Ng / len);
    const Light& l = scene.lights[0];
    if (l.type == LightType::Point) {
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
    RayCounts total;
    for (const RayCounts& c : perRow) {
        total.primary += c.primary;
        total.hits += c.hits;
        total.occluded += c.occluded;
    }
    return total;
}

#ifdef SHADELAB_HAVE_EMBREE
struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<glm::vec3> normals;  // geometric, per triangle, for the shadow-ray offset

    explicit EmbreeScene(const Scene& s) {
        device = rtcNewDevice(nullptr);
        scene = rtcNewScene(device);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        size_t nv = 0, nt = 0;
        for (const Mesh& m : s.meshes)
            for (const MeshPart& p : m.parts) {
                nv += p.geometry->positions.size();
                nt += p.triangleCount();
            }
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
        size_t vb = 0, ti = 0;
        for (const Mesh& m : s.meshes)
            for (const MeshPart& part : m.parts) {
                const MeshGeometry& p = *part.geometry;
                for (size_t k = 0; k < p.positions.size(); ++k) {
                    v[3 * (vb + k) + 0] = p.positions[k].x;
                    v[3 * (vb + k) + 1] = p.positions[k].y;
                    v[3 * (vb + k) + 2] = p.positions[k].z;
                }
                for (size_t t = 0; t < p.triangleCount(); ++t, ++ti) {
                    for (int c = 0; c < 3; ++c) idx[3 * ti + size_t(c)] = unsigned(vb + p.indices[3 * t + size_t(c)]);
                    const glm::vec3 a = p.positions[p.indices[3 * t]], b = p.positions[p.indices[3 * t + 1]],
                                    c = p.positions[p.indices[3 * t + 2]];
                    normals.push_back(glm::cross(b - a, c - a));
                }
                vb += p.positions.size();
            }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

RayCounts traceEmbree(const EmbreeScene& es, const Scene& scene, float eps, const ViewSetup& view, int threads) {
    std::vector<RayCounts> perRow(size_t(view.height));
    parallelRows(view.height, threads, [&](int y) {
        RayCounts c;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (int x = 0; x < view.width; ++x) {
            const trace::Ray ray = trace::sampleRay(view, 1, x, y, 0, 0);
            ++c.primary;
            RTCRayHit rh{};
            rh.ray.org_x = ray.origin.x;
            rh.ray.org_y = ray.origin.y;
            rh.ray.org_z = ray.origin.z;
            rh.ray.dir_x = ray.dir.x;
            rh.ray.dir_y = ray.dir.y;
            rh.ray.dir_z = ray.dir.z;
            rh.ray.tnear = 0.0f;
            rh.ray.tfar = INFINITY;
            rh.ray.mask = ~0u;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
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
    RayCounts total;
    for (const RayCounts& c : perRow) {
        total.primary += c.primary;
        total.hits += c.hits;
        total.occluded += c.occluded;
    }
    return total;
}
#endif

double mraysPerSecond(const RayCounts& c, double s) { return double(c.primary + c.hits) / s * 1e-6; }

void benchEngine(const Options& o) {
    if (!std::filesystem::exists(o.engine)) {
        std::printf("engine: %s missing (apt-get install assimp-testmodels); skipped\n", o.engine.c_str());
        return;
    }
    const Scene scene = loadScene(o.engine);
    auto t0 = Clock::now();
    const trace::TraceScene ts(scene);
    std::printf("engine: %zu triangles, BVH %zu nodes, depth %d, built in %.1f ms\n", ts.meshBvh()->triangleCount(),
                ts.meshBvh()->bvh().nodes.size(), ts.meshBvh()->bvh().depth, 1e3 * seconds(t0, Clock::now()));
    const ViewSetup view = makeViewSetup(ts.scene(), o.width, o.height);
    std::vector<double> ours;
    RayCounts c;
    for (int r = 0; r < o.runs; ++r) {
        t0 = Clock::now();
        c = traceOurs(ts, view, o.threads);
        const double s = seconds(t0, Clock::now());
        ours.push_back(mraysPerSecond(c, s));
        std::printf("  shadelab run %d: %.3f s, %.2f Mrays/s\n", r + 1, s, ours.back());
    }
    std::printf("engine %dx%d, %d threads: %llu primary + %llu shadow rays (%llu occluded)\n", o.width, o.height,
                o.threads, (unsigned long long)c.primary, (unsigned long long)c.hits, (unsigned long long)c.occluded);
    const double oursMedian = median(ours);
    std::printf("shadelab: median of %d: %.2f Mrays/s\n", o.runs, oursMedian);
#ifdef SHADELAB_HAVE_EMBREE
    t0 = Clock::now();
    const EmbreeScene es(scene);
    std::printf("embree %s: built in %.1f ms\n", RTC_VERSION_STRING, 1e3 * seconds(t0, Clock::now()));
    std::vector<double> theirs;
    RayCounts e;
    for (int r = 0; r < o.runs; ++r) {
        t0 = Clock::now();
        e = traceEmbree(es, scene, ts.epsilon(), view, o.threads);
        const double s = seconds(t0, Clock::now());
        theirs.push_back(mraysPerSecond(e, s));
        std::printf("  embree run %d: %.3f s, %.2f Mrays/s\n", r + 1, s, theirs.back());
    }
    std::printf("embree: %llu primary + %llu shadow rays (%llu occluded)\n", (unsigned long long)e.primary,
                (unsigned long long)e.hits, (unsigned long long)e.occluded);
    const double embreeMedian = median(theirs);
    std::printf("embree: median of %d: %.2f Mrays/s\n", o.runs, embreeMedian);
    std::printf("ratio shadelab / embree: %.2f (target >= 0.5)\n", oursMedian / embreeMedian);
#else
    std::printf("embree: not built (install libembree-dev and reconfigure for the comparison)\n");
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
        } else if (a == "--png")
            o.png = next();
        else {
            std::fprintf(stderr,
                         "usage: trace_bench [--only spheres|engine] [--runs N] [--threads N] [--size WxH]\n"
                         "                   [--spheres scene.json] [--engine model.glb] [--png spheres.png]\n");
            return 2;
        }
    }
    std::printf("machine: %u hardware threads\n", std::thread::hardware_concurrency());
    if (!o.skipSpheres) benchSpheres(o);
    if (!o.skipEngine) benchEngine(o);
    return 0;
}
