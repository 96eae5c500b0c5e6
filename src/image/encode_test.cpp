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
    Image8 out = toImage8(img, e, nullptr);
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
    Image8 out = toImage8(img, Encoding::Linear, nullptr);
    ASSERT_EQ(out.width, 3);
    ASSERT_EQ(out.height, 2);
    ASSERT_EQ(out.channels, 3);
    ASSERT_EQ(out.data.size(), 18u);
    EXPECT_EQ(out.pixel(1, 0)[0], 128);
    EXPECT_EQ(out.pixel(2, 1)[0], 255);
    EXPECT_EQ(out.pixel(2, 1)[1], 255);
    EXPECT_EQ(out.pixel(0, 0)[1], 0);
    EXPECT_EQ(out.pixel(0, 1)[2], 128);

    Image8 empty = toImage8(ImageF(0, 0), Encoding::Srgb, nullptr);
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
        const Image8 out = toImage8(img, Encoding::Srgb, &nonFinite);
        EXPECT_EQ(nonFinite, 3u) << side;
        EXPECT_EQ(out.pixel(0, 0)[0], 0) << "NaN is written black";
        EXPECT_EQ(out.pixel(1, 0)[2], 255) << "+inf is written white";
        toImage8(img, Encoding::Linear, &nonFinite);
        EXPECT_EQ(nonFinite, 6u) << "counts add up";
        // Negative control: the same image with finite values counts nothing.
        img.pixel(0, 0)[0] = img.pixel(1, 0)[2] = img.pixel(side - 1, side - 1)[1] = 3.4e38f;
        nonFinite = 0;
        toImage8(img, Encoding::Srgb, &nonFinite);
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
