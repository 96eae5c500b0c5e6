// The denoiser's row pass built for AVX2 and FMA (see src/image/CMakeLists.txt); denoise.cpp calls it only on
// CPUs that have both.
#include "image/denoise_row.h"

namespace shadelab::denoise_detail {

void filterRowAvx2(const Planes& in, const Guides& g, const std::vector<float>& lum, const std::vector<float>& varBlur,
                   const DenoiseSettings& s, int step, int y, Planes& out) {
    filterRowIn(in, g, lum, varBlur, s, step, y, out);
}

}  // namespace shadelab::denoise_detail
