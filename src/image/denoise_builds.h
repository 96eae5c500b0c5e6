// The denoiser's builds, one per instruction set: image/denoise_kernel.h instantiated 4 lanes wide for the
// x86-64 baseline (denoise.cpp), 8 for AVX2 + FMA (denoise_avx2.cpp) and 16 for AVX-512 (denoise_avx512.cpp).
// They differ only in rounding where FMA fuses a multiply and an add. denoise() runs the widest this CPU has;
// the tests run each. Not for other files.
#pragma once

#include "image/denoise.h"

#include <vector>

namespace shadelab::denoise_detail {

enum class DenoiseIsa { Baseline, Avx2, Avx512 };

// The builds this binary holds and this CPU runs, narrowest first (the baseline always).
std::vector<DenoiseIsa> denoiseIsas();

// The whole filter in one build, for input denoise() has checked (sizes agree, settings in range, at least
// one pixel) and threads >= 1; `isa` must be one of denoiseIsas().
ImageF denoiseWith(DenoiseIsa isa, const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                   const DenoiseSettings& s, int threads);

// The entry points of the builds other than the baseline (denoise_avx2.cpp, denoise_avx512.cpp).
ImageF denoiseAvx2(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                   const DenoiseSettings& s, int threads);
ImageF denoiseAvx512(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                     const DenoiseSettings& s, int threads);

}  // namespace shadelab::denoise_detail
