// OpenEXR files in and out (OpenEXR 3.1, Debian's libopenexr-dev): linear float images with named layers, for
// radiance that must keep what lies above 1 and for passes beside it (albedo, normal, depth, variance).
//
// Naming (the standard EXR convention, "Interpreting OpenEXR Deep Pixels" / "Technical Introduction", channel
// names): a layer's channels are "<layer>.<channel>"; the colour layer has the empty name and its channels are
// plain "R", "G", "B" (and "A" when given), so every viewer shows it. A layer of colour-like data uses R G B
// ("albedo.R"), a vector X Y Z ("normal.X"), a single value one channel ("depth.Z", "variance.Y"). Channel
// names are never empty and hold no '.'; a layer's name may nest ("left.albedo", read from "left.albedo.R": a
// layer is what comes before the last '.') but has no empty part; names are unique; a file holds
// 1..kMaxExrChannels channels.
//
// Writing encodes into memory (an Imf::OStream over a buffer), losslessly (ZIP, 16 scanlines per block), then
// writes through writeFileAtomic (util/atomic_file.h): atomic, and never over an input. Reading goes through
// readFile (util/read_file.h, at most kMaxExrFileBytes) and an Imf::IStream over the bytes, with the data
// window, the channel count and the memory the pixels need checked before any pixel is decoded; every problem,
// OpenEXR's own exceptions included, is one InputError naming the file.
#pragma once

#include "image/image.h"
#include "util/name_table.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

// How samples are stored: 16-bit half (Imath::half, 11 significant bits, largest finite 65504; larger values
// become +infinity) or 32-bit float (exact).
enum class ExrPrecision { Half, Float };

inline constexpr EnumName<ExrPrecision> kExrPrecisionNames[] = {
    {ExrPrecision::Half, "half"},
    {ExrPrecision::Float, "float"},
};

inline const char* toString(ExrPrecision p) { return nameOf(kExrPrecisionNames, p); }

// One layer: its channels' samples interleaved per pixel (width·height·channels.size() floats, row 0 at the
// top), in the order `channels` lists them.
struct ExrLayer {
    std::string name;                   // "" for the colour layer (channels "R", "G", "B")
    std::vector<std::string> channels;  // e.g. {"R", "G", "B"}, {"X", "Y", "Z"}, {"Z"}
    std::vector<float> samples;

    // The index of channel `channel` in `channels`, or nothing.
    std::optional<size_t> channelIndex(const std::string& channel) const;
};

// An image of layers of the same size. Layers are in the order given when written; when read, the colour layer
// comes first, then the others by name, and each layer's channels in the order R G B A X Y Z, then any others
// alphabetically (an EXR file lists channels alphabetically; this is the order people expect).
struct ExrImage {
    int width = 0, height = 0;
    std::vector<ExrLayer> layers;

    // The layer named `name`, or null.
    const ExrLayer* layer(const std::string& name) const;
};

// Reading's bounds (docs/cli.md "Limits"): the file's size, each side (kMaxImageSide), the channels, and the
// floats all layers decode to (4 bytes each, whatever the file stores).
inline constexpr uint64_t kMaxExrFileBytes = uint64_t(2) << 30;     // 2 GiB
inline constexpr int kMaxExrChannels = 64;                          // channels in one file, all layers
inline constexpr uint64_t kMaxExrDecodedBytes = uint64_t(4) << 30;  // 4 GiB of floats

// The colour layer of a float image (its R, G, B; alpha is dropped: every renderer's alpha is 1).
ExrLayer colourLayer(const ImageF& image);
// An image of one layer: the colour of `image`.
ExrImage exrFromImage(const ImageF& image);

// The file's bytes. Layers are CHECKed (util/check.h): names as above, sizes matching width·height, a size of
// 1..kMaxImageSide per side; these are the program's own data, never a user's.
std::string encodeExr(const ExrImage& image, ExrPrecision precision);
// encodeExr, then writeFileAtomic. Throws InputError naming `path` (a refused target, an input, a full disk).
void writeExr(const std::string& path, const ExrImage& image, ExrPrecision precision);

// Decodes the bytes of an EXR file (its first part; scanline or tiled, any compression OpenEXR reads); `name`
// is used in messages. Throws InputError("<name>", "<reason>") for anything it cannot or will not read.
ExrImage parseExr(const std::string& bytes, const std::string& name);
// readFile(path, kMaxExrFileBytes), then parseExr.
ExrImage readExr(const std::string& path);

// The colour layer as an RGBA float image (alpha 1, or the file's "A"). Throws InputError naming `name` and
// the first of R, G, B the file lacks.
ImageF colourOf(const ExrImage& image, const std::string& name);

// Whether `path` ends in ".exr" (any case).
bool hasExrExtension(const std::string& path);

}  // namespace shadelab
