// PathSettings: how the path tracer renders (design.md §8), as a plain struct. The front ends fill it from a
// render request (render/render_request.h); validate() is the path tracer's own guard.
#pragma once

#include "util/name_table.h"

#include <optional>
#include <string_view>

namespace shadelab::trace {

// Which strategies estimate the light of emissive objects and the environment. Point and directional
// lights are always sampled directly (no path can hit them). Every choice converges to the same image;
// only the noise differs (the estimator-agreement tests check it).
enum class PathEstimator { Mis, Bsdf, Light };

inline constexpr EnumName<PathEstimator> kPathEstimatorNames[] = {
    {PathEstimator::Mis, "mis"},
    {PathEstimator::Bsdf, "bsdf"},
    {PathEstimator::Light, "light"},
};

// Which light reaches the image: all of it; the direct part (light that left an emitter and was scattered
// once by a non-mirror surface on its way to the eye, plus what the eye sees of emitters, mirrors and glass
// included: the local model without its ambient term); or the indirect part (scattered twice or more by
// non-mirror surfaces): what the lecture's ambient term stands in for. All = direct + indirect.
enum class PathPart { All, Direct, Indirect };

inline constexpr EnumName<PathPart> kPathPartNames[] = {
    {PathPart::All, "all"},
    {PathPart::Direct, "direct"},
    {PathPart::Indirect, "indirect"},
};

// Where the path tracer's random numbers come from (sample_rng.h): Owen-scrambled Sobol points, stratified
// within each pixel (less noise at equal samples), or independent hashed numbers (plain Monte Carlo, which
// the tests keep as the reference). Both converge to the same image.
enum class PathSampler { Sobol, Independent };

inline constexpr EnumName<PathSampler> kPathSamplerNames[] = {
    {PathSampler::Sobol, "sobol"},
    {PathSampler::Independent, "independent"},
};

inline const char* toString(PathEstimator e) { return nameOf(kPathEstimatorNames, e); }
inline const char* toString(PathPart p) { return nameOf(kPathPartNames, p); }
inline std::optional<PathEstimator> parsePathEstimator(std::string_view s) {
    return lookupName(kPathEstimatorNames, s);
}
inline std::optional<PathPart> parsePathPart(std::string_view s) { return lookupName(kPathPartNames, s); }
inline const char* toString(PathSampler s) { return nameOf(kPathSamplerNames, s); }
inline std::optional<PathSampler> parsePathSampler(std::string_view s) { return lookupName(kPathSamplerNames, s); }

inline constexpr int kMaxPathSamples = 1 << 20;  // samples per pixel
inline constexpr double kMaxTimeLimit = 1e7;     // seconds

struct PathSettings {
    int width = 1280, height = 720;  // pixels, >= 1
    int spp = 16;                    // samples per pixel, >= 1 (any count; Sobol stratifies best at powers of 2)
    int threads = 0;                 // worker threads; 0 = every core
    int maxDepth = -1;               // bounces after the camera hit, >= 0 (0: direct light only); -1 = the scene's
    int rouletteDepth = 3;           // bounces before Russian roulette may end a path, >= 0
    int tileSize = 16;               // tile edge, pixels, >= 1
    double timeLimit = 0.0;          // seconds; > 0: stop after the last whole sample pass that began in time
    uint32_t seed = 0;               // the whole image's random variation (tests use independent seeds)
    bool coverage = false;           // also fill the coverage buffer (first hit of each pixel's centre)
    PathEstimator estimator = PathEstimator::Mis;
    PathPart part = PathPart::All;
    PathSampler sampler = PathSampler::Sobol;
    bool denoise = false;  // pathTraceImage also makes a denoised preview (trace/path/path_denoise.h)
};

// Throws SettingError (a std::invalid_argument, util/input_error.h) naming the field, e.g. "spp: ...".
void validate(const PathSettings& s);

}  // namespace shadelab::trace
