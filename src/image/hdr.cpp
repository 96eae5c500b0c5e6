// parseHdr: header lines up to the blank line, the resolution line, then one scanline at a time: a new-style
// run-length scanline starts with 2, 2 and the width; anything else is a flat scanline of RGBE quadruples.
#include "image/hdr.h"

#include "util/input_error.h"
#include "util/read_file.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace shadelab {
namespace {

constexpr size_t kMaxHeaderBytes = 64 << 10;

// Ward's RGBE: a shared exponent e, mantissas m/256 · 2^(e − 128); e = 0 is black.
void rgbeToFloat(const unsigned char* p, float* out) {
    if (p[3] == 0) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    const float f = std::ldexp(1.0f, int(p[3]) - (128 + 8));
    out[0] = float(p[0]) * f;
    out[1] = float(p[1]) * f;
    out[2] = float(p[2]) * f;
}

}  // namespace

HdrHeader parseHdrHeader(const std::string& bytes, const std::string& name) {
    const auto fail = [&name](const std::string& reason) { return InputError(name, reason); };
    size_t pos = 0;
    const auto nextLine = [&](std::string& line) {
        const size_t end = bytes.find('\n', pos);
        if (end == std::string::npos || end > kMaxHeaderBytes) return false;
        line = bytes.substr(pos, end - pos);
        pos = end + 1;
        return true;
    };
    std::string line;
    if (!nextLine(line) || (line != "#?RADIANCE" && line != "#?RGBE"))
        throw fail("not a Radiance .hdr file (expected '#?RADIANCE' on the first line)");
    bool formatSeen = false;
    while (true) {
        if (!nextLine(line)) throw fail("header: no blank line ends it within 64 KiB");
        if (line.empty()) break;
        if (line.compare(0, 7, "FORMAT=") == 0) {
            if (line != "FORMAT=32-bit_rle_rgbe")
                throw fail("header: unsupported " + line.substr(0, 64) + "; expected FORMAT=32-bit_rle_rgbe");
            formatSeen = true;
        }
    }
    (void)formatSeen;  // optional in the format; Radiance assumes RGBE
    if (!nextLine(line)) throw fail("missing resolution line");
    char ys[3] = {}, xs[3] = {};
    long h = 0, w = 0;
    char extra = 0;
    if (line.size() > 64 || std::sscanf(line.c_str(), "%2s %ld %2s %ld %c", ys, &h, xs, &w, &extra) != 4 ||
        std::strcmp(ys, "-Y") != 0 || std::strcmp(xs, "+X") != 0)
        throw fail("resolution line '" + line.substr(0, 64) + "': only '-Y <height> +X <width>' is supported");
    if (w < 1 || h < 1 || w > kMaxHdrSide || h > kMaxHdrSide || uint64_t(w) * uint64_t(h) > kMaxHdrPixels)
        throw fail("image of " + std::to_string(w) + "x" + std::to_string(h) + " pixels; at most " +
                   std::to_string(kMaxHdrSide) + " per side and " + std::to_string(kMaxHdrPixels >> 20) + " Mpixels");
    return HdrHeader{int(w), int(h), pos};
}

HdrImage parseHdr(const std::string& bytes, const std::string& name) {
    const auto fail = [&name](const std::string& reason) { return InputError(name, reason); };
    const HdrHeader header = parseHdrHeader(bytes, name);
    const long w = header.width;
    size_t pos = header.dataOffset;
    HdrImage img;
    img.width = header.width;
    img.height = header.height;
    img.rgb.resize(size_t(header.width) * size_t(header.height) * 3);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const size_t size = bytes.size();
    std::vector<unsigned char> scan(size_t(w) * 4);
    for (int y = 0; y < img.height; ++y) {
        const std::string where = "scanline " + std::to_string(y);
        if (pos + 4 > size) throw fail(where + ": file is truncated");
        const bool rle = w >= 8 && w < 32768 && data[pos] == 2 && data[pos + 1] == 2 && (data[pos + 2] & 0x80) == 0;
        if (rle) {
            if (((int(data[pos + 2]) << 8) | int(data[pos + 3])) != w)
                throw fail(where + ": run-length scanline width does not match the image's");
            pos += 4;
            // Four planes (R, G, B, E), each a sequence of runs (count > 128: one byte repeated count − 128
            // times) and literals (count bytes).
            for (int c = 0; c < 4; ++c) {
                long x = 0;
                while (x < w) {
                    if (pos >= size) throw fail(where + ": file is truncated");
                    int count = data[pos++];
                    if (count > 128) {
                        count -= 128;
                        if (x + count > w) throw fail(where + ": run overruns the scanline");
                        if (pos >= size) throw fail(where + ": file is truncated");
                        for (int k = 0; k < count; ++k) scan[size_t(x + k) * 4 + size_t(c)] = data[pos];
                        ++pos;
                    } else {
                        if (count == 0 || x + count > w) throw fail(where + ": bad run length");
                        if (pos + size_t(count) > size) throw fail(where + ": file is truncated");
                        for (int k = 0; k < count; ++k) scan[size_t(x + k) * 4 + size_t(c)] = data[pos + size_t(k)];
                        pos += size_t(count);
                    }
                    x += count;
                }
            }
        } else {
            if (pos + size_t(w) * 4 > size) throw fail(where + ": file is truncated");
            std::memcpy(scan.data(), data + pos, size_t(w) * 4);
            pos += size_t(w) * 4;
        }
        for (long x = 0; x < w; ++x)
            rgbeToFloat(&scan[size_t(x) * 4], &img.rgb[(size_t(y) * size_t(w) + size_t(x)) * 3]);
    }
    return img;
}

HdrImage readHdr(const std::string& path) { return parseHdr(readFile(path, kMaxHdrFileBytes), path); }

}  // namespace shadelab
