// The denoiser's passes (image/denoise_kernel.h) built for AVX-512 (AVX512F) and FMA, 16 lanes (see
// src/image/CMakeLists.txt); denoise.cpp calls them only on CPUs that have them.
#include "image/denoise_builds.h"
#include "image/denoise_kernel.h"

namespace shadelab::denoise_detail {

void filterStripAvx512(const DenoiseLayout& layout, const ImageF& color, const std::vector<float>& variance,
                       const DenoiseSettings& s, int strip, int y0, int y1, ImageF& out) {
    filterStrip<16>(layout, color, variance, s, strip, y0, y1, out);
}

}  // namespace shadelab::denoise_detail
