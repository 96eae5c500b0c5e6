// RenderRequest: one render, as every front end asks for it: the command line (`shadelab render`), Python
// (`shadelab.render`), the viewer's background renderers and its scripts. It holds the engine, size, samples,
// depth, threads, coverage, encoding, the display (exposure and view transform), the path tracer's options and the
// memory limit; check() is the one place a request is held to its limits, and the to*() conversions are the one place
// it becomes each renderer's settings. A problem is named by its field ("spp", "size", ...); each front end words it
// its own way (`--spp:
// ...` in the CLI, `spp: ...` in Python, `actions[3].spp: ...` in a script). Plain data: no GL, nothing
// rendered here; the memory estimate the limit is compared with is render/memory_budget.h.
#pragma once

#include "image/encoding.h"
#include "image/view_transform.h"
#include "raster/offscreen_options.h"
#include "scene/scene.h"
#include "trace/path/path_settings.h"
#include "trace/trace_settings.h"
#include "util/name_table.h"

#include <cstdint>
#include <optional>
#include <string>

namespace shadelab::render {

// Which renderer draws the image. Both: the rasterizer and the Whitted reference side by side, traced at the
// comparison's depth (compare/comparison.h).
enum class Engine { Raster, Trace, Both, Path };

// The words of `--renderer` and of render(renderer=...).
inline constexpr EnumName<Engine> kEngineNames[] = {
    {Engine::Raster, "raster"},
    {Engine::Trace, "trace"},
    {Engine::Both, "both"},
    {Engine::Path, "path"},
};

inline const char* toString(Engine e) { return nameOf(kEngineNames, e); }

// The limits of a request; the image side is kMaxImageSide (image/image.h), the grid's samples
// kMaxGridSamples (scene/sample_grid.h), the path tracer's kMaxPathSamples and kMaxTimeLimit
// (trace/path/path_settings.h).
inline constexpr int kMaxDepth = 64;
inline constexpr int kMaxThreads = 1024;
inline constexpr int kDefaultPathSamples = 16;
// The shortest time limit a request may give, seconds. The path tracer reads a time limit of 0 as none, so
// 0, -0 and 1e-300 would each silently mean "no limit"; a limit is absent or at least this.
inline constexpr double kMinTimeLimit = 1e-3;
// The path tracer's seeds: every 32-bit value (trace::SampleRng keys its numbers by it). 0, the default, is the
// image every earlier release rendered.
inline constexpr int64_t kMaxSeed = 4294967295;

// The path tracer's options; set only for Engine::Path (check() refuses them elsewhere).
struct PathOptions {
    std::optional<double> timeLimit;                // seconds, kMinTimeLimit..kMaxTimeLimit; stop at the last
                                                    // whole pass begun in time; unset: no limit
    std::optional<trace::PathEstimator> estimator;  // unset: mis
    std::optional<trace::PathPart> part;            // which light reaches the image; unset: all
    std::optional<trace::PathSampler> sampler;      // where the random numbers come from; unset: sobol
    std::optional<int64_t> seed;                    // the random numbers' variation, 0..kMaxSeed; unset: 0
    bool denoise = false;                           // show the denoised preview instead of the raw estimate
};

struct RenderRequest {
    Engine engine = Engine::Raster;
    int width = 1280, height = 720;      // pixels, 1..kMaxImageSide each
    std::optional<int> spp;              // unset: 1 on the grid (k², scene/sample_grid.h), 16 for the path tracer
    std::optional<int> depth;            // secondary-ray depth / bounces, 0..64; unset: the scene's maxDepth
    int threads = 0;                     // tracer workers, 0..kMaxThreads; 0 = every core
    bool coverage = false;               // also the coverage ids of each pixel (Both always has them)
    Encoding encoding = Encoding::Srgb;  // how the linear image becomes 8-bit
    // The display the 8-bit image is encoded with (image/view_transform.h); each unset field is the scene's
    // (its "display"), so a front end sets only what its user gave: the CLI's flags override the file.
    std::optional<double> exposure;  // stops, kMinExposure..kMaxExposure
    std::optional<ViewTransform> viewTransform;
    PathOptions path;
    // The most memory the render may take, bytes (render/memory_budget.h: compared with its estimate before
    // any pixel is drawn, and the environment map's load with it); unset: defaultMaxMemory(), half of
    // physical memory. check() refuses a limit below what any render of this request needs.
    std::optional<uint64_t> maxMemory;

    // The samples per pixel this request renders with: spp, or the engine's default.
    int samples() const;
};

// A request's field and why it cannot be rendered. Fields: "size", "spp", "depth", "threads",
// "time_limit", "estimator", "light_paths", "sampler", "seed", "denoise", "max_memory", "exposure".
struct RequestProblem {
    std::string field;
    std::string reason;
};

// The first problem of a request, or none.
std::optional<RequestProblem> check(const RenderRequest& request);

// Throws SettingError (util/input_error.h) with check()'s field and reason.
void require(const RenderRequest& request);

// The Whitted tracer's depth: the request's, else the scene's; for Engine::Both, the comparison's.
int traceDepth(const RenderRequest& request, const Scene& scene);

// The display the request's pixels are encoded with: its exposure and view transform, each the scene's where
// unset. Every 8-bit conversion of a request's image (toImage8) is given this.
DisplaySettings displayOf(const RenderRequest& request, const Scene& scene);

// The settings each renderer takes for this request (require() it first: they assume a valid request).
raster::OffscreenOptions toOffscreen(const RenderRequest& request, const Scene& scene);
trace::TraceSettings toTrace(const RenderRequest& request, const Scene& scene);
trace::PathSettings toPath(const RenderRequest& request, const Scene& scene);

}  // namespace shadelab::render
