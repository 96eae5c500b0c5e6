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

// Reads any PNG as 8-bit RGB or RGBA (channels as stored, grey expanded to RGB).
// Throws InputError naming the path and the reason.
Image8 readPng(const std::string& path);

namespace detail {
// encodePng with an explicit number of row bands compressed in parallel (clamped to [1, height]), so
// tests can cover the multi-band stream on any machine. encodePng picks it from the core count.
std::vector<uint8_t> encodePngBands(const Image8& img, int requestedBands);
}  // namespace detail

}  // namespace shadelab
