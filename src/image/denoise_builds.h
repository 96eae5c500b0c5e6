// The denoiser's builds, one per instruction set: the passes (image/denoise_kernel.h, filterStrip) 4 lanes
// wide for the x86-64 baseline (denoise.cpp), 8 for AVX2 + FMA (denoise_avx2.cpp) and 16 for AVX-512
// (denoise_avx512.cpp). They differ only in rounding where FMA fuses a multiply and an add. denoise() runs
// the widest this CPU has; the tests run each. Not for other files.
#pragma once

#include "image/denoise.h"
#include "image/denoise_layout.h"

#include <vector>

namespace shadelab::denoise_detail {

enum class DenoiseIsa { Baseline, Avx2, Avx512 };

// The builds this binary holds and this CPU runs, narrowest first (the baseline always).
std::vector<DenoiseIsa> denoiseIsas();

// The whole filter in one build, for input denoise() has checked (sizes agree, settings in range, at least
// one pixel) and threads >= 1; `isa` must be one of denoiseIsas().
ImageF denoiseWith(DenoiseIsa isa, const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                   const DenoiseSettings& s, int threads);

// Every pass over rows y0 .. y1 − 1 of `out`, in strip `strip` of the layout (denoise_kernel.h, filterStrip),
// as each build compiles it; the AVX2 and AVX-512 ones exist on x86-64 only.
using StripFilter = void (*)(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                             const DenoiseSettings& s, int strip, int y0, int y1, ImageF& out);
void filterStripAvx2(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                     const DenoiseSettings& s, int strip, int y0, int y1, ImageF& out);
void filterStripAvx512(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                       const DenoiseSettings& s, int strip, int y0, int y1, ImageF& out);

}  // namespace shadelab::denoise_detail
