// denoise: checks its input and runs the widest build of the filter this CPU has (image/denoise_builds.h);
// the x86-64 baseline's is built here.
#include "image/denoise.h"

#include "image/denoise_builds.h"
#include "image/denoise_kernel.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <thread>

namespace shadelab {

namespace denoise_detail {

std::vector<DenoiseIsa> denoiseIsas() {
    std::vector<DenoiseIsa> isas{DenoiseIsa::Baseline};
#if defined(SHADELAB_DENOISE_X86_BUILDS)
    __builtin_cpu_init();
    const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) isas.push_back(DenoiseIsa::Avx2);
    if (avx2 && __builtin_cpu_supports("avx512f")) isas.push_back(DenoiseIsa::Avx512);
#endif
    return isas;
}

ImageF denoiseWith(DenoiseIsa isa, const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
                   const DenoiseSettings& s, int threads) {
#if defined(SHADELAB_DENOISE_X86_BUILDS)
    if (isa == DenoiseIsa::Avx512) return denoiseAvx512(color, variance, guides, s, threads);
    if (isa == DenoiseIsa::Avx2) return denoiseAvx2(color, variance, guides, s, threads);
#else
    (void)isa;
#endif
    return denoiseLanes<4>(color, variance, guides, s, threads);
}

}  // namespace denoise_detail

ImageF denoise(const ImageF& color, const std::vector<float>& variance, const SurfacePasses& guides,
               const DenoiseSettings& s) {
    const size_t n = size_t(color.width) * size_t(color.height);
    if (color.rgba.size() != 4 * n || variance.size() != n || guides.width != color.width ||
        guides.height != color.height || guides.albedo.size() != 3 * n || guides.normal.size() != 3 * n ||
        guides.depth.size() != n)
        throw std::invalid_argument("denoise: the colour, variance and passes differ in size");
    if (s.iterations < 1 || s.iterations > 8)
        throw std::invalid_argument("denoise: iterations must be 1 to 8, got " + std::to_string(s.iterations));
    if (!(s.sigmaLuminance > 0.0f) || !(s.sigmaNormal >= 0.0f) || !(s.sigmaDepth > 0.0f) || !(s.sigmaAlbedo > 0.0f))
        throw std::invalid_argument("denoise: the edge-stopping widths must be positive");
    if (n == 0) return color;
    const int threads = s.threads > 0 ? s.threads : std::max(1, int(std::thread::hardware_concurrency()));
    static const denoise_detail::DenoiseIsa widest = denoise_detail::denoiseIsas().back();
    return denoise_detail::denoiseWith(widest, color, variance, guides, s, threads);
}

}  // namespace shadelab
