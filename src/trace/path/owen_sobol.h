// Owen-scrambled Sobol points in four dimensions, the path tracer's low-discrepancy numbers (design.md §8),
// after Burley 2020, "Practical Hash-based Owen Scrambling" (JCGT 9(4)):
// - the first four Sobol dimensions, with the direction numbers of Joe & Kuo 2008 ("Constructing Sobol
//   sequences with better two-dimensional projections", SIAM J. Sci. Comput. 30(5); the table
//   new-joe-kuo-6.21201), derived below from their primitive polynomials and initial numbers;
// - each dimension Owen-scrambled by a hash: a nested uniform scramble flips each bit of a point by a
//   random function of the bits above it, which reversing the bits turns into the Laine–Karras form (bit k
//   depends on bits below k only) that a few multiply-xors by even constants compute (Laine & Karras 2011,
//   "Stratified sampling for stochastic transparency"; Burley's constants);
// - the sample index itself shuffled by the same kind of scramble with its own seed, so that every
//   (pixel, bounce, group) walks the sequence in its own order: groups padded this way are decorrelated,
//   and the first 2^k shuffled indices are still one aligned block of 2^k, whose points are a (0,k,2)-net
//   in the first two dimensions (each 2^-a × 2^-(k−a) interval holds one point) whatever the seeds.
// pbrt-v4's ZSobolSampler and its FastOwenScrambler follow the same ideas (Pharr, Jakob & Humphreys,
// "Physically Based Rendering", 4th ed., §8.7).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec4.hpp>

namespace shadelab::trace {

// Bits in reverse order (bit 0 becomes bit 31).
constexpr uint32_t reverseBits(uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

namespace sobol_detail {

// One Sobol dimension of Joe & Kuo's table: the primitive polynomial x^s + a_1 x^(s−1) + ... + a_(s−1) x + 1
// (`a` holds a_1 .. a_(s−1), a_1 its highest bit) and the initial odd numbers m_1 .. m_s.
struct Polynomial {
    uint32_t s, a;
    uint32_t m[3];
};

// Dimensions 2, 3 and 4 of new-joe-kuo-6.21201 (dimension 1 is van der Corput's: every m_k = 1).
inline constexpr Polynomial kJoeKuo[3] = {{1, 0, {1, 0, 0}}, {2, 1, {1, 3, 0}}, {3, 1, {1, 3, 1}}};

// Direction numbers v_k = m_k / 2^k as 32-bit fractions, v[k] for index bit k, by Bratley & Fox's
// recurrence (ACM TOMS 14(1), 1988): v_k = a_1 v_(k−1) ⊕ ... ⊕ a_(s−1) v_(k−s+1) ⊕ v_(k−s) ⊕ v_(k−s) / 2^s.
constexpr std::array<uint32_t, 32> directions(int dim) {
    std::array<uint32_t, 32> v{};
    if (dim == 0) {
        for (int k = 0; k < 32; ++k) v[size_t(k)] = 1u << (31 - k);
        return v;
    }
    const Polynomial& p = kJoeKuo[dim - 1];
    const int s = int(p.s);
    for (int k = 0; k < 32; ++k) {
        if (k < s) {
            v[size_t(k)] = p.m[k] << (31 - k);
            continue;
        }
        uint32_t x = v[size_t(k - s)] ^ (v[size_t(k - s)] >> s);
        for (int j = 1; j < s; ++j)
            if ((p.a >> (s - 1 - j)) & 1u) x ^= v[size_t(k - j)];
        v[size_t(k)] = x;
    }
    return v;
}

// The four dimensions' bit-reversed Sobol points, by nibbles of the bit-reversed index z:
// table[n][b][d] = XOR over the bits j = 4n + i set in b of reverseBits(v_d[31 − j]). The XOR of eight
// lookups is then reverseBits(Sobol_d(reverseBits(z))) for all four dimensions at once (2 KiB).
struct NibbleTable {
    uint32_t t[8][16][4];
};

constexpr NibbleTable makeNibbleTable() {
    NibbleTable table{};
    for (int d = 0; d < 4; ++d) {
        const std::array<uint32_t, 32> v = directions(d);
        for (int n = 0; n < 8; ++n)
            for (uint32_t b = 0; b < 16; ++b) {
                uint32_t x = 0;
                for (int i = 0; i < 4; ++i)
                    if ((b >> i) & 1u) x ^= reverseBits(v[size_t(31 - (4 * n + i))]);
                table.t[n][b][d] = x;
            }
    }
    return table;
}

inline constexpr NibbleTable kNibbles = makeNibbleTable();

// Laine & Karras's form of a nested uniform scramble on bit-reversed input: each output bit is the input
// bit flipped by a hash of the bits below it and the seed (Burley 2020's constants).
inline glm::uvec4 laineKarras(glm::uvec4 x, glm::uvec4 seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// The same on one lane.
inline uint32_t laineKarras(uint32_t x, uint32_t seed) { return laineKarras(glm::uvec4(x), glm::uvec4(seed)).x; }

inline glm::uvec4 reverseBits(glm::uvec4 x) {
    return {trace::reverseBits(x.x), trace::reverseBits(x.y), trace::reverseBits(x.z), trace::reverseBits(x.w)};
}

}  // namespace sobol_detail

// The nested uniform (Owen) scramble of a 32-bit fraction under `seed`: a permutation of [0, 2^32) that maps
// every aligned interval of 2^k values onto another one.
inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
    return reverseBits(sobol_detail::laineKarras(reverseBits(x), seed));
}

// The first four Sobol dimensions of point `index`, unscrambled, as 32-bit fractions (tests).
inline glm::uvec4 sobolPoint(uint32_t index) {
    glm::uvec4 x(0u);
    for (int d = 0; d < 4; ++d) {
        const std::array<uint32_t, 32> v = sobol_detail::directions(d);
        for (int k = 0; k < 32; ++k)
            if ((index >> k) & 1u) x[d] ^= v[size_t(k)];
    }
    return x;
}

// Point `index` of the Owen-scrambled, index-shuffled four-dimensional Sobol sequence as 32-bit fractions:
// the index is scrambled under `shuffleSeed`, the point's dimension d under dimSeeds[d].
inline glm::uvec4 owenSobol4(uint32_t index, uint32_t shuffleSeed, glm::uvec4 dimSeeds) {
    using namespace sobol_detail;
    // z = reverseBits(shuffled index): the shuffle's last reversal cancels against the lookup's.
    const uint32_t z = laineKarras(reverseBits(index), shuffleSeed);
    glm::uvec4 r(0u);
    for (int n = 0; n < 8; ++n) {
        const uint32_t* e = kNibbles.t[n][(z >> (4 * n)) & 15u];
        r ^= glm::uvec4(e[0], e[1], e[2], e[3]);
    }
    // r holds each dimension bit-reversed, which is the form laineKarras scrambles.
    return sobol_detail::reverseBits(laineKarras(r, dimSeeds));
}

}  // namespace shadelab::trace
