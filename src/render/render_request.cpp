// The render request's limits and its conversions to each renderer's settings.
#include "render/render_request.h"

#include "compare/comparison.h"
#include "image/image.h"
#include "render/memory_budget.h"
#include "scene/sample_grid.h"
#include "util/check.h"
#include "util/input_error.h"

#include <cstdio>

namespace shadelab::render {
namespace {

std::optional<RequestProblem> problem(const char* field, std::string reason) {
    return RequestProblem{field, std::move(reason)};
}

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

int RenderRequest::samples() const { return spp.value_or(engine == Engine::Path ? kDefaultPathSamples : 1); }

std::optional<RequestProblem> check(const RenderRequest& r) {
    if (r.width < 1 || r.height < 1 || r.width > kMaxImageSide || r.height > kMaxImageSide)
        return problem("size", "each side must be 1.." + std::to_string(kMaxImageSide) + " pixels, got " +
                                   sizeText(r.width, r.height));
    const int spp = r.samples();
    if (r.engine == Engine::Path) {
        if (spp < 1 || spp > trace::kMaxPathSamples)
            return problem("spp", "the path tracer takes 1 to " + std::to_string(trace::kMaxPathSamples) +
                                      " samples per pixel, got " + std::to_string(spp));
    } else {
        try {
            gridSamplesPerSide(spp);
        } catch (const SettingError& e) {
            return problem("spp", e.reason());
        }
    }
    if (r.depth && (*r.depth < 0 || *r.depth > kMaxDepth))
        return problem("depth", "must be in [0, " + std::to_string(kMaxDepth) + "], got " + std::to_string(*r.depth));
    if (r.threads < 0 || r.threads > kMaxThreads)
        return problem("threads", "must be in [0, " + std::to_string(kMaxThreads) + "] (0 = every core), got " +
                                      std::to_string(r.threads));
    const PathOptions& p = r.path;
    if (r.engine != Engine::Path) {
        const char* given = p.timeLimit   ? "time_limit"
                            : p.estimator ? "estimator"
                            : p.part      ? "light_paths"
                            : p.denoise   ? "denoise"
                            : p.sampler   ? "sampler"
                            : p.seed      ? "seed"
                                          : nullptr;
        if (given)
            return problem(given, "is for the path tracer (renderer path), not " + std::string(toString(r.engine)));
    }
    // Not `>= 0`: a limit of 0 (or -0, or a denormal) would reach the path tracer as its "no limit".
    if (p.timeLimit && !(*p.timeLimit >= kMinTimeLimit && *p.timeLimit <= trace::kMaxTimeLimit)) {
        static_assert(kMinTimeLimit == 1e-3 && trace::kMaxTimeLimit == 1e7, "the message below names both");
        char got[32];
        std::snprintf(got, sizeof got, "%g", *p.timeLimit);
        return problem("time_limit",
                       "must be in [0.001, 1e7] seconds (leave it out for no limit), got " + std::string(got));
    }
    if (p.seed && (*p.seed < 0 || *p.seed > kMaxSeed))
        return problem("seed", "must be a whole number from 0 to " + std::to_string(kMaxSeed) + ", got " +
                                   std::to_string(*p.seed));
    if (r.exposure)
        if (std::optional<std::string> why = exposureProblem(*r.exposure)) return problem("exposure", *why);
    if (r.maxMemory) {
        const uint64_t least = minimumRenderBytes(r);
        if (*r.maxMemory < least)
            return problem("max_memory", "must be at least " + memoryText(least, true) + " for a " +
                                             sizeText(r.width, r.height) + " " + toString(r.engine) +
                                             " render, whatever the scene; got " + memoryText(*r.maxMemory));
    }
    return std::nullopt;
}

void require(const RenderRequest& request) {
    if (std::optional<RequestProblem> p = check(request)) throw SettingError(p->field, p->reason);
}

int traceDepth(const RenderRequest& r, const Scene& scene) {
    return r.engine == Engine::Both ? comparisonDepth(scene, r.depth) : r.depth.value_or(scene.maxDepth);
}

DisplaySettings displayOf(const RenderRequest& r, const Scene& scene) {
    DisplaySettings d = scene.display;
    if (r.exposure) d.exposure = *r.exposure;
    if (r.viewTransform) d.transform = *r.viewTransform;
    return d;
}

raster::OffscreenOptions toOffscreen(const RenderRequest& r, const Scene& scene) {
    SHADELAB_DCHECK(!check(r));  // the front end refused a bad request before converting it
    raster::OffscreenOptions o;
    o.width = r.width;
    o.height = r.height;
    o.spp = r.samples();
    o.encoding = r.encoding;
    o.display = displayOf(r, scene);
    o.coverage = r.coverage || r.engine == Engine::Both;
    return o;
}

trace::TraceSettings toTrace(const RenderRequest& r, const Scene& scene) {
    SHADELAB_DCHECK(!check(r));
    trace::TraceSettings s;
    s.width = r.width;
    s.height = r.height;
    s.spp = r.samples();
    s.threads = r.threads;
    s.maxDepth = traceDepth(r, scene);
    s.coverage = r.coverage || r.engine == Engine::Both;
    return s;
}

trace::PathSettings toPath(const RenderRequest& r, const Scene& scene) {
    SHADELAB_DCHECK(!check(r));
    trace::PathSettings s;
    s.width = r.width;
    s.height = r.height;
    s.spp = r.samples();
    s.threads = r.threads;
    s.maxDepth = r.depth.value_or(scene.maxDepth);
    s.coverage = r.coverage;
    s.timeLimit = r.path.timeLimit.value_or(0.0);
    s.estimator = r.path.estimator.value_or(trace::PathEstimator::Mis);
    s.part = r.path.part.value_or(trace::PathPart::All);
    s.denoise = r.path.denoise;
    s.sampler = r.path.sampler.value_or(trace::PathSampler::Sobol);
    s.seed = uint32_t(r.path.seed.value_or(0));
    return s;
}

}  // namespace shadelab::render
