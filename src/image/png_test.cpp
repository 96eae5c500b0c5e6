// Tests for the PNG writer and reader: round trips through stb_image and through a strict decoder here
// (chunk CRCs, zlib Adler-32, filters), grey expansion, and errors that name the file.
#include "image/png.h"

#include "image/encode.h"
#include "util/atomic_file.h"
#include "util/input_error.h"

#include <gtest/gtest.h>
#include <stb_image.h>
#include <zlib.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

std::string outPath(const std::string& name) {
    fs::path dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "png";
    fs::create_directories(dir);
    return (dir / name).string();
}

uint32_t getU32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

void putU32(std::vector<uint8_t>& out, uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(uint8_t(v >> s));
}

void putChunk(std::vector<uint8_t>& out, const char* type, const std::vector<uint8_t>& data) {
    putU32(out, uint32_t(data.size()));
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type), 4);
    if (!data.empty()) crc = crc32(crc, data.data(), uInt(data.size()));  // a null buffer would reset the CRC to 0
    putU32(out, uint32_t(crc));
}

// A deliberately independent PNG writer for fixtures encodePng cannot make (grey, grey+alpha).
std::vector<uint8_t> makePng(int w, int h, int colourType, int channels, const std::vector<uint8_t>& pixels) {
    std::vector<uint8_t> raw;
    for (int y = 0; y < h; ++y) {
        raw.push_back(0);
        raw.insert(raw.end(), pixels.begin() + y * w * channels, pixels.begin() + (y + 1) * w * channels);
    }
    std::vector<uint8_t> z(compressBound(uLong(raw.size())));
    uLongf zlen = z.size();
    EXPECT_EQ(compress(z.data(), &zlen, raw.data(), uLong(raw.size())), Z_OK);
    z.resize(zlen);
    std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}, ihdr;
    putU32(ihdr, uint32_t(w));
    putU32(ihdr, uint32_t(h));
    ihdr.insert(ihdr.end(), {8, uint8_t(colourType), 0, 0, 0});
    putChunk(out, "IHDR", ihdr);
    putChunk(out, "IDAT", z);
    putChunk(out, "IEND", {});
    return out;
}

// Strict decoder for what encodePng writes: checks every CRC, the zlib stream (uncompress verifies the
// Adler-32), the filtered length, and that IEND ends the file. stb_image checks none of these.
Image8 strictDecode(const std::vector<uint8_t>& png) {
    Image8 img;
    const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    EXPECT_TRUE(png.size() >= 8 && std::memcmp(png.data(), sig, 8) == 0);
    std::vector<uint8_t> idat;
    size_t pos = 8;
    bool ended = false;
    while (pos + 12 <= png.size() && !ended) {
        const uint32_t len = getU32(&png[pos]);
        const std::string type(reinterpret_cast<const char*>(&png[pos + 4]), 4);
        EXPECT_LE(pos + 12 + len, png.size());
        const uint8_t* data = &png[pos + 8];
        EXPECT_EQ(crc32(0L, &png[pos + 4], len + 4), getU32(data + len)) << type << " CRC";
        if (type == "IHDR") {
            EXPECT_EQ(len, 13u);
            img.width = int(getU32(data));
            img.height = int(getU32(data + 4));
            EXPECT_EQ(data[8], 8);
            img.channels = data[9] == 6 ? 4 : 3;
        } else if (type == "IDAT") {
            idat.insert(idat.end(), data, data + len);
        }
        ended = type == "IEND";
        pos += 12 + len;
    }
    EXPECT_TRUE(ended);
    EXPECT_EQ(pos, png.size()) << "bytes after IEND";

    const size_t rowBytes = size_t(img.width) * size_t(img.channels), bpp = size_t(img.channels);
    std::vector<uint8_t> raw((rowBytes + 1) * size_t(img.height) + 1);  // +1: must come out exactly short
    uLongf rawLen = raw.size();
    EXPECT_EQ(uncompress(raw.data(), &rawLen, idat.data(), uLong(idat.size())), Z_OK);
    EXPECT_EQ(rawLen, raw.size() - 1);
    img.data.assign(rowBytes * size_t(img.height), 0);
    for (int y = 0; y < img.height; ++y) {
        const uint8_t* in = &raw[size_t(y) * (rowBytes + 1)];
        uint8_t* cur = &img.data[size_t(y) * rowBytes];
        const uint8_t* prev = y > 0 ? cur - rowBytes : nullptr;
        for (size_t i = 0; i < rowBytes; ++i) {
            const int a = i >= bpp ? cur[i - bpp] : 0, b = prev ? prev[i] : 0, c = prev && i >= bpp ? prev[i - bpp] : 0;
            const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
            const int predictor[5] = {0, a, b, (a + b) / 2, pa <= pb && pa <= pc ? a : (pb <= pc ? b : c)};
            EXPECT_LE(in[0], 4);
            cur[i] = uint8_t(in[1 + i] + predictor[in[0] % 5]);
        }
    }
    return img;
}

Image8 makeImage(int w, int h, int channels, bool noise, uint32_t seed = 1) {
    Image8 img{w, h, channels, std::vector<uint8_t>(size_t(w) * size_t(h) * size_t(channels))};
    std::mt19937 rng(seed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c)
                img.data[(size_t(y) * size_t(w) + size_t(x)) * size_t(channels) + size_t(c)] =
                    noise ? uint8_t(rng()) : uint8_t((x * 255 / std::max(1, w - 1) + y * (c + 1)) & 0xFF);
    return img;
}

// A rendered-looking frame: graded background, Lambert + Blinn-Phong spheres, encoded to sRGB.
Image8 makeRenderedFrame(int w, int h) {
    ImageF f(w, h);
    const float L[3] = {0.577f, 0.577f, -0.577f};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = f.pixel(x, y);
            float bg = 0.05f + 0.1f * float(y) / float(h);
            p[0] = p[1] = bg, p[2] = bg * 1.5f, p[3] = 1;
            for (int s = 0; s < 3; ++s) {
                const float cx = w * (0.25f + 0.25f * s), cy = h * 0.5f, r = h * 0.2f;
                const float nx = (x - cx) / r, ny = (cy - y) / r, d = 1 - nx * nx - ny * ny;
                if (d <= 0) continue;
                const float N[3] = {nx, ny, -std::sqrt(d)}, Hv[3] = {0.45f, 0.45f, -0.77f};  // Blinn 1977
                const float NoL = std::max(0.0f, N[0] * L[0] + N[1] * L[1] + N[2] * L[2]);
                const float spec = std::pow(std::max(0.0f, N[0] * Hv[0] + N[1] * Hv[1] + N[2] * Hv[2]), 64.0f);
                for (int c = 0; c < 3; ++c) p[c] = 0.02f + (c == s ? 0.8f : 0.1f) * NoL + spec;
            }
        }
    return toImage8(f, Encoding::Srgb, DisplaySettings{}, nullptr);
}

void expectRoundTrip(const Image8& img, const std::string& name) {
    SCOPED_TRACE(name);
    const std::vector<uint8_t> png = encodePng(img);
    Image8 strict = strictDecode(png);
    EXPECT_EQ(strict.width, img.width);
    EXPECT_EQ(strict.height, img.height);
    EXPECT_EQ(strict.channels, img.channels);
    EXPECT_TRUE(strict.data == img.data) << "strict decode differs";

    const std::string path = outPath(name + ".png");
    writePng(path, img);
    Image8 back = readPng(path);
    EXPECT_EQ(back.width, img.width);
    EXPECT_EQ(back.height, img.height);
    EXPECT_EQ(back.channels, img.channels);
    EXPECT_TRUE(back.data == img.data) << "stb_image decode differs; file left at " << path;
}

std::string expectReadError(const std::string& path) {
    try {
        readPng(path);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        return e.what();
    }
    ADD_FAILURE() << "expected InputError reading " << path;
    return {};
}

}  // namespace

TEST(Png, RoundTripSizes) {
    const int sizes[][2] = {{1, 1}, {3, 7}, {7, 3}, {1921, 3}, {2, 3000}, {640, 480}, {1920, 1080}};
    for (const auto& s : sizes)
        for (int channels : {3, 4})
            for (bool noise : {false, true}) {
                const std::string name = std::to_string(s[0]) + "x" + std::to_string(s[1]) + "_" +
                                         (channels == 4 ? "rgba" : "rgb") + (noise ? "_noise" : "_gradient");
                expectRoundTrip(makeImage(s[0], s[1], channels, noise, uint32_t(s[0] * 31 + s[1])), name);
            }
}

TEST(Png, AnyBandCountGivesTheSameImage) {
    // Band seams: each band's Up filter reads the last row of the band above, and the Adler-32s combine.
    for (int channels : {3, 4})
        for (int h : {1, 2, 5, 17})
            for (int bands : {1, 2, 3, 4, 8, 64}) {
                SCOPED_TRACE(std::to_string(channels) + " channels, height " + std::to_string(h) + ", " +
                             std::to_string(bands) + " bands");
                const Image8 img = makeImage(33, h, channels, h % 2 == 1, uint32_t(h * bands));
                EXPECT_TRUE(strictDecode(detail::encodePngBands(img, bands)).data == img.data);
            }
    const Image8 frame = makeRenderedFrame(320, 240);
    EXPECT_TRUE(strictDecode(detail::encodePngBands(frame, 7)).data == frame.data);
}

TEST(Png, RoundTripRenderedFrameAndFlat) {
    expectRoundTrip(makeRenderedFrame(1920, 1080), "rendered_1920x1080");
    Image8 flat{800, 600, 3, std::vector<uint8_t>(800 * 600 * 3, 77)};
    expectRoundTrip(flat, "flat_800x600");
    EXPECT_LT(encodePng(flat).size(), 5000u);  // the filter + RLE should make a flat frame tiny
}

TEST(Png, ReadExpandsGrey) {
    const std::string grey = outPath("grey.png"), greyAlpha = outPath("grey_alpha.png");
    const std::vector<uint8_t> g = {0, 100, 255, 7, 8, 9};
    const std::vector<uint8_t> ga = {10, 200, 20, 100};
    const std::vector<uint8_t> pngG = makePng(3, 2, 0, 1, g), pngGa = makePng(2, 1, 4, 2, ga);
    writeFileAtomic(grey, pngG.data(), pngG.size());
    writeFileAtomic(greyAlpha, pngGa.data(), pngGa.size());

    Image8 a = readPng(grey);
    ASSERT_EQ(a.channels, 3);
    ASSERT_EQ(a.width, 3);
    ASSERT_EQ(a.height, 2);
    for (size_t i = 0; i < g.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(a.data[i * 3 + size_t(c)], g[i]);

    Image8 b = readPng(greyAlpha);
    ASSERT_EQ(b.channels, 4);
    EXPECT_EQ(b.data, (std::vector<uint8_t>{10, 10, 10, 200, 20, 20, 20, 100}));
}

TEST(Png, ReadErrorsNameTheFile) {
    const std::string missing = outPath("missing.png");
    fs::remove(missing);
    EXPECT_NE(expectReadError(missing).find(missing + ": cannot read: No such file or directory"), std::string::npos);

    const std::string garbage = outPath("garbage.png");
    writeFileAtomic(garbage, std::string("this is not an image, just some text\n"));
    EXPECT_NE(expectReadError(garbage).find("not a PNG file"), std::string::npos);

    const std::string empty = outPath("empty.png");
    writeFileAtomic(empty, std::string());
    EXPECT_NE(expectReadError(empty).find("not a PNG file"), std::string::npos);

    const std::vector<uint8_t> png = encodePng(makeImage(64, 64, 3, true));
    for (size_t cut : {size_t(12), size_t(40), png.size() / 2, png.size() - 20}) {
        const std::string truncated = outPath("truncated_" + std::to_string(cut) + ".png");
        writeFileAtomic(truncated, png.data(), cut);
        EXPECT_NE(expectReadError(truncated).find("corrupt PNG: "), std::string::npos) << cut;
    }
}

// Sets the CRC of the chunk at `at` to what its type and data give.
void fixCrc(std::vector<uint8_t>& png, size_t at) {
    const uint32_t len = getU32(&png[at]);
    const uint32_t crc = uint32_t(crc32(0L, &png[at + 4], len + 4));
    for (int k = 0; k < 4; ++k) png[at + 8 + len + size_t(k)] = uint8_t(crc >> (24 - 8 * k));
}

TEST(Png, ChecksumsAreVerifiedBeforeDecoding) {
    const std::vector<uint8_t> good = encodePng(makeImage(16, 8, 3, true));
    // What encodePng writes: the signature, IHDR at byte 8 (25 bytes), then IDAT at byte 33 and IEND last.
    ASSERT_EQ(std::string(good.begin() + 37, good.begin() + 41), "IDAT");
    const size_t idatLength = getU32(&good[33]), iend = 33 + 12 + idatLength;
    ASSERT_EQ(std::string(good.begin() + long(iend) + 4, good.begin() + long(iend) + 8), "IEND");
    struct Case {
        const char* name;
        std::vector<uint8_t> bytes;
        const char* reason;
    };
    std::vector<Case> cases;
    auto corrupt = [&](const char* name, const char* reason, auto&& change) {
        std::vector<uint8_t> b = good;
        change(b);
        cases.push_back({name, b, reason});
    };
    corrupt("ihdr_crc", "the IHDR chunk at byte 8 has a bad CRC", [](auto& b) { b[29] ^= 1; });
    corrupt("idat_crc", "the IDAT chunk at byte 33 has a bad CRC (stored 0x",
            [&](auto& b) { b[33 + 8 + idatLength] ^= 0x10; });
    corrupt("iend_crc", "the IEND chunk at byte", [&](auto& b) { b[iend + 8] ^= 0xFF; });
    // The zlib stream's last 4 bytes are its Adler-32: change one and give the chunk an honest CRC, so only
    // the Adler-32 is wrong.
    corrupt("adler", "Adler-32 does not match", [&](auto& b) {
        b[33 + 8 + idatLength - 1] ^= 1;
        fixCrc(b, 33);
    });
    corrupt("no_iend", "without an IEND chunk", [&](auto& b) { b.resize(iend); });
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = outPath(std::string("checksum_") + c.name + ".png");
        writeFileAtomic(path, c.bytes.data(), c.bytes.size());
        const std::string error = expectReadError(path);
        EXPECT_NE(error.find(path + ": corrupt PNG: "), std::string::npos) << error;
        EXPECT_NE(error.find(c.reason), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
    // Negative controls: stb_image alone decodes the flipped Adler-32 and the flipped CRCs (it checks
    // neither), so only the check above stands between them and a comparison; and the untouched file reads.
    for (const Case& c : cases) {
        if (std::string(c.name) == "no_iend") continue;
        int w = 0, h = 0, n = 0;
        stbi_uc* pixels = stbi_load_from_memory(c.bytes.data(), int(c.bytes.size()), &w, &h, &n, 3);
        EXPECT_NE(pixels, nullptr) << c.name << ": stb_image refused it by itself";
        stbi_image_free(pixels);
    }
    const std::string path = outPath("checksum_good.png");
    writeFileAtomic(path, good.data(), good.size());
    EXPECT_EQ(readPng(path).width, 16);
}

TEST(Png, WriteFailureNamesTheFile) {
    const std::string path = outPath("no/such/dir/x.png");
    try {
        writePng(path, makeImage(4, 4, 3, false));
        ADD_FAILURE() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
    }
}
