// The denoiser's lanes (image/denoise_kernel.h): N pixels of a row computed together as one GCC vector of
// floats, 4 wide in the x86-64 baseline build (SSE2), 8 in the AVX2 build and 16 in the AVX-512 one, from the
// same text (denoise_builds.h). Every lane computes the same operations in the same order. Internal linkage:
// each including file keeps its own build. Not for other files.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE__)
#include <immintrin.h>
#endif

namespace shadelab::denoise_detail {
namespace {

template <int N>
struct LaneTypes;
template <>
struct LaneTypes<4> {
    typedef float F __attribute__((vector_size(16)));
    typedef int32_t I __attribute__((vector_size(16)));
};
template <>
struct LaneTypes<8> {
    typedef float F __attribute__((vector_size(32)));
    typedef int32_t I __attribute__((vector_size(32)));
};
template <>
struct LaneTypes<16> {
    typedef float F __attribute__((vector_size(64)));
    typedef int32_t I __attribute__((vector_size(64)));
};

template <int N>
struct Lanes {
    using F = typename LaneTypes<N>::F;
    using I = typename LaneTypes<N>::I;

    [[gnu::always_inline]] static F load(const float* p) {
        F v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    [[gnu::always_inline]] static void store(float* p, F v) { std::memcpy(p, &v, sizeof v); }
    [[gnu::always_inline]] static F splat(float v) { return F{} + v; }
    [[gnu::always_inline]] static F abs(F v) { return (F)((I)v & 0x7fffffff); }
    [[gnu::always_inline]] static F min(F a, F b) { return a < b ? a : b; }
    [[gnu::always_inline]] static F max(F a, F b) { return a > b ? a : b; }

    [[gnu::always_inline]] static F sqrt(F v) {
#if defined(__AVX512F__)
        // The masked form: GCC 12's _mm512_sqrt_ps reads an undefined register, which -Wall reports.
        if constexpr (N == 16) return _mm512_mask_sqrt_ps(v, __mmask16(0xffff), v);
#endif
#if defined(__AVX__)
        if constexpr (N == 8) return _mm256_sqrt_ps(v);
#endif
#if defined(__SSE__)
        if constexpr (N == 4) return _mm_sqrt_ps(v);
#endif
        F r;
        for (int l = 0; l < N; ++l) r[l] = std::sqrt(v[l]);
        return r;
    }

    // e^-x for x >= 0, within 8e-5 relative: 2^t with t = −x·log2 e split as i + f, i = trunc(t), f in (−1, 0],
    // 2^f by its cubic minimax polynomial (relative error), scaled by 2^i through the exponent bits. From x = 16
    // on (a weight of 1e-7), and for x not a number, it is 0: smaller weights would only make denormal products
    // (w²·var with a variance near the filter's floor of 1e-20), which cost a hundred cycles each on x86.
    [[gnu::always_inline]] static F expNeg(F x) {
        const I inRange = x < 16.0f;
        const F t = min(x, splat(16.0f)) * -1.44269504f;
        const I i = __builtin_convertvector(t, I);
        const F f = t - __builtin_convertvector(i, F);
        const F p = ((0.0390121117f * f + 0.230069950f) * f + 0.691020429f) * f + 0.999925196f;
        return (F)((I)(p * (F)((i + 127) << 23)) & inRange);
    }
};

}  // namespace
}  // namespace shadelab::denoise_detail
