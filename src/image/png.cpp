// PNG writer (own chunk writer over zlib, row bands deflated in parallel) and reader (stb_image).
// Writes 8-bit RGB/RGBA only; no interlacing, no ancillary chunks.
#include "image/png.h"

#include "image/png_integrity.h"
#include "util/atomic_file.h"
#include "util/check.h"
#include "util/input_error.h"
#include "util/read_file.h"

#include <stb_image.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <memory>
#include <thread>

namespace shadelab {

namespace {

// Measured on a 1920x1080 rendered frame (see png_test.cpp): the Up filter with Z_RLE gives files about
// as small as Sub/Paeth or zlib level 1, and stays near 20 ms where level 1 takes over 30 ms on noisy
// path-traced frames. Z_RLE ignores the level; 1 keeps the zlib header honest ("fastest").
constexpr int kLevel = 1;
constexpr int kStrategy = Z_RLE;
constexpr size_t kMinBandBytes = 256 * 1024;  // below this a thread costs more than it saves

const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

void putU32(std::vector<uint8_t>& out, uint32_t v) {
    const uint8_t b[4] = {uint8_t(v >> 24), uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
    out.insert(out.end(), b, b + 4);
}

// Length, type, data, CRC of type+data (PNG spec §5.3).
void putChunk(std::vector<uint8_t>& out, const char* type, const uint8_t* data, size_t size) {
    SHADELAB_CHECK_LE(size, size_t(0x7FFFFFFF));
    putU32(out, uint32_t(size));
    out.insert(out.end(), type, type + 4);
    if (size > 0) out.insert(out.end(), data, data + size);
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type), 4);
    if (size > 0) crc = crc32_z(crc, data, size);  // a null buffer would reset the CRC to 0
    putU32(out, uint32_t(crc));
}

// One band of rows, deflated on its own (pigz-style). Every band but the last ends with Z_SYNC_FLUSH,
// which byte-aligns it without a final-block bit, so the raw streams simply concatenate. The first
// band carries the zlib header; the last carries the Adler-32 of the whole filtered stream.
struct Band {
    int y0 = 0, y1 = 0;
    bool first = false, last = false;
    std::vector<uint8_t> bytes;  // what goes into this band's IDAT chunk(s)
    uLong adler = 0;             // Adler-32 of this band's filtered bytes alone
    size_t rawSize = 0;          // filtered bytes fed to deflate
    std::exception_ptr error;
};

// Runs deflate until it has consumed all input (and, for Z_FINISH, ended the stream), growing out.
void deflateAll(z_stream& z, std::vector<uint8_t>& out, size_t& used, int flush) {
    for (;;) {
        if (out.size() - used < 64) out.resize(out.size() * 2 + 1024);
        z.next_out = out.data() + used;
        z.avail_out = uInt(std::min<size_t>(out.size() - used, 0x7FFFFFFF));
        const uInt before = z.avail_out;
        int rc = deflate(&z, flush);
        SHADELAB_CHECK(rc == Z_OK || rc == Z_STREAM_END || rc == Z_BUF_ERROR);
        used += before - z.avail_out;
        if (flush == Z_FINISH ? rc == Z_STREAM_END : (z.avail_in == 0 && z.avail_out > 0)) return;
    }
}

struct JoinAll {
    std::vector<std::thread>& pool;
    ~JoinAll() {
        for (auto& t : pool)
            if (t.joinable()) t.join();
    }
};

void compressBand(const Image8& img, Band& band) {
    const size_t rowBytes = size_t(img.width) * size_t(img.channels);
    z_stream z{};
    SHADELAB_CHECK_EQ(deflateInit2(&z, kLevel, Z_DEFLATED, -15, 8, kStrategy), Z_OK);
    std::unique_ptr<z_stream, int (*)(z_stream*)> guard(&z, deflateEnd);

    band.rawSize = (rowBytes + 1) * size_t(band.y1 - band.y0);
    // A first guess at a sixteenth of the raw bytes, grown by deflateAll as needed: sized to deflateBound, the
    // zero-filled buffers of a 1920x1080 image held 6 MiB for a 240 KB file.
    band.bytes.resize(std::min<size_t>(deflateBound(&z, uLong(band.rawSize)) + 64, band.rawSize / 16 + 65536));
    size_t used = 0;
    if (band.first) {
        band.bytes[0] = 0x78;  // CMF: deflate, 32K window
        band.bytes[1] = 0x01;  // FLG: fastest, no dictionary; 0x7801 % 31 == 0
        used = 2;
    }
    band.adler = adler32(0L, nullptr, 0);
    std::vector<uint8_t> row(rowBytes + 1);
    row[0] = 2;  // filter type Up on every row: one subtraction per byte, vectorizes
    for (int y = band.y0; y < band.y1; ++y) {
        const uint8_t* cur = img.data.data() + size_t(y) * rowBytes;
        if (y == 0) {
            std::memcpy(row.data() + 1, cur, rowBytes);  // the row above the image is zero
        } else {
            const uint8_t* prev = cur - rowBytes;
            uint8_t* dst = row.data() + 1;
            for (size_t i = 0; i < rowBytes; ++i) dst[i] = uint8_t(cur[i] - prev[i]);
        }
        band.adler = adler32_z(band.adler, row.data(), row.size());
        z.next_in = row.data();
        z.avail_in = uInt(row.size());
        deflateAll(z, band.bytes, used, Z_NO_FLUSH);
    }
    deflateAll(z, band.bytes, used, band.last ? Z_FINISH : Z_SYNC_FLUSH);
    band.bytes.resize(used);
}

}  // namespace

std::vector<uint8_t> encodePng(const Image8& img) {
    // Bands of whole rows, one per core, none smaller than kMinBandBytes.
    const size_t rawBytes = (size_t(img.width) * size_t(img.channels) + 1) * size_t(img.height);
    size_t bands = std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), 8);
    bands = std::min(bands, std::max<size_t>(1, rawBytes / kMinBandBytes));
    return detail::encodePngBands(img, int(bands));
}

std::vector<uint8_t> detail::encodePngBands(const Image8& img, int requestedBands) {
    SHADELAB_CHECK(img.channels == 3 || img.channels == 4);
    SHADELAB_CHECK(img.width > 0 && img.height > 0);
    const size_t rowBytes = size_t(img.width) * size_t(img.channels);
    SHADELAB_CHECK_EQ(img.data.size(), rowBytes * size_t(img.height));
    const size_t bandCount = size_t(std::clamp(requestedBands, 1, img.height));
    std::vector<Band> bands(bandCount);
    for (size_t i = 0; i < bandCount; ++i) {
        bands[i].y0 = int(size_t(img.height) * i / bandCount);
        bands[i].y1 = int(size_t(img.height) * (i + 1) / bandCount);
        bands[i].first = i == 0;
        bands[i].last = i + 1 == bandCount;
    }
    auto work = [&img](Band& b) {
        try {
            compressBand(img, b);
        } catch (...) {
            b.error = std::current_exception();
        }
    };
    {
        std::vector<std::thread> pool;
        JoinAll joinAll{pool};  // joins even if starting a thread throws
        for (size_t i = 1; i < bandCount; ++i) pool.emplace_back(work, std::ref(bands[i]));
        work(bands[0]);
    }
    for (const Band& b : bands)
        if (b.error) std::rethrow_exception(b.error);

    // Adler-32 of the whole stream from the per-band sums (zlib's adler32_combine, as pigz does).
    uLong adler = bands[0].adler;
    for (size_t i = 1; i < bandCount; ++i) adler = adler32_combine(adler, bands[i].adler, z_off_t(bands[i].rawSize));
    Band& lastBand = bands.back();
    for (int shift = 24; shift >= 0; shift -= 8) lastBand.bytes.push_back(uint8_t(adler >> shift));

    size_t total = 8 + 25 + 12;
    for (const Band& b : bands) total += b.bytes.size() + 12 * (1 + b.bytes.size() / 0x40000000);
    std::vector<uint8_t> out;
    out.reserve(total);
    out.insert(out.end(), kSignature, kSignature + 8);

    std::vector<uint8_t> ihdr;
    putU32(ihdr, uint32_t(img.width));
    putU32(ihdr, uint32_t(img.height));
    const uint8_t rest[5] = {8, uint8_t(img.channels == 4 ? 6 : 2), 0, 0, 0};  // depth, colour type, deflate,
    ihdr.insert(ihdr.end(), rest, rest + 5);                                   // filter method 0, no interlace
    putChunk(out, "IHDR", ihdr.data(), ihdr.size());

    // IDAT chunks split anywhere; decoders concatenate them. One (or more, if huge) per band.
    for (const Band& b : bands)
        for (size_t off = 0; off < b.bytes.size(); off += 0x40000000)
            putChunk(out, "IDAT", b.bytes.data() + off, std::min<size_t>(0x40000000, b.bytes.size() - off));
    putChunk(out, "IEND", nullptr, 0);
    return out;
}

void writePng(const std::string& path, const Image8& img) {
    std::vector<uint8_t> bytes = encodePng(img);
    writeFileAtomic(path, bytes.data(), bytes.size());
}

PngFile readPngFile(const std::string& path) {
    PngFile f;
    f.path = path;
    f.bytes = readFile(path, kMaxPngFileBytes);
    const std::string& b = f.bytes;
    if (b.size() < 8 || std::memcmp(b.data(), kSignature, 8) != 0)
        throw InputError(path, "not a PNG file (bad signature)");
    // PNG spec §5.2/§11.2.2: the first chunk is IHDR, 13 bytes, width and height big-endian in [1, 2^31).
    if (b.size() < 8 + 8 + 13 || b.compare(12, 4, "IHDR") != 0)
        throw InputError(path, "corrupt PNG: no IHDR chunk first");
    const auto be32 = [&](size_t at) {
        return uint32_t(uint8_t(b[at])) << 24 | uint32_t(uint8_t(b[at + 1])) << 16 | uint32_t(uint8_t(b[at + 2])) << 8 |
               uint32_t(uint8_t(b[at + 3]));
    };
    const uint32_t w = be32(16), h = be32(20);
    if (w == 0 || h == 0 || w > 0x7FFFFFFFu || h > 0x7FFFFFFFu)
        throw InputError(path, "corrupt PNG: IHDR declares " + std::to_string(w) + "x" + std::to_string(h) + " pixels");
    if (uint64_t(w) * uint64_t(h) > kMaxPngPixels)
        throw InputError(path, "PNG of " + std::to_string(w) + "x" + std::to_string(h) +
                                   " pixels exceeds the limit of " + std::to_string(kMaxPngPixels) + " pixels (" +
                                   std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide) +
                                   "); nothing was decoded");
    f.width = int(w);
    f.height = int(h);
    return f;
}

Image8 decodePng(const PngFile& file) {
    const std::string& path = file.path;
    if (file.bytes.size() > size_t(0x7FFFFFFF)) throw InputError(path, "PNG file too large");
    // stb_image checks neither the chunks' CRCs nor the zlib stream's Adler-32: a changed bit would decode.
    checkPngIntegrity(path, file.bytes, uint32_t(file.width), uint32_t(file.height));
    const auto* bytes = reinterpret_cast<const stbi_uc*>(file.bytes.data());
    const int len = int(file.bytes.size());
    stbi_set_flip_vertically_on_load_thread(0);  // another module may have set the global flag
    const auto reason = [] {
        const char* r = stbi_failure_reason();
        return std::string("corrupt PNG: ") + (r && *r ? r : "the decoder gave no reason");
    };
    int w = 0, h = 0, stored = 0;
    if (!stbi_info_from_memory(bytes, len, &w, &h, &stored)) throw InputError(path, reason());
    const int channels = (stored == 2 || stored == 4) ? 4 : 3;  // grey → RGB, grey+alpha → RGBA
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_memory(bytes, len, &w, &h, &stored, channels),
                                                     stbi_image_free);
    if (!pixels) throw InputError(path, reason());

    Image8 img;
    img.width = w;
    img.height = h;
    img.channels = channels;
    img.data.assign(pixels.get(), pixels.get() + size_t(w) * size_t(h) * size_t(channels));
    return img;
}

Image8 readPng(const std::string& path) { return decodePng(readPngFile(path)); }

}  // namespace shadelab
