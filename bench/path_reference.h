// PathReference: a path-traced reference image with the variance of each pixel's estimate, rendered once and
// cached on disk as OpenEXR, so that error benchmarks need neither a 4096-spp render per run nor to ignore the
// reference's own noise (image_error.h removes it). Bench-only.
//
// Two ways to know that noise (ReferenceMethod):
// - SampleVariance: one render with the independent sampler; each pixel's sample variance over its sample
//   count estimates the variance of its mean without bias (Sobol's stratified samples err less than their
//   sample variance says, design.md §8, so Sobol cannot be used this way).
// - SplitHalves: two renders of half the samples with the default Sobol sampler and independent seeds, A and
//   B; the reference is (A + B) / 2 and |A − B|² / 4 its variance, since E|A − B|² = 2 Var(A) for any
//   sampler. Better still, |(A + B)/2 − μ|² and |A − B|² / 4 share the same a² + b² (a = A − μ, b = B − μ)
//   and differ only by the cross term ab: a firefly in one half is cancelled where it lands, not just on
//   average.
// The seeds keep the reference independent of the images measured against it (seed 0). The cache file is
// keyed by the scene file's bytes, the method, size, spp, depth and seed, and the bytes of the libraries that
// draw the image (SHADELAB_BENCH_LIBS, set by bench/CMakeLists.txt): a rebuilt path tracer renders a new one.
#pragma once

#include "bench_timing.h"
#include "image/exr.h"
#include "trace/path/path_render.h"
#include "util/read_file.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab::bench {

enum class ReferenceMethod { SampleVariance, SplitHalves };

inline const char* toString(ReferenceMethod m) {
    return m == ReferenceMethod::SampleVariance ? "sample-variance" : "split-halves";
}

struct PathReference {
    ImageF image;                 // the mean, linear RGB
    std::vector<float> variance;  // 3 per pixel (RGB): the variance of that mean, standardError²
    int spp = 0;
};

// FNV-1a, 64 bits (Fowler, Noll, Vo): enough to tell two versions of a file apart, not a digest.
inline uint64_t fnv1a(const std::string& bytes, uint64_t h = 1469598103934665603ull) {
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    return h;
}

// The hash of the library files named in SHADELAB_BENCH_LIBS (':'-separated paths, as in PATH).
inline uint64_t buildHash() {
    uint64_t h = fnv1a("");
    std::stringstream libs(SHADELAB_BENCH_LIBS);
    for (std::string path; std::getline(libs, path, ':');)
        if (!path.empty()) h = fnv1a(readFile(path, uint64_t(1) << 31), h);
    return h;
}

// The reference (A + B) / 2 of two independent estimates of the same image, its variance |A − B|² / 4.
inline PathReference splitHalves(const ImageF& a, const ImageF& b) {
    PathReference ref;
    ref.image = ImageF(a.width, a.height);
    ref.variance.resize(size_t(3) * size_t(a.width) * size_t(a.height));
    for (size_t i = 0, p = 0; i < a.rgba.size(); i += 4, ++p) {
        for (size_t c = 0; c < 3; ++c) {
            const float d = a.rgba[i + c] - b.rgba[i + c];
            ref.image.rgba[i + c] = 0.5f * (a.rgba[i + c] + b.rgba[i + c]);
            ref.variance[3 * p + c] = 0.25f * d * d;
        }
        ref.image.rgba[i + 3] = 1.0f;
    }
    return ref;
}

inline ImageF renderImage(const std::shared_ptr<const trace::TraceScene>& scene, const trace::PathSettings& s,
                          std::vector<float>* variance = nullptr) {
    trace::PathRender render(scene, s);
    render.addSamples(s.spp);
    if (variance) {
        variance->resize(size_t(3) * size_t(s.width) * size_t(s.height));
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x) {
                const glm::vec3 se = render.standardError(x, y);
                for (int c = 0; c < 3; ++c)
                    (*variance)[3 * (size_t(y) * size_t(s.width) + size_t(x)) + size_t(c)] = se[c] * se[c];
            }
    }
    return render.image();
}

// `s.spp` samples in all (SplitHalves: two renders of s.spp / 2, seeds s.seed and s.seed + 1).
inline PathReference renderReference(const std::shared_ptr<const trace::TraceScene>& scene, trace::PathSettings s,
                                     ReferenceMethod method) {
    PathReference ref;
    ref.spp = s.spp;
    if (method == ReferenceMethod::SampleVariance) {
        s.sampler = trace::PathSampler::Independent;
        ref.image = renderImage(scene, s, &ref.variance);
        return ref;
    }
    s.sampler = trace::PathSampler::Sobol;
    s.spp /= 2;
    const ImageF a = renderImage(scene, s);
    s.seed += 1;
    ref = splitHalves(a, renderImage(scene, s));
    ref.spp = 2 * s.spp;
    return ref;
}

// The reference of `scenePath` under `s` (s.spp samples in all, s.seed the first seed), read from `cacheDir`
// when there, else rendered (its time printed) and written there. An empty `cacheDir` renders without caching.
inline PathReference cachedReference(const std::string& scenePath,
                                     const std::shared_ptr<const trace::TraceScene>& scene, trace::PathSettings s,
                                     ReferenceMethod method, const std::string& cacheDir) {
    if (s.maxDepth < 0) s.maxDepth = scene->scene().maxDepth;
    char key[200];
    std::snprintf(key, sizeof key, "%s-%s-%dx%d-%dspp-depth%d-seed%u-%016llx.exr",
                  std::filesystem::path(scenePath).stem().string().c_str(), toString(method), s.width, s.height, s.spp,
                  s.maxDepth, unsigned(s.seed), (unsigned long long)(fnv1a(readFile(scenePath)) ^ buildHash()));
    const std::string file = cacheDir.empty() ? std::string() : cacheDir + "/" + key;
    if (!file.empty() && std::filesystem::exists(file)) {
        const ExrImage exr = readExr(file);
        const ExrLayer* var = exr.layer("variance");
        if (exr.width == s.width && exr.height == s.height && var && var->channels.size() == 3) {
            std::printf("reference: %s (cached)\n", file.c_str());
            return {colourOf(exr, file), var->samples, s.spp};
        }
    }
    const Clock::time_point t0 = Clock::now();
    PathReference ref = renderReference(scene, s, method);
    std::printf("reference: %dx%d, %d spp (%s, seed %u) rendered in %.1f s\n", s.width, s.height, s.spp,
                toString(method), unsigned(s.seed), msSince(t0) / 1000.0);
    if (!file.empty()) {
        std::filesystem::create_directories(cacheDir);
        ExrImage exr = exrFromImage(ref.image);
        exr.layers.push_back({"variance", {"R", "G", "B"}, ref.variance});
        writeExr(file, exr, ExrPrecision::Float);
        std::printf("reference: cached as %s\n", file.c_str());
    }
    std::fflush(stdout);
    return ref;
}

}  // namespace shadelab::bench
