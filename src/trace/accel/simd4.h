// F4: four floats in one SSE register, the few operations the BVH builder and its SSE2 box test need.
// x86-64's baseline (SSE2) only, so the binary runs on any x86-64; other targets get a plain-array version
// with the same results (min/max as `a < b ? a : b`, as _mm_min_ps; IEEE add/sub/mul are the same everywhere).
#pragma once

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define SHADELAB_SIMD4_SSE2 1
#endif

namespace shadelab::trace {

// Asks for the cache line at p ahead of use (a hint; nothing on compilers without the builtin).
inline void prefetchLine(const void* p) {
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
}

#ifdef SHADELAB_SIMD4_SSE2

struct F4 {
    __m128 v;
};
inline F4 load4(const float* p) { return {_mm_load_ps(p)}; }  // p 16-byte aligned
inline F4 loadu4(const float* p) { return {_mm_loadu_ps(p)}; }
inline F4 splat4(float x) { return {_mm_set1_ps(x)}; }
inline void store4(float* p, F4 a) { _mm_storeu_ps(p, a.v); }
inline F4 operator+(F4 a, F4 b) { return {_mm_add_ps(a.v, b.v)}; }
inline F4 operator-(F4 a, F4 b) { return {_mm_sub_ps(a.v, b.v)}; }
inline F4 operator*(F4 a, F4 b) { return {_mm_mul_ps(a.v, b.v)}; }
inline F4 min4(F4 a, F4 b) { return {_mm_min_ps(a.v, b.v)}; }
inline F4 max4(F4 a, F4 b) { return {_mm_max_ps(a.v, b.v)}; }
// Lanes 0-2 of a, lane 3 zeroed.
inline F4 keepLanes3(F4 a) { return {_mm_and_ps(a.v, _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1)))}; }
// Bit k set where a[k] <= b[k] (false for NaN).
inline int lessEqualMask(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmple_ps(a.v, b.v)); }
// Lanes truncated toward zero (as int(x) for x in int range).
inline void truncate4(F4 a, int* out) { _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_cvttps_epi32(a.v)); }
// (a1, a2, a0, a3): x y z turned one lane, so a * rotate3(a) is (xy, yz, zx).
inline F4 rotate3(F4 a) { return {_mm_shuffle_ps(a.v, a.v, _MM_SHUFFLE(3, 0, 2, 1))}; }
inline float lane0(F4 a) { return _mm_cvtss_f32(a.v); }
inline F4 set4(float x, float y, float z, float w) { return {_mm_setr_ps(x, y, z, w)}; }
// a with lane `lane` (0-2) replaced by x.
inline F4 withLane(F4 a, int lane, float x) {
    const __m128 m = _mm_castsi128_ps(_mm_set_epi32(0, lane == 2 ? -1 : 0, lane == 1 ? -1 : 0, lane == 0 ? -1 : 0));
    return {_mm_or_ps(_mm_andnot_ps(m, a.v), _mm_and_ps(m, _mm_set1_ps(x)))};
}

#else

struct F4 {
    float v[4];
};
inline F4 load4(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
inline F4 loadu4(const float* p) { return load4(p); }
inline F4 splat4(float x) { return {{x, x, x, x}}; }
inline void store4(float* p, F4 a) {
    for (int k = 0; k < 4; ++k) p[k] = a.v[k];
}
#define SHADELAB_F4_OP(op, expr)                \
    inline F4 op(F4 a, F4 b) {                  \
        F4 r;                                   \
        for (int k = 0; k < 4; ++k) {           \
            const float x = a.v[k], y = b.v[k]; \
            r.v[k] = expr;                      \
        }                                       \
        return r;                               \
    }
SHADELAB_F4_OP(operator+, x + y)
SHADELAB_F4_OP(operator-, x - y)
SHADELAB_F4_OP(operator*, x* y)
SHADELAB_F4_OP(min4, x < y ? x : y)
SHADELAB_F4_OP(max4, x > y ? x : y)
#undef SHADELAB_F4_OP
inline F4 keepLanes3(F4 a) { return {{a.v[0], a.v[1], a.v[2], 0.0f}}; }
inline int lessEqualMask(F4 a, F4 b) {
    int m = 0;
    for (int k = 0; k < 4; ++k) m |= (a.v[k] <= b.v[k] ? 1 : 0) << k;
    return m;
}
inline void truncate4(F4 a, int* out) {
    for (int k = 0; k < 4; ++k) out[k] = int(a.v[k]);
}
inline F4 rotate3(F4 a) { return {{a.v[1], a.v[2], a.v[0], a.v[3]}}; }
inline float lane0(F4 a) { return a.v[0]; }
inline F4 set4(float x, float y, float z, float w) { return {{x, y, z, w}}; }
inline F4 withLane(F4 a, int lane, float x) {
    a.v[lane] = x;
    return a;
}

#endif

}  // namespace shadelab::trace
