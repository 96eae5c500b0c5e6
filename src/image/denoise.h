// denoise: an edge-avoiding à-trous wavelet filter (Dammertz, Sewtz, Hanika & Lensch 2010, "Edge-Avoiding
// À-Trous Wavelet Transform for fast Global Illumination Filtering") for a Monte Carlo estimate, its luminance
// stop scaled by the estimate's own noise as in SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided
// Filtering"). Each of `iterations` passes blends a pixel with its 3x3 neighbours 2^k pixels apart (B-spline
// weights 1/4, 1/2, 1/4), each weighted down by how much it differs in luminance (in standard deviations of
// the noise there), normal, depth (against the plane through the pixel) and albedo; the variance is carried
// through the passes (Σw²·var / (Σw)²), so a pass smooths only what is still noise. A pixel with no noise left
// keeps its value; an edge the passes tell apart is never blurred across. A preview: what is compared (probe,
// difference, compare) is always the raw estimate. Deterministic and the same for any thread count.
//
// Three choices keep it from biasing what it smooths:
// - It filters the linear estimate. A compression such as c / (1 + L) before filtering (and its inverse after)
//   tames a lamp's pixels but darkens noisy ones, since a few bright samples carry much of their light: 8 % of
//   the Cornell box's light at 4 samples a pixel (bench/denoise_quality).
// - The first pass compares the luminance's 3x3 means, not single pixels, against the noise of such a mean:
//   single pixels of a few samples are mostly darker than their mean, and comparing them kept the dark ones
//   dark.
// - Depth is compared as 1/z, which is affine in the image over any plane, against the plane through the pixel
//   (its value plus its gradient times the tap's offset): a wall seen at a grazing angle is smoothed along its
//   depth as much as across it. Comparing depths alone left such walls streaked along the depth's steepest
//   direction.
#pragma once

#include "image/image.h"
#include "image/surface_passes.h"

#include <vector>

namespace shadelab {

struct DenoiseSettings {
    int iterations = 5;           // 1..8 passes: steps 1, 2, 4, 8, 16 pixels, a footprint 63 pixels wide
    float sigmaLuminance = 4.0f;  // luminance differences this many noise standard deviations apart weigh e^-1
    float sigmaNormal = 64.0f;    // e^(-σ·(1 − n·n')): normals 10° apart weigh e^-1
    float sigmaDepth = 1.0f;    // departures from the pixel's plane (in 1/z) of σ times its slope per step weigh e^-1
    float sigmaAlbedo = 0.05f;  // albedo differences (sum over RGB) of this weigh e^-1
    int threads = 0;            // 0: every core
};

// `color`: the estimate, linear RGB (alpha kept). `variance`: per pixel, the variance of the estimate's
// luminance (0: exact); `guides`: the first hit at each pixel, of the same size. A pixel whose colour is
// not finite is left as it is and lends nothing to its neighbours. Throws std::invalid_argument on sizes
// that do not match or settings out of range.
ImageF denoise(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
               const DenoiseSettings& settings = {});

}  // namespace shadelab
