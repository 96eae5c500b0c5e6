// The denoiser (image/denoise_kernel.h) built for AVX2 and FMA, 8 lanes (see src/image/CMakeLists.txt);
// denoise.cpp calls it only on CPUs that have both.
#include "image/denoise_builds.h"
#include "image/denoise_kernel.h"

namespace shadelab::denoise_detail {

ImageF denoiseAvx2(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                   const DenoiseSettings& s, int threads) {
    return denoiseLanes<8>(color, variance, guides, s, threads);
}

}  // namespace shadelab::denoise_detail
