// Float → 8-bit conversion (design.md §2). encodeChannel is the exact reference; toImage8 gets the
// same answer for every float through a table of the 256 decision thresholds, built from encodeChannel, after
// the display's exposure and view transform (the same float function for both, so the answer stays exact).
#include "image/encode.h"

#include "util/check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>

namespace shadelab {

namespace {

// The view transforms, the text shaders/view_image.frag includes (scalar float only, so no GLM is needed).
namespace view {
#define SL_FN inline
#include "shaders/view_transform.glsl"
#undef SL_FN
}  // namespace view

int transformCode(ViewTransform t) {
    return t == ViewTransform::Filmic ? view::SL_VIEW_FILMIC : view::SL_VIEW_STANDARD;
}

// IEC 61966-2-1 sRGB transfer function, in double so the 8-bit rounding below is decided exactly.
double srgbCurve(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055; }

// NaN and negatives → 0, above 1 → 1. Written so that NaN fails both comparisons.
inline float clamp01(float x) {
    x = x > 0.0f ? x : 0.0f;
    return x < 1.0f ? x : 1.0f;
}

float floatFromBits(uint32_t b) {
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}

// Coarse cells of width 1/kCells. The steepest part of the sRGB curve gains 12.92*255 ≈ 3295 codes per
// unit, below one per cell, so one comparison after the lookup is nearly always the last.
constexpr int kCells = 4096;

// For one encoding: threshold[k] is the smallest float in [0,1] whose code is >= k (threshold[256] is
// above 1), and cellCode[i] is the code at i/kCells. Codes grow with the input, so the code of x is
// the number of thresholds above 0 at or below x.
struct Thresholds {
    float threshold[257];
    uint8_t cellCode[kCells + 1];

    explicit Thresholds(Encoding e) {
        const uint32_t oneBits = 0x3F800000u;  // positive floats order like their bit patterns
        threshold[0] = 0.0f;
        for (int k = 1; k <= 255; ++k) {
            uint32_t lo = 0, hi = oneBits;  // encode(hi) >= k always holds: encode(1) == 255
            while (lo < hi) {
                uint32_t mid = lo + (hi - lo) / 2;
                if (encodeChannel(floatFromBits(mid), e) >= k)
                    hi = mid;
                else
                    lo = mid + 1;
            }
            threshold[k] = floatFromBits(lo);
        }
        threshold[256] = 2.0f;
        for (int i = 0; i <= kCells; ++i) cellCode[i] = encodeChannel(float(i) / float(kCells), e);
    }

    uint8_t code(float linear) const {
        float x = clamp01(linear);
        // x*kCells is exact (power of two), so the cell start i/kCells is at or below x.
        int code = cellCode[int(x * float(kCells))];
        while (x >= threshold[code + 1]) ++code;
        return uint8_t(code);
    }
};

const Thresholds& thresholdsFor(Encoding e) {
    static const Thresholds srgb(Encoding::Srgb);
    static const Thresholds linear(Encoding::Linear);
    return e == Encoding::Srgb ? srgb : linear;
}

struct JoinAll {
    std::vector<std::thread>& pool;
    ~JoinAll() {
        for (auto& t : pool)
            if (t.joinable()) t.join();
    }
};

// `rows` rows of `width` RGBA floats (`srcStride` floats apart) into RGB8 (`dstStride` bytes apart); the pixels
// whose RGB is not all finite are added to `nonFinite` (one sum catches them: NaN or ±inf in any channel makes
// it NaN or ±inf). A display that is not Standard goes through displayValue first; Standard keeps the bare lookup
// (and its speed). The non-finite count reads the raw values either way.
void encodeRows(const float* src, size_t srcStride, uint8_t* dst, size_t dstStride, size_t width, int rows,
                const Thresholds& t, const DisplaySettings& display, uint64_t& nonFinite) {
    const bool standard = display.isStandard();
    const float scale = display.scale();
    const int transform = transformCode(display.transform);
    uint64_t bad = 0;
    for (int y = 0; y < rows; ++y, src += srcStride, dst += dstStride) {
        if (standard) {
            for (size_t x = 0; x < width; ++x) {
                dst[3 * x + 0] = t.code(src[4 * x + 0]);
                dst[3 * x + 1] = t.code(src[4 * x + 1]);
                dst[3 * x + 2] = t.code(src[4 * x + 2]);
                bad += std::isfinite(src[4 * x + 0] + src[4 * x + 1] + src[4 * x + 2]) ? 0 : 1;
            }
        } else {
            for (size_t x = 0; x < width; ++x) {
                for (size_t c = 0; c < 3; ++c)
                    dst[3 * x + c] = t.code(view::viewChannel(src[4 * x + c], scale, transform));
                bad += std::isfinite(src[4 * x + 0] + src[4 * x + 1] + src[4 * x + 2]) ? 0 : 1;
            }
        }
    }
    nonFinite += bad;
}

// Rows [y0, y1) of a whole image.
void encodeImageRows(const ImageF& img, const Thresholds& t, const DisplaySettings& display, Image8& out, int y0,
                     int y1, uint64_t& nonFinite) {
    const size_t w = size_t(img.width);
    encodeRows(img.rgba.data() + size_t(y0) * w * 4, w * 4, out.data.data() + size_t(y0) * w * 3, w * 3, w, y1 - y0, t,
               display, nonFinite);
}

}  // namespace

float linearToSrgb(float linear) { return float(srgbCurve(double(linear))); }

// IEC 61966-2-1 inverse transfer function.
float srgbToLinear(float encoded) {
    double v = encoded;
    return float(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

float displayValue(float linear, const DisplaySettings& display) {
    return view::viewChannel(linear, display.scale(), transformCode(display.transform));
}

uint8_t encodeChannel(float linear, Encoding e, const DisplaySettings& display) {
    return encodeChannel(displayValue(linear, display), e);
}

float displayEncoded(float linear, Encoding e, const DisplaySettings& display) {
    const double x = clamp01(displayValue(linear, display));
    return float(e == Encoding::Srgb ? srgbCurve(x) : x);
}

uint8_t encodeChannel(float linear, Encoding e) {
    double x = clamp01(linear);
    double v = e == Encoding::Srgb ? srgbCurve(x) : x;
    double code = std::floor(v * 255.0 + 0.5);  // round half up
    return uint8_t(std::min(255.0, std::max(0.0, code)));
}

Image8 toImage8(const ImageF& img, Encoding e, const DisplaySettings& display, uint64_t* nonFinite) {
    SHADELAB_CHECK_EQ(img.rgba.size(), size_t(img.width) * size_t(img.height) * 4);
    Image8 out;
    out.width = img.width;
    out.height = img.height;
    out.channels = 3;
    out.data.resize(size_t(img.width) * size_t(img.height) * 3);
    const Thresholds& t = thresholdsFor(e);

    // Threads pay off only above ~100k pixels; each costs tens of microseconds to start.
    const size_t pixels = size_t(img.width) * size_t(img.height);
    int threads = int(std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), 8));
    threads = std::min(threads, std::max(1, int(pixels / 131072)));
    threads = std::min(threads, std::max(1, img.height));
    std::vector<uint64_t> bad(size_t(threads), 0);  // one counter per thread: no sharing, no atomics
    if (threads <= 1) {
        encodeImageRows(img, t, display, out, 0, img.height, bad[0]);
    } else {
        std::vector<std::thread> pool;
        JoinAll joinAll{pool};  // joins even if starting a thread throws
        for (int i = 1; i < threads; ++i) {
            int y0 = int(int64_t(img.height) * i / threads), y1 = int(int64_t(img.height) * (i + 1) / threads);
            pool.emplace_back(encodeImageRows, std::cref(img), std::cref(t), std::cref(display), std::ref(out), y0, y1,
                              std::ref(bad[size_t(i)]));
        }
        encodeImageRows(img, t, display, out, 0, int(int64_t(img.height) / threads), bad[0]);
    }
    if (nonFinite)
        for (uint64_t b : bad) *nonFinite += b;
    return out;
}

void encodeRgbaRows(const float* src, size_t srcStride, uint8_t* dst, size_t dstStride, int width, int rows, Encoding e,
                    const DisplaySettings& display, uint64_t* nonFinite) {
    uint64_t bad = 0;
    encodeRows(src, srcStride, dst, dstStride, size_t(width), rows, thresholdsFor(e), display, bad);
    if (nonFinite) *nonFinite += bad;
}

std::string nonFiniteMessage(uint64_t nonFinite, uint64_t pixels) {
    char share[32];
    std::snprintf(share, sizeof share, "%.2g", pixels ? 100.0 * double(nonFinite) / double(pixels) : 0.0);
    return std::to_string(nonFinite) + " of " + std::to_string(pixels) + " pixels (" + share +
           " %) have no finite value (NaN or infinity: an overflow in the scene's numbers) and are written black "
           "(NaN) or white (infinity)";
}

}  // namespace shadelab
