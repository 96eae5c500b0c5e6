// The path tracer's denoised preview: its image through image/denoise.h, guided by the scene's first-hit
// passes (trace/first_hit_passes.h), the noise of each pixel taken from the render's own sample variance.
// A preview only: the probe, the difference view and comparisons read PathRender's raw estimate.
#pragma once

#include "image/denoise.h"
#include "image/surface_passes.h"
#include "trace/path/path_render.h"

#include <vector>

namespace shadelab::trace {

// Per pixel, the variance of the render's luminance estimate: (Σ_c w_c·se_c)², the channels' noise taken
// as fully correlated (one path carries all three), so that no noise is taken for less than it is. A
// pixel with fewer than two samples has no measured noise; it gets the largest variance of the image.
std::vector<float> luminanceVariance(const PathRender& render);

// The noise the filter stops at: each pixel's standard error (the root of `variance`, luminanceVariance's)
// pulled toward the mean of its 3x3 neighbours' by n0 / (n + n0), n its samples. A sample variance of a few
// samples is itself noisy: a pixel whose few samples all missed the rare bright paths reads almost no noise,
// and a filter that believed it would keep that pixel dark and darken the image (measured: 17 % at 4 spp
// with the pixel's own estimate alone). Standard errors, not variances, are averaged, so that one pixel
// half on a lamp does not lend its neighbours its noise; with thousands of samples a pixel's own estimate
// is all that counts.
std::vector<float> stopVariance(const PathRender& render, std::vector<float> variance);

// The preview's filter settings for a render of `samples` per pixel: `settings` with the luminance stop
// scaled by sqrt(kSamplesAtUsualStop / samples), never below kNarrowestStop of it: four times as wide at 4
// samples, half as wide at 256. The noise of a mean of a few path samples is far from normal (most samples
// dark, a few very bright) and its measured variance is itself noisy, so a difference of a few standard
// errors there is not yet an edge, and a narrow stop keeps the dark majority dark (measured on the Cornell
// box, bench/denoise_quality). With many samples every difference the stop lets through is detail, and a
// narrower stop gives a converged image back as it is.
DenoiseSettings previewSettings(int samples, DenoiseSettings settings);
inline constexpr int kSamplesAtUsualStop = 64;
inline constexpr float kNarrowestStop = 0.25f;

// The denoised preview of `render` (trace::luminanceVariance given as `variance`, or computed).
ImageF denoisedImage(const PathRender& render, const std::vector<float>& variance, const SurfacePasses& passes,
                     const DenoiseSettings& settings = {});
ImageF denoisedImage(const PathRender& render, const SurfacePasses& passes, const DenoiseSettings& settings = {});

}  // namespace shadelab::trace
