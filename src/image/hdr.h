// readHdr: Radiance RGBE (.hdr) images, the flat and the run-length encodings (Ward 1991, "Real Pixels",
// Graphics Gems II; the format of Radiance's color.c), into linear float RGB. Bounded and strict: any
// problem is one InputError naming the file. Not a writer (tools/make_sky_hdr.py writes the shipped one).
#pragma once

#include "image/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab {

struct HdrImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width·height RGB, row 0 at the top
};

inline constexpr uint64_t kMaxHdrFileBytes = uint64_t(256) << 20;  // an environment map file
inline constexpr int kMaxHdrSide = kMaxImageSide;                  // pixels per side
inline constexpr uint64_t kMaxHdrPixels = uint64_t(16) << 20;      // 16 Mpixels (192 MiB of floats)

// What the header of a .hdr file says: its size, and where its scanlines begin in the file's bytes.
struct HdrHeader {
    int width = 0;
    int height = 0;
    size_t dataOffset = 0;
};

// The header of the bytes of a .hdr file, checked as parseHdr checks it (within kMaxHdrSide and
// kMaxHdrPixels), without decoding a pixel: what a caller needs to refuse an image before paying for it.
HdrHeader parseHdrHeader(const std::string& bytes, const std::string& name);

// Reads `path` (util/read_file.h, at most kMaxHdrFileBytes) and decodes it.
HdrImage readHdr(const std::string& path);

// Decodes the bytes of a .hdr file; `name` is used in messages. Only the standard orientation "-Y h +X w".
HdrImage parseHdr(const std::string& bytes, const std::string& name);

}  // namespace shadelab
