// Tests for the float → 8-bit conversion: the sRGB curve against known values, and the fast table path
// of toImage8 against the exact per-channel encodeChannel for every kind of input.
#include "image/encode.h"

#include "util/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace shadelab;

namespace {

float floatFromBits(uint32_t b) {
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}

// Runs values through toImage8 (three per pixel, alpha set to junk) and compares with encodeChannel.
// Returns the number of mismatches and reports the first few.
size_t countMismatches(const std::vector<float>& values, Encoding e) {
    const int width = 1024;
    const size_t pixels = (values.size() + 2) / 3;
    ImageF img(width, int((pixels + width - 1) / width));
    for (size_t i = 0; i < values.size(); ++i) img.rgba[(i / 3) * 4 + i % 3] = values[i];
    for (size_t p = 0; p < size_t(img.width) * size_t(img.height); ++p) img.rgba[p * 4 + 3] = -7.0f;
    Image8 out = toImage8(img, e, DisplaySettings{}, nullptr);
    EXPECT_EQ(out.channels, 3);
    size_t bad = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        uint8_t want = encodeChannel(values[i], e);
        uint8_t got = out.data[(i / 3) * 3 + i % 3];
        if (got != want && ++bad <= 5)
            ADD_FAILURE() << "value " << values[i] << " (" << toString(e) << "): toImage8 " << int(got)
                          << ", encodeChannel " << int(want);
    }
    return bad;
}

std::vector<float> edgeCases() {
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> v = {0.0f,
                            -0.0f,
                            1.0f,
                            -1.0f,
                            2.0f,
                            inf,
                            -inf,
                            std::nanf(""),
                            -std::nanf(""),
                            std::numeric_limits<float>::min(),
                            std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::max(),
                            0.0031308f,
                            0.5f,
                            0.99999994f,
                            1.0000001f};
    // Every 8-bit code's decision point in both encodings, with neighbours a few ULPs either side.
    for (int k = 0; k < 256; ++k) {
        for (float mid : {srgbToLinear((k + 0.5f) / 255.0f), (k + 0.5f) / 255.0f}) {
            float f = mid;
            for (int i = 0; i < 8; ++i) f = std::nextafter(f, 0.0f);
            for (int i = 0; i < 17; ++i, f = std::nextafter(f, 2.0f)) v.push_back(f);
        }
    }
    return v;
}

}  // namespace

TEST(Encode, SrgbCurveKnownValues) {
    EXPECT_FLOAT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(linearToSrgb(1.0f), 1.0f);
    EXPECT_NEAR(linearToSrgb(0.5f), 0.735356983f, 1e-6);
    EXPECT_NEAR(linearToSrgb(0.18f), 0.461356129f, 1e-6);
    EXPECT_NEAR(linearToSrgb(0.0031308f), 0.04045f, 1e-6);  // the two pieces meet here
    EXPECT_FLOAT_EQ(linearToSrgb(0.001f), 0.01292f);        // linear segment
    for (float x = 0.0f; x <= 1.0f; x += 0.01f) EXPECT_NEAR(srgbToLinear(linearToSrgb(x)), x, 1e-6);
}

TEST(Encode, ChannelRoundsAndClamps) {
    EXPECT_EQ(encodeChannel(0.5f, Encoding::Srgb), 188);
    EXPECT_EQ(encodeChannel(0.18f, Encoding::Srgb), 118);
    EXPECT_EQ(encodeChannel(0.5f, Encoding::Linear), 128);  // 127.5 rounds up
    EXPECT_EQ(encodeChannel(std::nextafter(0.5f / 255.0f, 0.0f), Encoding::Linear), 0);
    EXPECT_EQ(encodeChannel(0.5f / 255.0f, Encoding::Linear), 1);
    for (Encoding e : {Encoding::Srgb, Encoding::Linear}) {
        EXPECT_EQ(encodeChannel(-1.0f, e), 0);
        EXPECT_EQ(encodeChannel(std::nanf(""), e), 0);
        EXPECT_EQ(encodeChannel(-std::nanf(""), e), 0);
        EXPECT_EQ(encodeChannel(1.0f, e), 255);
        EXPECT_EQ(encodeChannel(1e30f, e), 255);
        EXPECT_EQ(encodeChannel(std::numeric_limits<float>::infinity(), e), 255);
    }
    // Every code decodes and re-encodes to itself.
    for (int k = 0; k < 256; ++k) {
        EXPECT_EQ(encodeChannel(srgbToLinear(k / 255.0f), Encoding::Srgb), k);
        EXPECT_EQ(encodeChannel(k / 255.0f, Encoding::Linear), k);
    }
}

TEST(Encode, ChannelIsMonotonic) {
    // The threshold table in toImage8 relies on codes never going down as the input grows.
    for (Encoding e : {Encoding::Srgb, Encoding::Linear}) {
        int last = 0;
        for (uint32_t b = 0; b <= 0x3F800000u; b += 61) {
            int c = encodeChannel(floatFromBits(b), e);
            ASSERT_GE(c, last) << floatFromBits(b);
            last = c;
        }
    }
}

TEST(Encode, TableMatchesExactOnEdgeCases) {
    for (Encoding e : {Encoding::Srgb, Encoding::Linear}) EXPECT_EQ(countMismatches(edgeCases(), e), 0u);
}

TEST(Encode, TableMatchesExactOnRandomFloats) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> wide(-0.25f, 1.25f), unit(0.0f, 1.0f);
    std::uniform_int_distribution<uint32_t> bits;
    std::vector<float> v;
    for (int i = 0; i < 1000000; ++i) {
        switch (i % 4) {
            case 0: v.push_back(wide(rng)); break;
            case 1: v.push_back(unit(rng) * unit(rng) * 0.01f); break;  // dark values, steep part of the curve
            case 2: v.push_back(unit(rng)); break;
            default: v.push_back(floatFromBits(bits(rng))); break;  // anything, NaNs included
        }
    }
    for (Encoding e : {Encoding::Srgb, Encoding::Linear}) EXPECT_EQ(countMismatches(v, e), 0u);
}

TEST(Encode, TableMatchesExactOnStridedFloatsInUnitRange) {
    // Bit patterns 0 .. 1.0f in order, an odd stride so every mantissa pattern class is visited.
    std::vector<float> v;
    for (uint32_t b = 0; b <= 0x3F800000u; b += 101) v.push_back(floatFromBits(b));
    for (uint32_t m = 0; m < (1u << 23); m += 7) v.push_back(floatFromBits(0x3F000000u | m));  // [0.5, 1)
    for (Encoding e : {Encoding::Srgb, Encoding::Linear}) EXPECT_EQ(countMismatches(v, e), 0u);
}

TEST(Encode, ToImage8DropsAlphaAndKeepsLayout) {
    ImageF img(3, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            float* p = img.pixel(x, y);
            p[0] = x / 2.0f, p[1] = y, p[2] = 0.5f, p[3] = 0.25f;
        }
    Image8 out = toImage8(img, Encoding::Linear, DisplaySettings{}, nullptr);
    ASSERT_EQ(out.width, 3);
    ASSERT_EQ(out.height, 2);
    ASSERT_EQ(out.channels, 3);
    ASSERT_EQ(out.data.size(), 18u);
    EXPECT_EQ(out.pixel(1, 0)[0], 128);
    EXPECT_EQ(out.pixel(2, 1)[0], 255);
    EXPECT_EQ(out.pixel(2, 1)[1], 255);
    EXPECT_EQ(out.pixel(0, 0)[1], 0);
    EXPECT_EQ(out.pixel(0, 1)[2], 128);

    Image8 empty = toImage8(ImageF(0, 0), Encoding::Srgb, DisplaySettings{}, nullptr);
    EXPECT_EQ(empty.data.size(), 0u);
}

// No silent black image: every pixel with a NaN or an infinite channel is counted, on one thread and on many
// (a large image converts in parallel), and the count accumulates over calls (strips of one image).
TEST(Encode, ToImage8CountsPixelsWithoutAFiniteValue) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (int side : {4, 1024}) {
        ImageF img(side, side);
        for (float& v : img.rgba) v = 0.5f;
        img.pixel(0, 0)[0] = nan;
        img.pixel(1, 0)[2] = inf;
        img.pixel(side - 1, side - 1)[1] = -inf;
        img.pixel(2, 0)[3] = nan;  // alpha is dropped: not counted
        uint64_t nonFinite = 0;
        const Image8 out = toImage8(img, Encoding::Srgb, DisplaySettings{}, &nonFinite);
        EXPECT_EQ(nonFinite, 3u) << side;
        EXPECT_EQ(out.pixel(0, 0)[0], 0) << "NaN is written black";
        EXPECT_EQ(out.pixel(1, 0)[2], 255) << "+inf is written white";
        toImage8(img, Encoding::Linear, DisplaySettings{}, &nonFinite);
        EXPECT_EQ(nonFinite, 6u) << "counts add up";
        // Negative control: the same image with finite values counts nothing.
        img.pixel(0, 0)[0] = img.pixel(1, 0)[2] = img.pixel(side - 1, side - 1)[1] = 3.4e38f;
        nonFinite = 0;
        toImage8(img, Encoding::Srgb, DisplaySettings{}, &nonFinite);
        EXPECT_EQ(nonFinite, 0u) << side;
    }
    EXPECT_EQ(nonFiniteMessage(3, 16),
              "3 of 16 pixels (19 %) have no finite value (NaN or infinity: an overflow in the scene's numbers) and "
              "are written black (NaN) or white (infinity)");
}

TEST(Encode, ParseEncoding) {
    EXPECT_EQ(parseEncoding("srgb"), Encoding::Srgb);
    EXPECT_EQ(parseEncoding("linear"), Encoding::Linear);
    EXPECT_STREQ(toString(*parseEncoding("srgb")), "srgb");
    EXPECT_STREQ(toString(*parseEncoding("linear")), "linear");
    // image/ knows no flags: a bad word is nullopt, and the CLI words the error (cli_test checks it).
    EXPECT_FALSE(parseEncoding("sRGB2").has_value());
    EXPECT_FALSE(parseEncoding("").has_value());
}

// ---- The display: exposure and view transform (image/view_transform.h) ----------------------------------

namespace {

// A fixed sweep of linear values: [-1, 8) in 2^14 steps, then the edge cases; three per pixel.
ImageF displaySweep() {
    std::vector<float> v;
    for (int i = 0; i < (1 << 14); ++i) v.push_back(-1.0f + 9.0f * float(i) / float(1 << 14));
    for (float e : edgeCases()) v.push_back(e);
    const int width = 256;
    ImageF img(width, int((v.size() / 3 + width) / width));
    for (size_t i = 0; i < v.size(); ++i) img.rgba[(i / 3) * 4 + i % 3] = v[i];
    return img;
}

// FNV-1a over the bytes: a fingerprint of an image to hold against one recorded from older code.
uint64_t fingerprint(const Image8& img) {
    uint64_t h = 1469598103934665603ull;
    for (uint8_t b : img.data) h = (h ^ b) * 1099511628211ull;
    return h;
}

// The fingerprints of displaySweep() through toImage8 before the display existed (the code of the commit
// this feature started from, built and run once), for the sRGB and the linear encoding.
constexpr uint64_t kSweepFingerprintSrgb = 0xbaee2d0731c0b3c7ull;
constexpr uint64_t kSweepFingerprintLinear = 0xf463b8e9c8170e15ull;

// Narkowicz 2016, "ACES Filmic Tone Mapping Curve", written here from the published formula, in double and
// independently of shaders/view_transform.glsl: saturate(x(ax + b) / (x(cx + d) + e)).
double publishedFilmic(double x) {
    const double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    const double y = (x * (a * x + b)) / (x * (c * x + d) + e);
    return std::min(1.0, std::max(0.0, y));
}

}  // namespace

// Standard at 0 stops is today's conversion, byte for byte: the fingerprint of the sweep was recorded with
// the code before exposure and view transforms existed (both encodings), and a display that is anything else
// changes it (negative control).
TEST(EncodeDisplay, StandardIsTodaysBytes) {
    const ImageF img = displaySweep();
    const Image8 srgb = toImage8(img, Encoding::Srgb, DisplaySettings{}, nullptr);
    const Image8 linear = toImage8(img, Encoding::Linear, DisplaySettings{}, nullptr);
    EXPECT_EQ(fingerprint(srgb), kSweepFingerprintSrgb);
    EXPECT_EQ(fingerprint(linear), kSweepFingerprintLinear);
    EXPECT_TRUE(DisplaySettings{}.isStandard());
    for (const DisplaySettings d :
         {DisplaySettings{0.5, ViewTransform::Standard}, DisplaySettings{0.0, ViewTransform::Filmic},
          DisplaySettings{-0.25, ViewTransform::Standard}}) {
        EXPECT_FALSE(d.isStandard());
        EXPECT_NE(fingerprint(toImage8(img, Encoding::Srgb, d, nullptr)), kSweepFingerprintSrgb) << describe(d);
    }
}

// The shared curve (shaders/view_transform.glsl compiled as C++) equals the published formula at fixed inputs,
// and a different curve (Reinhard's x / (1 + x)) is told apart (negative control).
TEST(EncodeDisplay, FilmicIsNarkowiczsPublishedCurve) {
    const DisplaySettings filmic{0.0, ViewTransform::Filmic};
    const double inputs[] = {0.0, 1e-4, 0.01, 0.05, 0.18, 0.5, 1.0, 2.0, 4.0, 7.0, 7.5, 10.0, 100.0, 1e6};
    for (double x : inputs) {
        const double got = displayValue(float(x), filmic), want = publishedFilmic(double(float(x)));
        EXPECT_NEAR(got, want, 1e-6) << "x = " << x;
        EXPECT_GE(got, 0.0);
        EXPECT_LE(got, 1.0);
    }
    // Values written out by hand from the formula: f(1) = 2.54 / 3.16, f(0.18) = 0.059724 / 0.328, f(0) = 0.
    EXPECT_NEAR(displayValue(1.0f, filmic), 2.54 / 3.16, 1e-6);
    EXPECT_NEAR(displayValue(0.18f, filmic), 0.18 * (2.51 * 0.18 + 0.03) / (0.18 * (2.43 * 0.18 + 0.59) + 0.14), 1e-6);
    EXPECT_EQ(displayValue(0.0f, filmic), 0.0f);
    int told = 0;
    for (double x : inputs)
        if (std::abs(displayValue(float(x), filmic) - x / (1.0 + x)) > 1e-3) ++told;
    EXPECT_GE(told, 8) << "Reinhard's curve passed for the filmic one: the test cannot fail";
    // Monotone, and highlights no longer clip at 1: 1, 2 and 4 give three different codes below 255.
    const uint8_t c1 = encodeChannel(1.0f, Encoding::Srgb, filmic), c2 = encodeChannel(2.0f, Encoding::Srgb, filmic),
                  c4 = encodeChannel(4.0f, Encoding::Srgb, filmic);
    EXPECT_LT(c1, c2);
    EXPECT_LT(c2, c4);
    EXPECT_LT(c4, 255);
    EXPECT_EQ(encodeChannel(1.0f, Encoding::Srgb), 255) << "Standard clips 1";
    float previous = -1.0f;
    for (int i = 0; i <= 4000; ++i) {
        const float y = displayValue(float(i) * 0.005f, filmic);
        EXPECT_GE(y, previous) << "at " << float(i) * 0.005f;
        previous = y;
    }
}

// Exposure +1 doubles the linear values before the curve: exactly (a power of two) under Standard, and under
// filmic the curve sees 2x. The bytes of toImage8 at +1 equal those of the doubled image at 0 stops; at 0 they
// do not (negative control).
TEST(EncodeDisplay, ExposurePlusOneDoublesLinearValuesBeforeTheCurve) {
    for (float x : {0.0f, 0.01f, 0.1f, 0.3f, 0.49f, 1.0f, 3.0f}) {
        EXPECT_EQ(displayValue(x, DisplaySettings{1.0, ViewTransform::Standard}), 2.0f * x);
        EXPECT_EQ(displayValue(x, DisplaySettings{-1.0, ViewTransform::Standard}), 0.5f * x);
        EXPECT_EQ(displayValue(x, DisplaySettings{1.0, ViewTransform::Filmic}),
                  displayValue(2.0f * x, DisplaySettings{0.0, ViewTransform::Filmic}));
    }
    EXPECT_EQ((DisplaySettings{3.0, ViewTransform::Standard}.scale()), 8.0f);
    ImageF img = displaySweep(), doubled = img;
    for (float& v : doubled.rgba) v *= 2.0f;
    for (ViewTransform t : {ViewTransform::Standard, ViewTransform::Filmic}) {
        const Image8 a = toImage8(img, Encoding::Srgb, DisplaySettings{1.0, t}, nullptr);
        const Image8 b = toImage8(doubled, Encoding::Srgb, DisplaySettings{0.0, t}, nullptr);
        EXPECT_EQ(a.data, b.data) << toString(t);
        EXPECT_NE(toImage8(img, Encoding::Srgb, DisplaySettings{0.0, t}, nullptr).data, b.data) << toString(t);
    }
}

// toImage8's table path equals the per-channel reference for every display and encoding, NaN and
// infinities included (NaN black, +inf white, under filmic too), on one thread and on many.
TEST(EncodeDisplay, ToImage8EqualsEncodeChannelUnderEveryDisplay) {
    const ImageF small = displaySweep();
    ImageF randomLarge(1024, 512);  // converts on several threads
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-0.5f, 20.0f);
    for (float& v : randomLarge.rgba) v = u(rng);
    const ImageF& large = randomLarge;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const DisplaySettings d :
         {DisplaySettings{0.0, ViewTransform::Filmic}, DisplaySettings{2.5, ViewTransform::Filmic},
          DisplaySettings{-3.0, ViewTransform::Standard}, DisplaySettings{16.0, ViewTransform::Filmic}}) {
        for (Encoding e : {Encoding::Srgb, Encoding::Linear}) {
            for (const ImageF* img : {&small, &large}) {
                const Image8 out = toImage8(*img, e, d, nullptr);
                size_t bad = 0;
                for (size_t p = 0; p < size_t(img->width) * size_t(img->height); ++p)
                    for (size_t c = 0; c < 3; ++c)
                        if (out.data[p * 3 + c] != encodeChannel(img->rgba[p * 4 + c], e, d)) ++bad;
                EXPECT_EQ(bad, 0u) << describe(d) << ", " << toString(e) << ", " << img->width;
            }
            EXPECT_EQ(encodeChannel(nan, e, d), 0) << describe(d);
            EXPECT_EQ(encodeChannel(inf, e, d), 255) << describe(d);
            EXPECT_EQ(encodeChannel(-inf, e, d), 0) << describe(d);
        }
    }
    // The linear encoding after filmic: the curve's value itself, rounded.
    EXPECT_EQ(encodeChannel(1.0f, Encoding::Linear, DisplaySettings{0.0, ViewTransform::Filmic}),
              uint8_t(std::floor(publishedFilmic(1.0) * 255.0 + 0.5)));
}

TEST(EncodeDisplay, NamesAndExposureLimits) {
    EXPECT_EQ(parseViewTransform("standard"), ViewTransform::Standard);
    EXPECT_EQ(parseViewTransform("filmic"), ViewTransform::Filmic);
    EXPECT_STREQ(toString(ViewTransform::Filmic), "filmic");
    EXPECT_FALSE(parseViewTransform("aces").has_value());
    EXPECT_EQ(nameChoices(kViewTransformNames), "standard or filmic");
    for (double ok : {-16.0, -1.5, 0.0, 2.0, 16.0}) EXPECT_FALSE(exposureProblem(ok)) << ok;
    EXPECT_EQ(exposureProblem(40.0).value_or(""), "must be in [-16, 16] stops, got 40");
    EXPECT_EQ(exposureProblem(-16.5).value_or(""), "must be in [-16, 16] stops, got -16.5");
    EXPECT_EQ(exposureProblem(std::nan("")).value_or(""), "must be in [-16, 16] stops, got nan");
    EXPECT_EQ(exposureProblem(INFINITY).value_or(""), "must be in [-16, 16] stops, got inf");
    EXPECT_EQ(describe(DisplaySettings{}), "");
    EXPECT_EQ(describe(DisplaySettings{1.5, ViewTransform::Filmic}), "filmic, +1.5 stops");
    EXPECT_EQ(describe(DisplaySettings{0.0, ViewTransform::Filmic}), "filmic");
    EXPECT_EQ(describe(DisplaySettings{-2.0, ViewTransform::Standard}), "standard, -2 stops");
}
