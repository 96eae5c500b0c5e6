// A PNG's integrity before it is decoded: every chunk's CRC-32 (PNG spec §5.3), the chunks in order up to
// IEND, and the zlib stream of the IDAT chunks with its Adler-32 (RFC 1950), which stb_image does not check.
// `compare` must not measure an image that a bit flip has changed.
#pragma once

#include <cstdint>
#include <string>

namespace shadelab {

// Throws InputError(path, "corrupt PNG: ...") naming the chunk (its type and byte offset) for the first
// problem. `bytes` start with the PNG signature and an IHDR chunk (readPngFile checked both); `width` and
// `height` are IHDR's and bound how much the image data may inflate to.
void checkPngIntegrity(const std::string& path, const std::string& bytes, uint32_t width, uint32_t height);

}  // namespace shadelab
