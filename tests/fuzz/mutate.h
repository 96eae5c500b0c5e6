// The standalone driver's mutations: what libFuzzer's default mutators do to bytes (flips, inserts, deletions,
// crossover with another input), plus one aimed at the text formats: replacing a number with a hostile one
// (1e308, -0, 3e38, 1e-45, integers past 64 bits, NaN-like tokens) that a reader must narrow, clamp or refuse.
// Deterministic for a given Rng state, so a fixed seed replays the same cases.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace shadelab::fuzz {

// SplitMix64 (Steele, Lea & Flood 2014): small, fast and the same on every platform, unlike std:: engines'
// distributions.
class Rng {
public:
    explicit Rng(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, n); n > 0.
    size_t below(size_t n) { return size_t(next() % n); }

private:
    uint64_t state_;
};

// The numbers the number mutation writes, as text.
const std::vector<std::string>& hostileNumbers();

// One to four stacked mutations of `base` (number replacement most often when it is text); `others` (the pool, `base`
// may be among them) feeds the splices. The result is at most maxLen bytes.
std::string mutate(const std::string& base, const std::vector<std::string>& others, size_t maxLen, Rng& rng);

}  // namespace shadelab::fuzz
