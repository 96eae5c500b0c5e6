// PNG files in and out. Writing is atomic (temp file + rename) and fast enough for 1080p in a few
// tens of ms (zlib, fast level, rows compressed in parallel). Reading uses stb_image.
#pragma once

#include "image/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab {

// Encodes an 8-bit RGB or RGBA image as PNG bytes.
std::vector<uint8_t> encodePng(const Image8& img);

// Encodes and writes atomically. Throws InputError naming the path on any I/O failure; the
// destination is then untouched.
void writePng(const std::string& path, const Image8& img);

// Largest image readPng decodes: kMaxImageSide² pixels (1 GiB as RGBA), as large as shadelab renders.
inline constexpr uint64_t kMaxPngPixels = uint64_t(kMaxImageSide) * kMaxImageSide;

// A PNG file's bytes with its size read from the IHDR chunk, before anything is decoded.
struct PngFile {
    std::string path;
    std::string bytes;
    int width = 0, height = 0;  // pixels, from IHDR
};

// Reads a PNG file (util/read_file.h) and its header: signature, IHDR present, width and height in
// [1, 2^31) and their product within kMaxPngPixels. Throws InputError naming the path and the reason.
PngFile readPngFile(const std::string& path);
// Decodes a file readPngFile returned as 8-bit RGB or RGBA (channels as stored, grey expanded to RGB).
Image8 decodePng(const PngFile& file);
// readPngFile then decodePng.
Image8 readPng(const std::string& path);

namespace detail {
// encodePng with an explicit number of row bands compressed in parallel (clamped to [1, height]), so
// tests can cover the multi-band stream on any machine. encodePng picks it from the core count.
std::vector<uint8_t> encodePngBands(const Image8& img, int requestedBands);
}  // namespace detail

}  // namespace shadelab
