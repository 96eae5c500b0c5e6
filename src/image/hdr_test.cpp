// readHdr / parseHdr: both encodings decode to the same floats, the RGBE arithmetic, and hostile input
// (truncated, huge dimensions, bad header, bad runs) is refused with one line naming the file.
#include "image/hdr.h"

#include "util/input_error.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace shadelab;

namespace {

std::string header(int w, int h) {
    return "#?RADIANCE\n# made by hdr_test\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " +
           std::to_string(w) + "\n";
}

// RGBE of pixel (x, y) of the test pattern: varied mantissas and exponents, some black, a flat run.
void pixel(int x, int y, unsigned char* p) {
    p[0] = (unsigned char)(x * 7 + y);
    p[1] = (unsigned char)(x < 5 ? 200 : 17 * y);
    p[2] = (unsigned char)(x + 3 * y);
    p[3] = (unsigned char)((x + y) % 5 == 0 ? 0 : 120 + (x % 12));
}

std::string flatFile(int w, int h) {
    std::string s = header(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            unsigned char p[4];
            pixel(x, y, p);
            s.append(reinterpret_cast<char*>(p), 4);
        }
    return s;
}

// New-style run-length scanlines: a run wherever two or more bytes repeat, else literals.
std::string rleFile(int w, int h) {
    std::string s = header(w, h);
    for (int y = 0; y < h; ++y) {
        s += char(2);
        s += char(2);
        s += char(w >> 8);
        s += char(w & 255);
        for (int c = 0; c < 4; ++c) {
            std::vector<unsigned char> plane(static_cast<size_t>(w), 0);
            for (int x = 0; x < w; ++x) {
                unsigned char p[4];
                pixel(x, y, p);
                plane[size_t(x)] = p[c];
            }
            int x = 0;
            while (x < w) {
                int run = 1;
                while (x + run < w && run < 127 && plane[size_t(x + run)] == plane[size_t(x)]) ++run;
                if (run >= 2) {
                    s += char(128 + run);
                    s += char(plane[size_t(x)]);
                    x += run;
                } else {
                    int lit = 1;
                    while (x + lit < w && lit < 128 &&
                           !(x + lit + 1 < w && plane[size_t(x + lit)] == plane[size_t(x + lit + 1)]))
                        ++lit;
                    s += char(lit);
                    for (int k = 0; k < lit; ++k) s += char(plane[size_t(x + k)]);
                    x += lit;
                }
            }
        }
    }
    return s;
}

void expectRefused(const std::string& bytes, const std::string& what) {
    try {
        parseHdr(bytes, "env.hdr");
        ADD_FAILURE() << "accepted " << what;
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("env.hdr: ", 0), 0u) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

}  // namespace

TEST(Hdr, FlatAndRunLengthDecodeAlike) {
    const HdrImage flat = parseHdr(flatFile(40, 6), "flat.hdr");
    const HdrImage rle = parseHdr(rleFile(40, 6), "rle.hdr");
    ASSERT_EQ(flat.width, 40);
    ASSERT_EQ(flat.height, 6);
    EXPECT_EQ(flat.rgb, rle.rgb);
    // Negative control: another pattern differs.
    const HdrImage other = parseHdr(flatFile(40, 6).replace(header(40, 6).size() + 4, 1, "\x05"), "other.hdr");
    EXPECT_NE(other.rgb, flat.rgb);
}

TEST(Hdr, RgbeArithmetic) {
    std::string s = header(2, 1);
    const unsigned char px[8] = {128, 64, 255, 129, 10, 20, 30, 0};  // 1, 0.5, 1.99; black
    s.append(reinterpret_cast<const char*>(px), 8);
    const HdrImage img = parseHdr(s, "a.hdr");
    EXPECT_EQ(img.rgb[0], 1.0f);
    EXPECT_EQ(img.rgb[1], 0.5f);
    EXPECT_EQ(img.rgb[2], 255.0f / 128.0f);
    EXPECT_EQ(img.rgb[3], 0.0f);
    EXPECT_EQ(img.rgb[5], 0.0f);
}

TEST(Hdr, HostileInputIsRefusedInOneLine) {
    const std::string good = rleFile(16, 4);
    expectRefused("", "an empty file");
    expectRefused("P6\n1 1\n255\nabc", "a PPM");
    expectRefused("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", "a header without its blank line");
    expectRefused("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\nabcd", "XYZE");
    expectRefused("#?RADIANCE\n\n+Y 1 +X 1\nabcd", "a flipped orientation");
    expectRefused("#?RADIANCE\n\n-Y 1 +X\n", "a short resolution line");
    expectRefused(header(100000, 1), "a huge width");
    expectRefused(header(16000, 16000), "too many pixels");
    expectRefused(header(0, 5), "a zero width");
    expectRefused(header(-3, 5), "a negative width");
    expectRefused(good.substr(0, good.size() - 3), "a truncated run-length file");
    expectRefused(flatFile(5, 5).substr(0, header(5, 5).size() + 50), "a truncated flat file");
    std::string badRun = header(16, 1) + std::string("\x02\x02\x00\x10", 4) + std::string(1, char(128 + 40)) + "x";
    expectRefused(badRun, "a run past the scanline");
    std::string zeroRun = header(16, 1) + std::string("\x02\x02\x00\x10", 4) + std::string(1, '\0');
    expectRefused(zeroRun, "a zero-length literal");
    std::string wrongWidth = header(16, 1) + std::string("\x02\x02\x00\x11", 4);
    expectRefused(wrongWidth, "a scanline of the wrong width");
}

TEST(Hdr, ReadHdrNamesTheMissingFile) {
    try {
        readHdr("/nonexistent/sky.hdr");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/sky.hdr"), std::string::npos);
    }
}
