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

ImageF denoisedImage(const PathRender& render, const SurfacePasses& passes, const DenoiseSettings& settings = {});

}  // namespace shadelab::trace
