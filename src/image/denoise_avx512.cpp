// The denoiser (image/denoise_kernel.h) built for AVX-512 (AVX512F) and FMA, 16 lanes (see
// src/image/CMakeLists.txt); denoise.cpp calls it only on CPUs that have them.
#include "image/denoise_builds.h"
#include "image/denoise_kernel.h"

namespace shadelab::denoise_detail {

ImageF denoiseAvx512(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                     const DenoiseSettings& s, int threads) {
    return denoiseLanes<16>(color, variance, guides, s, threads);
}

}  // namespace shadelab::denoise_detail
