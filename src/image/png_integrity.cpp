// checkPngIntegrity: one pass over the chunks, checking each CRC and inflating the IDAT data into a scratch
// buffer (discarded) so that zlib checks the stream and its Adler-32.
#include "image/png_integrity.h"

#include "util/input_error.h"

#include <zlib.h>

#include <cstdio>
#include <vector>

namespace shadelab {
namespace {

uint32_t be32(const std::string& b, size_t at) {
    return uint32_t(uint8_t(b[at])) << 24 | uint32_t(uint8_t(b[at + 1])) << 16 | uint32_t(uint8_t(b[at + 2])) << 8 |
           uint32_t(uint8_t(b[at + 3]));
}

// "the IDAT chunk at byte 33"; a type that is not four ASCII letters (§5.4) is written byte by byte.
std::string chunkName(const std::string& b, size_t at) {
    std::string type;
    for (size_t i = 0; i < 4; ++i) {
        const auto c = static_cast<unsigned char>(b[at + 4 + i]);
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')) {
            type += char(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            type += hex;
        }
    }
    return "the " + type + " chunk at byte " + std::to_string(at);
}

std::string hex32(uint32_t v) {
    char s[16];
    std::snprintf(s, sizeof s, "0x%08x", v);
    return s;
}

// The most bytes the filtered image data of a width × height image may inflate to: each row's filter byte and
// its pixels at the widest format (16-bit RGBA, 8 bytes a pixel), doubled for Adam7's passes, whose rows
// each add a filter byte and round up to a byte. More than this is not an image of that size.
uint64_t maxInflatedBytes(uint32_t width, uint32_t height) {
    return 2 * uint64_t(height) * (2 + 8 * uint64_t(width)) + 64;
}

// Inflates the IDAT chunks' zlib stream as it arrives, keeping none of the output.
class IdatStream {
public:
    IdatStream(const std::string& path, uint64_t maxOut) : path_(path), maxOut_(maxOut) {
        if (inflateInit(&z_) != Z_OK) throw InputError(path, "out of memory while checking the PNG");
    }
    ~IdatStream() { inflateEnd(&z_); }
    IdatStream(const IdatStream&) = delete;
    IdatStream& operator=(const IdatStream&) = delete;

    void feed(const std::string& bytes, size_t at, size_t size, const std::string& chunk) {
        if (ended_) return;  // bytes after the stream's end are stb_image's business, not a checksum's
        z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + at));
        z_.avail_in = uInt(size);
        while (z_.avail_in > 0 && !ended_) {
            z_.next_out = scratch_.data();
            z_.avail_out = uInt(scratch_.size());
            const uInt inBefore = z_.avail_in;
            const int rc = inflate(&z_, Z_NO_FLUSH);
            if (rc == Z_BUF_ERROR && z_.avail_in == inBefore && z_.avail_out == scratch_.size())
                throw InputError(path_, "corrupt PNG: " + chunk + ": the image data's zlib stream makes no progress");
            if (rc == Z_STREAM_END) {
                ended_ = true;
            } else if (rc == Z_DATA_ERROR) {
                const std::string why = z_.msg ? z_.msg : "invalid data";
                throw InputError(path_, "corrupt PNG: " + chunk + ": the image data's zlib stream is invalid (" + why +
                                            (why == "incorrect data check" ? ": its Adler-32 does not match" : "") +
                                            ")");
            } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
                throw InputError(path_, "corrupt PNG: " + chunk + ": zlib error " + std::to_string(rc));
            }
            if (z_.total_out > maxOut_)
                throw InputError(path_, "corrupt PNG: " + chunk + ": the image data inflates to more than the " +
                                            std::to_string(maxOut_) + " bytes its size allows");
        }
    }
    bool ended() const { return ended_; }

private:
    const std::string& path_;
    uint64_t maxOut_;
    z_stream z_{};
    std::vector<Bytef> scratch_ = std::vector<Bytef>(64 * 1024);
    bool ended_ = false;
};

}  // namespace

void checkPngIntegrity(const std::string& path, const std::string& bytes, uint32_t width, uint32_t height) {
    IdatStream idat(path, maxInflatedBytes(width, height));
    bool sawIdat = false;
    size_t at = 8;  // after the signature
    std::string last = "the signature";
    for (;;) {
        if (bytes.size() - at < 12)
            throw InputError(path, "corrupt PNG: the file ends after " + last + " without an IEND chunk (truncated)");
        const uint32_t length = be32(bytes, at);
        const std::string chunk = chunkName(bytes, at);
        if (length > 0x7FFFFFFFu)
            throw InputError(path, "corrupt PNG: " + chunk + " declares " + std::to_string(length) +
                                       " bytes, over the format's 2^31 - 1");
        if (bytes.size() - at - 12 < length)
            throw InputError(path, "corrupt PNG: " + chunk + " runs past the end of the file (truncated)");
        // CRC-32 over the type and the data (§5.3).
        const uint32_t stored = be32(bytes, at + 8 + length);
        const uint32_t computed =
            uint32_t(crc32_z(0L, reinterpret_cast<const Bytef*>(bytes.data() + at + 4), size_t(length) + 4));
        if (stored != computed)
            throw InputError(path, "corrupt PNG: " + chunk + " has a bad CRC (stored " + hex32(stored) + ", computed " +
                                       hex32(computed) + ")");
        const std::string type = bytes.substr(at + 4, 4);
        if (type == "IDAT") {
            sawIdat = true;
            idat.feed(bytes, at + 8, length, chunk);
        } else if (type == "IEND") {
            if (!sawIdat) throw InputError(path, "corrupt PNG: no IDAT chunk before " + chunk);
            if (!idat.ended())
                throw InputError(path, "corrupt PNG: the image data (IDAT) ends before its zlib stream does, at " +
                                           chunk + " (truncated)");
            return;
        }
        last = chunk;
        at += 12 + size_t(length);
    }
}

}  // namespace shadelab
